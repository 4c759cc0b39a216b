#include "cli/option_values.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <stdexcept>

namespace cmx::cli {
namespace {

std::string in_quotes(std::string_view text) { return "'" + std::string(text) + "'"; }

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

// strtod on the whole text, or nullopt (empty, leading blanks, trailing characters). Overflow
// gives +-inf, as the value is then beyond any limit anyway.
std::optional<double> whole_double(std::string_view text) {
  if (text.empty() || text.front() == ' ' || text.front() == '\t') return std::nullopt;
  const std::string copy(text);
  char* end = nullptr;
  const double x = std::strtod(copy.c_str(), &end);
  if (end != copy.c_str() + copy.size()) return std::nullopt;
  return x;
}

}  // namespace

std::uint64_t parse_integer(std::string_view text, std::uint64_t min, std::uint64_t max) {
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  const bool whole = !text.empty() && ec == std::errc() && end == text.data() + text.size();
  if (!whole || value < min || value > max)
    throw std::invalid_argument("needs an integer from " + std::to_string(min) + " to " + std::to_string(max) + ", not " +
                                in_quotes(text));
  return value;
}

std::uint64_t parse_seed(std::string_view text) { return parse_integer(text, 0, UINT64_MAX); }

double parse_time_limit(std::string_view text) {
  const auto x = whole_double(text);
  if (!x || !(*x > 0))
    throw std::invalid_argument("needs a positive number of seconds (or inf: no limit), not " + in_quotes(text));
  return std::isinf(*x) ? 0 : *x;
}

double parse_nonnegative(std::string_view text) {
  const auto x = whole_double(text);
  if (!x || !std::isfinite(*x) || *x < 0) throw std::invalid_argument("needs a finite number >= 0, not " + in_quotes(text));
  return *x;
}

std::vector<std::string> parse_list(std::string_view text, const std::vector<std::string>& known, const std::string& what) {
  std::vector<std::string> out;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string item(text.substr(start, comma - start));
    start = comma + 1;
    if (item.empty()) continue;
    if (std::find(known.begin(), known.end(), item) == known.end())
      throw std::invalid_argument("unknown " + what + " " + in_quotes(item) + " (known: " + joined(known) + ")");
    out.push_back(item);
  }
  return out;
}

}  // namespace cmx::cli
