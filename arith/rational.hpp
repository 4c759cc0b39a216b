#pragma once
// Exact scalars on GMP: Integer (mpz) and Rational (mpq, always canonical).
//
// Parsing accepts, exactly: integers ("-12"), decimals with optional exponent ("1.25e-3", ".5",
// "7."), fractions "p/q" (q > 0 after sign handling, e.g. "-3/4"), and C hexfloats ("0x1.8p-3").
// It rejects nan, inf, "1/0", empty or trailing garbage, and exponents beyond the documented
// limits (so that a 20-byte token cannot ask for a 10^9-digit number).
#include <gmpxx.h>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "arith/sign.hpp"

namespace cmx {

using Integer = mpz_class;
using Rational = mpq_class;
// A point with exact rational coordinates (x, y, z): the one spelling every layer uses.
using Point3 = std::array<Rational, 3>;

// Largest |exponent| accepted: decimal "e" exponents and hexfloat binary "p" exponents.
inline constexpr long max_decimal_exponent = 10000;
inline constexpr long max_binary_exponent = 40000;
// Longest token accepted by the parser, in characters.
inline constexpr std::size_t max_number_length = 100000;

// Parses one exact number (see the header comment). On failure returns nullopt and, if `why`
// is given, a short reason ("zero denominator", "not a number: 'abc'", ...).
std::optional<Rational> parse_rational(std::string_view text, std::string* why = nullptr);

// Canonical text: "p/q" with gcd 1 and q > 1, or "p" for integers. parse_rational reads it back.
std::string to_string(const Rational& q);
std::string to_string(const Integer& z);

// Bits of |z| (0 for zero).
std::size_t bit_size(const Integer& z);
// Bits of numerator plus bits of denominator: the storage measure used in precision studies.
std::size_t bit_size(const Rational& q);

inline Sign sign(const Rational& q) { return Sign(mpq_sgn(q.get_mpq_t())); }
inline Sign sign(const Integer& z) { return Sign(mpz_sgn(z.get_mpz_t())); }

// Exact value of a finite double (throws std::domain_error on NaN or infinity).
Rational rational_from_double(double x);

// True when q equals some double exactly.
bool is_double(const Rational& q);

}  // namespace cmx
