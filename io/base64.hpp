#pragma once
// Base64 (RFC 4648 alphabet) as VTK XML files carry binary data in it. Two habits of the
// writers are accepted: whitespace between characters, and a padded quantum ("xx==", "xxx=")
// followed by more base64 — VTK and meshio encode a block header and its data as two streams,
// one after the other, so padding may occur in the middle of an array's text.
#include <cstddef>
#include <string>
#include <string_view>

namespace cmx::io {

// Decodes on demand, so that only the bytes asked for are ever held in memory.
class Base64Reader {
 public:
  explicit Base64Reader(std::string_view text) : text_(text) {}

  enum class Status { ok, ended, invalid };

  // Appends the next `n` decoded bytes to `out`. `ended`: the text ran out first; `invalid`: a
  // character outside the alphabet. Either way `out` holds what was decoded.
  Status read(std::size_t n, std::string& out);

  // At most this many bytes are still to come (for bounding sizes before allocating).
  std::size_t remaining_bound() const { return (text_.size() - pos_) / 4 * 3 + 3 + pending_.size(); }

 private:
  bool decode_quantum(std::string& into);  // false at the end of the text or on a bad character

  std::string_view text_;
  std::size_t pos_ = 0;
  std::string pending_;  // decoded bytes not yet handed out
  bool invalid_ = false;
};

}  // namespace cmx::io
