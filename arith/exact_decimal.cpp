#include "arith/exact_decimal.hpp"

#include <gmpxx.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace cmx {

std::string exact_decimal(double x) {
  if (!std::isfinite(x)) throw std::domain_error("exact_decimal: NaN or infinity");
  const auto bits = std::bit_cast<std::uint64_t>(x);
  const bool negative = (bits >> 63) != 0;
  const auto biased = static_cast<int>((bits >> 52) & 0x7FF);
  std::uint64_t mantissa = bits & ((std::uint64_t{1} << 52) - 1);
  // |x| = mantissa * 2^exponent (subnormals: biased exponent 0, no hidden bit).
  int exponent = biased == 0 ? -1074 : biased - 1075;
  if (biased != 0) mantissa |= std::uint64_t{1} << 52;
  const std::string sign = negative ? "-" : "";
  if (mantissa == 0) return sign + "0";
  // An odd mantissa makes the digits below free of trailing zeros.
  const int shift = std::countr_zero(mantissa);
  mantissa >>= shift;
  exponent += shift;

  mpz_class digits;
  mpz_import(digits.get_mpz_t(), 1, 1, sizeof mantissa, 0, 0, &mantissa);
  if (exponent >= 0) {
    mpz_mul_2exp(digits.get_mpz_t(), digits.get_mpz_t(), static_cast<mp_bitcnt_t>(exponent));
    return sign + digits.get_str();
  }
  // mantissa / 2^k = mantissa * 5^k / 10^k: the digits of mantissa * 5^k with the point k places
  // from the right. The last digit is 5 (odd times a power of 5), so no trailing zeros.
  const auto k = static_cast<unsigned long>(-exponent);
  mpz_class five_k;
  mpz_ui_pow_ui(five_k.get_mpz_t(), 5, k);
  digits *= five_k;
  std::string text = digits.get_str();
  if (text.size() <= k) text.insert(0, k + 1 - text.size(), '0');
  text.insert(text.size() - k, 1, '.');
  return sign + text;
}

}  // namespace cmx
