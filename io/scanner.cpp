#include "io/scanner.hpp"

#include <cctype>
#include <charconv>
#include <fstream>
#include <iterator>
#include <sstream>

namespace cmx::io {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\f' || c == '\v'; }
bool is_space(char c) { return is_blank(c) || c == '\n' || c == '\r'; }

}  // namespace

std::string quoted(std::string_view token) {
  std::string s;
  const std::size_t limit = 40;
  for (char c : token.substr(0, limit)) s += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  return "'" + s + (token.size() > limit ? "...'" : "'");
}

void Scanner::fail(ErrorKind kind, const std::string& message) const { throw IoError(kind, file_, line_, message); }
void Scanner::fail_at(std::size_t line, ErrorKind kind, const std::string& message) const {
  throw IoError(kind, file_, line, message);
}

bool Scanner::skip_space() {
  while (pos_ < data_.size()) {
    const char c = data_[pos_];
    if (c == '\n') {
      ++line_;
      ++pos_;
    } else if (c == '\r') {
      ++pos_;
      if (pos_ < data_.size() && data_[pos_] == '\n') ++pos_;
      ++line_;
    } else if (is_blank(c)) {
      ++pos_;
    } else if (comment_ && c == comment_) {
      while (pos_ < data_.size() && data_[pos_] != '\n' && data_[pos_] != '\r') ++pos_;
    } else {
      return true;
    }
  }
  return false;
}

bool Scanner::more_on_line() {
  while (pos_ < data_.size() && is_blank(data_[pos_])) ++pos_;
  if (pos_ < data_.size() && comment_ && data_[pos_] == comment_)
    while (pos_ < data_.size() && data_[pos_] != '\n' && data_[pos_] != '\r') ++pos_;
  return pos_ < data_.size() && data_[pos_] != '\n' && data_[pos_] != '\r';
}

std::string_view Scanner::try_token() {
  if (!skip_space()) return {};
  const std::size_t start = pos_;
  while (pos_ < data_.size() && !is_space(data_[pos_])) {
    if (comment_ && data_[pos_] == comment_) break;
    ++pos_;
  }
  return data_.substr(start, pos_ - start);
}

std::string_view Scanner::token(std::string_view what) {
  const auto t = try_token();
  if (t.empty()) fail(ErrorKind::truncated, "unexpected end of file, expected " + std::string(what));
  return t;
}

std::string_view Scanner::rest_of_line() {
  const std::size_t start = pos_;
  while (pos_ < data_.size() && data_[pos_] != '\n' && data_[pos_] != '\r') ++pos_;
  const auto line = data_.substr(start, pos_ - start);
  if (pos_ < data_.size()) {
    if (data_[pos_] == '\r' && pos_ + 1 < data_.size() && data_[pos_ + 1] == '\n') ++pos_;
    ++pos_;
    ++line_;
  }
  return line;
}

std::uint64_t Scanner::unsigned_integer(std::string_view what) {
  auto t = token(what);
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  std::uint64_t v = 0;
  const auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec == std::errc::result_out_of_range) fail(ErrorKind::too_large, std::string(what) + " " + quoted(t) + " is too large");
  if (ec != std::errc() || p != t.data() + t.size() || t.empty())
    fail(ErrorKind::syntax, "expected " + std::string(what) + " (a non-negative integer), found " + quoted(t));
  return v;
}

std::int64_t Scanner::integer(std::string_view what) {
  auto t = token(what);
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  std::int64_t v = 0;
  const auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec == std::errc::result_out_of_range) fail(ErrorKind::too_large, std::string(what) + " " + quoted(t) + " is too large");
  if (ec != std::errc() || p != t.data() + t.size() || t.empty())
    fail(ErrorKind::syntax, "expected " + std::string(what) + " (an integer), found " + quoted(t));
  return v;
}

Rational Scanner::rational(std::string_view what) {
  const auto t = token(what);
  std::string why;
  auto q = parse_rational(t, &why);
  if (!q) {
    std::string lower;
    for (char c : t.substr(0, 8)) lower += char(std::tolower(static_cast<unsigned char>(c)));
    const auto body = lower.find_first_not_of("+-");
    const bool nonfinite = body != std::string::npos &&
                           (lower.compare(body, 3, "nan") == 0 || lower.compare(body, 3, "inf") == 0);
    fail(nonfinite ? ErrorKind::not_finite : ErrorKind::syntax,
         std::string(what) + " " + quoted(t) + (nonfinite ? " is not finite" : " is not a number: " + why));
  }
  return std::move(*q);
}

std::uint64_t Scanner::count(std::string_view what, std::uint64_t limit, std::size_t bytes_per_item) {
  skip_space();
  const std::size_t at = line_;
  const auto n = unsigned_integer(what);
  if (n > limit) fail_at(at, ErrorKind::too_large, std::string(what) + " " + std::to_string(n) + " exceeds the limit " + std::to_string(limit));
  if (bytes_per_item && n > remaining() / bytes_per_item + 1)
    fail_at(at, ErrorKind::truncated,
            std::string(what) + " " + std::to_string(n) + " cannot fit in the " + std::to_string(remaining()) +
                " bytes left in the file (truncated file or wrong count)");
  return n;
}

std::string_view Scanner::bytes(std::size_t n, std::string_view what) {
  if (n > remaining())
    fail(ErrorKind::truncated, "unexpected end of file in " + std::string(what) + ": " + std::to_string(n) +
                                   " bytes needed, " + std::to_string(remaining()) + " left");
  const auto b = data_.substr(pos_, n);
  pos_ += n;
  return b;
}

void Scanner::skip_one_newline() {
  if (pos_ < data_.size() && data_[pos_] == '\r') ++pos_;
  if (pos_ < data_.size() && data_[pos_] == '\n') {
    ++pos_;
    ++line_;
  }
}

void Scanner::seek(std::size_t offset) {
  if (offset > data_.size()) offset = data_.size();
  for (; pos_ < offset; ++pos_)
    if (data_[pos_] == '\n') ++line_;
}

std::string read_file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(ErrorKind::open_failed, path, 0, "cannot open file for reading");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw IoError(ErrorKind::open_failed, path, 0, "read error");
  return std::move(buffer).str();
}

std::string extension_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  for (auto& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace cmx::io
