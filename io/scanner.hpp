#pragma once
// A cursor over an in-memory file for the readers: whitespace-separated tokens with 1-based line
// tracking (LF, CRLF and lone CR all end a line), optional comment character, whole lines, and
// raw byte runs for the binary sections of VTK and Gmsh files. Every failure throws IoError with
// the file name and the current line. Nothing here allocates in proportion to a count read from
// the file; callers bound their reservations with `plausible_count`.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "io/io_error.hpp"
#include "io/tet_mesh_data.hpp"

namespace cmx::io {

class Scanner {
 public:
  Scanner(std::string_view data, std::string file) : data_(data), file_(std::move(file)) {}

  // '#' for formats with comments; '\0' (default) for none. A comment runs to the end of line.
  void set_comment_char(char c) { comment_ = c; }

  // Skips blanks, line ends and comments; returns false at the end of the data.
  bool skip_space();
  // Skips blanks (not line ends) and a comment; true if the line has another token.
  bool more_on_line();
  // The next token (stops at whitespace); throws truncated with `what` at end of data.
  std::string_view token(std::string_view what);
  // The next token, or empty at end of data.
  std::string_view try_token();
  // The rest of the current line (without the line end), advancing to the next line.
  std::string_view rest_of_line();
  // Moves past the end of the current line.
  void skip_line() { rest_of_line(); }

  // Numbers. `what` names the quantity in messages ("vertex count", "x coordinate", ...).
  std::uint64_t unsigned_integer(std::string_view what);
  std::int64_t integer(std::string_view what);
  Rational rational(std::string_view what);  // exact; rejects nan/inf with not_finite
  // A count from a header, rejected with too_large above `limit` or above the number of items
  // that `bytes_per_item` bytes each could fit in the rest of the file.
  std::uint64_t count(std::string_view what, std::uint64_t limit, std::size_t bytes_per_item);

  // Raw bytes (binary sections). Throws truncated when fewer than n bytes are left.
  std::string_view bytes(std::size_t n, std::string_view what);
  // Skips exactly one line end (LF or CRLF) if it is next (after binary data).
  void skip_one_newline();

  bool at_end() const { return pos_ >= data_.size(); }
  std::size_t remaining() const { return data_.size() - pos_; }
  std::size_t position() const { return pos_; }
  std::size_t line() const { return line_; }
  const std::string& file() const { return file_; }
  std::string_view data() const { return data_; }
  // Moves to an absolute offset (forward only; line numbers are recounted).
  void seek(std::size_t offset);

  [[noreturn]] void fail(ErrorKind kind, const std::string& message) const;
  [[noreturn]] void fail_at(std::size_t line, ErrorKind kind, const std::string& message) const;

 private:
  std::string_view data_;
  std::string file_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
  char comment_ = '\0';
};

// A reservation size for `count` items that cannot exceed what `bytes_left` bytes can hold.
inline std::size_t plausible_count(std::uint64_t count, std::size_t bytes_left, std::size_t min_bytes_per_item) {
  const std::uint64_t fit = bytes_left / (min_bytes_per_item ? min_bytes_per_item : 1) + 1;
  return std::size_t(count < fit ? count : fit);
}

// Quotes a token for messages, shortened so that a 1 MB garbage token gives a short message.
std::string quoted(std::string_view token);

// Reads a whole file into memory (IoError open_failed on failure).
std::string read_file_bytes(const std::string& path);

// Lower-cased file extension without the dot ("vtk", "mesh", ...), "" if none.
std::string extension_of(const std::string& path);

}  // namespace cmx::io
