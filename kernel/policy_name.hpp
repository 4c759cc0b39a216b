#pragma once
// Reading the "NAME:BITS" policy names of the command line (mpfr:BITS for filters and arithmetic).
#include <charconv>
#include <optional>
#include <string_view>

namespace cmx {

// The decimal integer `digits` (nothing else) when it lies in [lo, hi], else nullopt.
inline std::optional<long> parse_bounded_integer(std::string_view digits, long lo, long hi) {
  long value = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec != std::errc() || end != digits.data() + digits.size() || digits.empty() || value < lo || value > hi)
    return std::nullopt;
  return value;
}

}  // namespace cmx
