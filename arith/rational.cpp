#include "arith/rational.hpp"

#include <cctype>
#include <cmath>
#include <stdexcept>

#include "arith/rounding.hpp"

namespace cmx {
namespace {

bool fail(std::string* why, std::string message) {
  if (why) *why = std::move(message);
  return false;
}

std::string quoted(std::string_view text) {
  constexpr std::size_t shown = 40;
  std::string s(text.substr(0, shown));
  if (text.size() > shown) s += "...";
  return "'" + s + "'";
}

bool is_digit(char c, int base) {
  return base == 10 ? std::isdigit(static_cast<unsigned char>(c)) != 0
                    : std::isxdigit(static_cast<unsigned char>(c)) != 0;
}

// Consumes a run of digits of `base` starting at i; returns it (possibly empty).
std::string_view take_digits(std::string_view s, std::size_t& i, int base) {
  std::size_t start = i;
  while (i < s.size() && is_digit(s[i], base)) ++i;
  return s.substr(start, i - start);
}

// Parses an optionally signed exponent; rejects magnitudes above `limit`.
bool take_exponent(std::string_view s, std::size_t& i, long limit, long& exponent, std::string* why) {
  bool negative = false;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) negative = s[i++] == '-';
  std::string_view digits = take_digits(s, i, 10);
  if (digits.empty()) return fail(why, "missing exponent digits");
  long value = 0;
  for (char c : digits) {
    value = value * 10 + (c - '0');
    if (value > limit) return fail(why, "exponent out of range (|exponent| > " + std::to_string(limit) + ")");
  }
  exponent = negative ? -value : value;
  return true;
}

Integer integer_from_digits(std::string_view digits, int base) {
  Integer z;
  if (digits.empty()) return z;
  z.set_str(std::string(digits), base);
  return z;
}

// value = mantissa * base^exponent, exactly (base 2 or 10).
Rational scaled(const Integer& mantissa, unsigned long base, long exponent) {
  Integer power;
  mpz_ui_pow_ui(power.get_mpz_t(), base, static_cast<unsigned long>(std::labs(exponent)));
  Rational q = exponent >= 0 ? Rational(mantissa * power) : Rational(mantissa, power);
  q.canonicalize();
  return q;
}

// The common case of a mesh file, at most 19 digits and a power of ten up to 10^19 (both below
// 2^64): the same value as scaled(), without GMP's string conversion and power.
bool small_decimal(std::string_view whole, std::string_view fraction, long exponent, Rational& out) {
  if (whole.size() + fraction.size() > 19 || exponent < -19 || exponent > 19) return false;
  unsigned long mantissa = 0, power = 1;
  static_assert(sizeof(unsigned long) >= 8, "19 decimal digits need 64-bit unsigned long");
  for (char c : whole) mantissa = mantissa * 10 + static_cast<unsigned long>(c - '0');
  for (char c : fraction) mantissa = mantissa * 10 + static_cast<unsigned long>(c - '0');
  for (long k = 0; k < std::labs(exponent); ++k) power *= 10;
  if (exponent >= 0) {
    Integer m(mantissa);
    mpz_mul_ui(m.get_mpz_t(), m.get_mpz_t(), power);
    out = Rational(m);
  } else {
    out = Rational(Integer(mantissa), Integer(power));
    out.canonicalize();
  }
  return true;
}

bool parse_hexfloat(std::string_view s, std::size_t i, Rational& out, std::string* why) {
  std::string_view whole = take_digits(s, i, 16);
  std::string_view fraction;
  if (i < s.size() && s[i] == '.') fraction = take_digits(s, ++i, 16);
  if (whole.empty() && fraction.empty()) return fail(why, "hexfloat without digits");
  long exponent = 0;
  if (i < s.size() && (s[i] == 'p' || s[i] == 'P') && !take_exponent(s, ++i, max_binary_exponent, exponent, why))
    return false;
  if (i != s.size()) return fail(why, "unexpected character in hexfloat");
  Integer mantissa = integer_from_digits(std::string(whole) + std::string(fraction), 16);
  out = scaled(mantissa, 2, exponent - 4 * long(fraction.size()));
  return true;
}

bool parse_decimal_or_fraction(std::string_view s, std::size_t i, Rational& out, std::string* why) {
  std::string_view whole = take_digits(s, i, 10);
  if (i < s.size() && s[i] == '/') {
    std::string_view denominator = take_digits(s, ++i, 10);
    if (whole.empty() || denominator.empty() || i != s.size())
      return fail(why, "malformed fraction (expected p/q with decimal integers)");
    Integer q = integer_from_digits(denominator, 10);
    if (q == 0) return fail(why, "zero denominator");
    out = Rational(integer_from_digits(whole, 10), q);
    out.canonicalize();
    return true;
  }
  std::string_view fraction;
  if (i < s.size() && s[i] == '.') fraction = take_digits(s, ++i, 10);
  if (whole.empty() && fraction.empty()) return fail(why, "no digits");
  long exponent = 0;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E') && !take_exponent(s, ++i, max_decimal_exponent, exponent, why))
    return false;
  if (i != s.size()) return fail(why, "unexpected character");
  if (small_decimal(whole, fraction, exponent - long(fraction.size()), out)) return true;
  Integer mantissa = integer_from_digits(std::string(whole) + std::string(fraction), 10);
  out = scaled(mantissa, 10, exponent - long(fraction.size()));
  return true;
}

bool is_word(std::string_view s, std::string_view word) {
  if (s.size() != word.size()) return false;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(s[i])) != word[i]) return false;
  return true;
}

}  // namespace

std::optional<Rational> parse_rational(std::string_view text, std::string* why) {
  if (text.size() > max_number_length) {
    fail(why, "number longer than " + std::to_string(max_number_length) + " characters");
    return std::nullopt;
  }
  std::size_t i = 0;
  bool negative = false;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) negative = text[i++] == '-';
  std::string_view body = text.substr(i);
  std::string reason;
  Rational value;
  bool ok;
  if (body.empty()) {
    ok = fail(&reason, "empty number");
  } else if (is_word(body, "nan")) {
    ok = fail(&reason, "NaN is not a number");
  } else if (is_word(body, "inf") || is_word(body, "infinity")) {
    ok = fail(&reason, "infinity is not a finite number");
  } else if (body.size() > 1 && body[0] == '0' && (body[1] == 'x' || body[1] == 'X')) {
    ok = parse_hexfloat(body, 2, value, &reason);
  } else {
    ok = parse_decimal_or_fraction(body, 0, value, &reason);
  }
  if (!ok) {
    if (why) *why = reason + " in " + quoted(text);
    return std::nullopt;
  }
  if (negative) value = -value;
  return value;
}

std::string to_string(const Rational& q) { return q.get_str(10); }
std::string to_string(const Integer& z) { return z.get_str(10); }

std::size_t bit_size(const Integer& z) { return z == 0 ? 0 : mpz_sizeinbase(z.get_mpz_t(), 2); }
std::size_t bit_size(const Rational& q) { return bit_size(q.get_num()) + bit_size(q.get_den()); }

Rational rational_from_double(double x) {
  if (!std::isfinite(x)) throw std::domain_error("rational_from_double: NaN or infinity");
  return Rational(x);  // mpq_set_d is exact
}

bool is_double(const Rational& q) {
  double d = to_double(q, Round::toward_zero);
  return std::isfinite(d) && Rational(d) == q;
}

}  // namespace cmx
