#include "cli/number_lines.hpp"

#include <sstream>
#include <string>
#include <vector>

#include "arith/rounding.hpp"
#include "cli/messages.hpp"

namespace cmx::cli {
namespace {

// Splits off a '#' comment and returns the blank-separated tokens.
std::vector<std::string> tokens(const std::string& line) {
  std::istringstream in(line.substr(0, line.find('#')));
  std::vector<std::string> out;
  for (std::string t; in >> t;) out.push_back(t);
  return out;
}

// The numbers of one line, or false after reporting why not.
bool parse_line(const std::vector<std::string>& t, long number, std::string_view expected,
                std::vector<Rational>& out) {
  const std::string where = "line " + std::to_string(number) + ": ";
  if (t.size() != out.size()) {
    message(where + "expected " + std::string(expected) + ", got " + std::to_string(t.size()));
    return false;
  }
  std::string why;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const std::optional<Rational> v = parse_rational(t[i], &why);
    if (!v) {
      message(where + "number " + std::to_string(i + 1) + ": " + why);
      return false;
    }
    out[i] = *v;
  }
  return true;
}

}  // namespace

bool read_number_lines(std::istream& in, std::size_t count, std::string_view expected,
                       const std::function<void(std::span<const Rational>)>& on_line) {
  bool ok = true;
  std::vector<Rational> numbers(count);
  std::string line;
  for (long number = 1; std::getline(in, line); ++number) {
    const std::vector<std::string> t = tokens(line);
    if (t.empty()) continue;
    if (parse_line(t, number, expected, numbers))
      on_line(numbers);
    else
      ok = false;
  }
  if (in.bad()) {
    message("read error");
    return false;
  }
  return ok;
}

}  // namespace cmx::cli
