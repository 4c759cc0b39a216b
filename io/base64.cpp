#include "io/base64.hpp"

#include <cstdint>

namespace cmx::io {
namespace {

// The 6-bit value of a base64 character, -1 for padding '=', -2 for anything else.
int sextet(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  if (c == '=') return -1;
  return -2;
}

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

}  // namespace

bool Base64Reader::decode_quantum(std::string& into) {
  int values[4];
  int have = 0, padding = 0;
  while (have < 4) {
    while (pos_ < text_.size() && is_blank(text_[pos_])) ++pos_;
    if (pos_ >= text_.size()) break;
    const int v = sextet(text_[pos_]);
    // Padding is only allowed in the last two places, and only padding may follow it.
    if (v == -2 || (v == -1 && have < 2) || (v >= 0 && padding > 0)) {
      invalid_ = true;
      return false;
    }
    padding += v == -1;
    values[have++] = v < 0 ? 0 : v;
    ++pos_;
  }
  // An unpadded final quantum of 2 or 3 characters is decoded as if padded; 1 character is not base64.
  if (have == 0) return false;
  if (have == 1) {
    invalid_ = true;
    return false;
  }
  const int bytes = have - padding - 1;
  const std::uint32_t bits = (std::uint32_t(values[0]) << 18) | (std::uint32_t(values[1]) << 12) |
                             (std::uint32_t(have > 2 ? values[2] : 0) << 6) | std::uint32_t(have > 3 ? values[3] : 0);
  for (int i = 0; i < bytes; ++i) into += char((bits >> (16 - 8 * i)) & 0xFF);
  return true;
}

Base64Reader::Status Base64Reader::read(std::size_t n, std::string& out) {
  const std::size_t target = out.size() + n;
  const std::size_t from_pending = pending_.size() < n ? pending_.size() : n;
  out.append(pending_, 0, from_pending);
  pending_.erase(0, from_pending);
  while (out.size() < target && !invalid_)
    if (!decode_quantum(out)) break;
  if (out.size() > target) {  // the last quantum went past what was asked for
    pending_.assign(out, target, std::string::npos);
    out.resize(target);
  }
  if (out.size() == target) return Status::ok;
  return invalid_ ? Status::invalid : Status::ended;
}

}  // namespace cmx::io
