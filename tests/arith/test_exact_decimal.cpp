// exact_decimal: the full decimal expansion of a double, checked three ways: known strings, an
// exact read-back (parse_rational == rational_from_double), and glibc's printf, which prints the
// exact digits at any requested precision.
#include <doctest/doctest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "arith/exact_decimal.hpp"
#include "arith/rational.hpp"

using cmx::exact_decimal;

// glibc's "%.1074f" of x (exact: every double has at most 1074 fraction digits), trailing zeros
// and a trailing point removed.
static std::string printf_exact(double x) {
  std::string buf(1400, '\0');
  const int n = std::snprintf(buf.data(), buf.size(), "%.1074f", x);
  REQUIRE(n > 0);
  REQUIRE(std::size_t(n) < buf.size());
  buf.resize(std::size_t(n));
  while (buf.back() == '0') buf.pop_back();
  if (buf.back() == '.') buf.pop_back();
  return buf;
}

static void check_round_trip(double x) {
  CAPTURE(x);
  const std::string text = exact_decimal(x);
  CAPTURE(text);
  const auto q = cmx::parse_rational(text);
  REQUIRE(q.has_value());
  CHECK(*q == cmx::rational_from_double(x));
  CHECK(std::bit_cast<std::uint64_t>(std::strtod(text.c_str(), nullptr)) == std::bit_cast<std::uint64_t>(x));
  CHECK(text == printf_exact(x));
}

TEST_CASE("exact_decimal: known expansions") {
  CHECK(exact_decimal(0.1) == "0.1000000000000000055511151231257827021181583404541015625");
  CHECK(exact_decimal(-0.1) == "-0.1000000000000000055511151231257827021181583404541015625");
  CHECK(exact_decimal(0.5) == "0.5");
  CHECK(exact_decimal(2.5) == "2.5");
  CHECK(exact_decimal(-3.0) == "-3");
  CHECK(exact_decimal(1.0) == "1");
  CHECK(exact_decimal(0.0) == "0");
  CHECK(exact_decimal(-0.0) == "-0");
  CHECK(exact_decimal(9007199254740993.0) == "9007199254740992");  // 2^53 + 1 rounds to 2^53
  const std::string big = exact_decimal(1e300);
  CHECK(big.size() == 301);
  CHECK(big.find('.') == std::string::npos);
  CHECK(big.rfind("1000000000000000052504760255204420248704468581108159154915854115", 0) == 0);
  CHECK(big.substr(big.size() - 30) == "115669472196386865459400540160");
  const std::string tiny = exact_decimal(std::numeric_limits<double>::denorm_min());
  CHECK(tiny.rfind("0.000", 0) == 0);
  CHECK(tiny.size() == 2 + 1074);  // "0." and 1074 fraction digits, the last one 5
  CHECK(tiny.back() == '5');
  CHECK(tiny.find("4940656458412465441765687928682213723650598026143247644255856825") == 2 + 323);
  CHECK(exact_decimal(DBL_MAX).size() == 309);
}

TEST_CASE("exact_decimal: NaN and infinities are rejected") {
  CHECK_THROWS_AS(exact_decimal(std::numeric_limits<double>::quiet_NaN()), std::domain_error);
  CHECK_THROWS_AS(exact_decimal(std::numeric_limits<double>::infinity()), std::domain_error);
  CHECK_THROWS_AS(exact_decimal(-std::numeric_limits<double>::infinity()), std::domain_error);
}

TEST_CASE("exact_decimal: read back exactly over random doubles") {
  std::mt19937_64 rng(20240611);
  int checked = 0;
  // Random bit patterns: every exponent equally likely, so huge values and subnormals are common.
  for (int i = 0; i < 3000; ++i) {
    const double x = std::bit_cast<double>(rng());
    if (!std::isfinite(x)) continue;
    check_round_trip(x);
    ++checked;
  }
  // Subnormals and their neighbours, and values near 1 (long fractions of few integer digits).
  for (int i = 0; i < 500; ++i) {
    const std::uint64_t low = rng() & ((std::uint64_t{1} << 52) - 1);
    check_round_trip(std::bit_cast<double>(low));                             // subnormal
    check_round_trip(-std::bit_cast<double>(low | (std::uint64_t{1} << 52))); // smallest normal binade
    check_round_trip(std::ldexp(1.0 + double(low) * 0x1p-52, int(rng() % 128) - 64));
    checked += 3;
  }
  for (double x : {DBL_MAX, -DBL_MAX, DBL_MIN, DBL_EPSILON, 1e-300, 1e22, 1e23, 123456.789, -0.0})
    check_round_trip(x), ++checked;
  MESSAGE(checked << " doubles read back exactly");
}
