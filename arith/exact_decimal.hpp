#pragma once
// The exact decimal expansion of a double. Every finite double is m * 2^e with integer m, and
// 2^-k = 5^k / 10^k, so its value has a finite decimal expansion (at most 767 significant digits,
// for subnormals). Printing it in full lets any exact reader (parse_rational) recover the double's
// value, not merely the double: the Shrink-and-Expand boundary files use the same convention.
#include <string>

namespace cmx {

// The exact value of finite x in plain positional decimal: an optional '-', the integer digits
// without leading zeros, and, when x is not an integer, '.' followed by the fraction digits
// without trailing zeros. No exponent. Examples: 0.1 -> "0.1000000000000000055511151231257827021181583404541015625",
// 2.5 -> "2.5", 1e300 -> all 301 integer digits, -3.0 -> "-3". Negative zero prints as "-0"
// (the sign survives a round trip through strtod; parse_rational reads it as 0). Throws
// std::domain_error for NaN and infinities.
std::string exact_decimal(double x);

}  // namespace cmx
