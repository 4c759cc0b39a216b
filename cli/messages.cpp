#include "cli/messages.hpp"

#include <cstdio>

namespace cmx::cli {
namespace {

std::string& name_storage() {
  static std::string name;
  return name;
}

bool& quiet_storage() {
  static bool q = false;
  return q;
}

// Length of the well-formed UTF-8 sequence of two or more bytes at text[i], or 0 (RFC 3629:
// no overlong forms, no surrogates, nothing above U+10FFFF).
std::size_t utf8_sequence(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xBF;  // the allowed range of the second byte
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
    if (lead == 0xC2) low = 0xA0;  // U+0080..U+009F are control characters (C1) too
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) low = 0xA0;
    if (lead == 0xED) high = 0x9F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) low = 0x90;
    if (lead == 0xF4) high = 0x8F;
  }
  if (length == 0 || i + length > text.size()) return 0;
  if (byte(i + 1) < low || byte(i + 1) > high) return 0;
  for (std::size_t k = 2; k < length; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  return length;
}

void print_line(std::string_view text) {
  const std::string& name = name_storage();
  const std::string line = (name.empty() ? "cmx: " : "cmx " + name + ": ") + printable(text) + "\n";
  std::fflush(stdout);  // results printed so far come first when both go to one terminal
  std::fputs(line.c_str(), stderr);
}

}  // namespace

void set_command_name(std::string_view name) { name_storage() = std::string(name); }
const std::string& command_name() { return name_storage(); }
void set_quiet(bool quiet) { quiet_storage() = quiet; }
bool quiet() { return quiet_storage(); }

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7F) {
      out += char(c);
      ++i;
    } else if (const std::size_t n = c >= 0x80 ? utf8_sequence(text, i) : 0) {
      out.append(text.substr(i, n));
      i += n;
    } else {
      char code[5];
      std::snprintf(code, sizeof code, "\\x%02X", unsigned(c));
      out += code;
      ++i;
    }
  }
  return out;
}

void message(std::string_view text) { print_line(text); }

void note(std::string_view text) {
  if (!quiet()) print_line(text);
}

}  // namespace cmx::cli
