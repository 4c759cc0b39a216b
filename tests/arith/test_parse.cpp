#include <doctest/doctest.h>

#include <string>

#include "arith/rational.hpp"
#include "arith/rounding.hpp"

using cmx::Rational;
using cmx::parse_rational;

static Rational parsed(const char* text) {
  std::string why;
  auto q = parse_rational(text, &why);
  INFO(text << ": " << why);
  REQUIRE(q.has_value());
  return *q;
}

static std::string rejection(const char* text) {
  std::string why;
  auto q = parse_rational(text, &why);
  CHECK_FALSE(q.has_value());
  return why;
}

TEST_CASE("integers, decimals, fractions and hexfloats parse exactly") {
  CHECK(parsed("42") == 42);
  CHECK(parsed("-7") == -7);
  CHECK(parsed("+3") == 3);
  CHECK(parsed("0.1") == Rational(1, 10));
  CHECK(parsed("-1.25e-3") == Rational(-1, 800));
  CHECK(parsed(".5") == Rational(1, 2));
  CHECK(parsed("7.") == 7);
  CHECK(parsed("1E3") == 1000);
  CHECK(parsed("2.5e+2") == 250);
  CHECK(parsed("6/4") == Rational(3, 2));
  CHECK(parsed("-6/4") == Rational(-3, 2));
  CHECK(parsed("0x1.8p-3") == Rational(3, 16));
  CHECK(parsed("-0X10") == -16);
  CHECK(parsed("0x.8") == Rational(1, 2));
  CHECK(parsed("0x1p+4") == 16);
  // 0.1 as a double, written as its exact decimal expansion, is not 1/10.
  CHECK(parsed("0.1000000000000000055511151231257827021181583404541015625") == Rational(0.1));
}

// The value of a decimal by GMP's own reader: the digits as an integer over a power of ten.
static Rational by_gmp(const char* digits, int exponent) {
  Rational q{cmx::Integer(digits)};
  cmx::Integer power;
  mpz_ui_pow_ui(power.get_mpz_t(), 10, static_cast<unsigned long>(exponent < 0 ? -exponent : exponent));
  q = exponent < 0 ? Rational(q / power) : Rational(q * power);
  q.canonicalize();
  return q;
}

TEST_CASE("decimals on both sides of the 19-digit, 10^19 short cut parse to the same values") {
  CHECK(parsed("9999999999999999999") == by_gmp("9999999999999999999", 0));     // 19 digits
  CHECK(parsed("99999999999999999999") == by_gmp("99999999999999999999", 0));   // 20 digits
  CHECK(parsed("0.9999999999999999999") == by_gmp("9999999999999999999", -19));
  CHECK(parsed("0.99999999999999999999") == by_gmp("99999999999999999999", -20));
  CHECK(parsed("1e19") == by_gmp("1", 19));
  CHECK(parsed("9999999999999999999e19") == by_gmp("9999999999999999999", 19));  // product past 2^64
  CHECK(parsed("1e20") == by_gmp("1", 20));
  CHECK(parsed("1e-19") == by_gmp("1", -19));
  CHECK(parsed("1e-20") == by_gmp("1", -20));
  CHECK(parsed("-0.333333") == -by_gmp("333333", -6));
  CHECK(parsed("0.000") == 0);
  CHECK(parsed("12.5e-1") == Rational(5, 4));
  CHECK(parsed("0.666667") == Rational(666667, 1000000));
}

TEST_CASE("canonical printing round-trips") {
  for (const char* text : {"0", "1", "-1", "1/3", "-22/7", "123456789012345678901234567891/1024"}) {
    Rational q = parsed(text);
    CHECK(cmx::to_string(q) == text);
    CHECK(parsed(cmx::to_string(q).c_str()) == q);
  }
  CHECK(cmx::to_string(parsed("10/4")) == "5/2");
  CHECK(cmx::to_string(parsed("0.75")) == "3/4");
  CHECK(cmx::to_string(parsed("-4/2")) == "-2");
}

TEST_CASE("bad numbers are rejected with a reason") {
  CHECK(rejection("1/0").find("zero denominator") != std::string::npos);
  CHECK(rejection("abc").find("'abc'") != std::string::npos);
  CHECK(rejection("nan").find("NaN") != std::string::npos);
  CHECK(rejection("-Inf").find("infinity") != std::string::npos);
  CHECK(rejection("1e999999999").find("exponent out of range") != std::string::npos);
  CHECK(rejection("0x1p9999999").find("exponent out of range") != std::string::npos);
  CHECK(rejection("").find("empty") != std::string::npos);
  CHECK(rejection("-").find("empty") != std::string::npos);
  CHECK(rejection("1.2.3").find("unexpected character") != std::string::npos);
  CHECK(rejection("1e").find("missing exponent") != std::string::npos);
  CHECK(rejection("3/-4").find("malformed fraction") != std::string::npos);
  CHECK(rejection("1/2/3").find("malformed fraction") != std::string::npos);
  CHECK(rejection(" 1").size() > 0);
  CHECK(rejection("0x").find("without digits") != std::string::npos);
  CHECK(rejection(std::string(cmx::max_number_length + 1, '1').c_str()).find("longer") != std::string::npos);
}

TEST_CASE("bit sizes") {
  CHECK(cmx::bit_size(cmx::Integer(0)) == 0);
  CHECK(cmx::bit_size(cmx::Integer(1)) == 1);
  CHECK(cmx::bit_size(cmx::Integer(-255)) == 8);
  CHECK(cmx::bit_size(Rational(3, 8)) == 2 + 4);
}
