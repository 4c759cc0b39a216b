#include <doctest/doctest.h>

#include <cfenv>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include "arith/rational.hpp"
#include "arith/rounding.hpp"

using cmx::Rational;
using cmx::Round;
using cmx::to_double;

static Rational pow2(long e) {
  Rational q = 1;
  if (e >= 0)
    mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
  else
    mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
  return q;
}

TEST_CASE("to_double: ties to even and the directed modes") {
  Rational tie_down = 1 + pow2(-53);    // halfway between 1 and 1 + 2^-52
  Rational tie_up = 1 + 3 * pow2(-53);  // halfway between 1 + 2^-52 and 1 + 2^-51
  CHECK(to_double(tie_down) == 1.0);
  CHECK(to_double(tie_up) == 1.0 + std::ldexp(1.0, -51));
  CHECK(to_double(tie_down, Round::upward) == 1.0 + std::ldexp(1.0, -52));
  CHECK(to_double(-tie_down, Round::upward) == -1.0);
  CHECK(to_double(-tie_down, Round::downward) == -(1.0 + std::ldexp(1.0, -52)));
  CHECK(to_double(-tie_down, Round::toward_zero) == -1.0);
  CHECK(to_double(Rational(1, 3), Round::downward) < to_double(Rational(1, 3), Round::upward));
}

TEST_CASE("to_double: subnormals and overflow") {
  const double tiny = std::numeric_limits<double>::denorm_min();
  CHECK(to_double(pow2(-1075)) == 0.0);  // tie between 0 and denorm_min: even is 0
  CHECK(to_double(3 * pow2(-1076)) == tiny);
  CHECK(to_double(pow2(-1075), Round::upward) == tiny);
  CHECK(to_double(pow2(-1100), Round::downward) == 0.0);
  CHECK(to_double(-pow2(-1100), Round::downward) == -tiny);
  CHECK(to_double(Rational(5) * pow2(-1074)) == 5 * tiny);
  CHECK(to_double(pow2(1024)) == std::numeric_limits<double>::infinity());
  CHECK(to_double(pow2(1024), Round::toward_zero) == DBL_MAX);
  CHECK(to_double(pow2(1024), Round::downward) == DBL_MAX);
  CHECK(to_double(-pow2(1024), Round::upward) == -DBL_MAX);
  CHECK(to_double(-pow2(1024), Round::downward) == -std::numeric_limits<double>::infinity());
  CHECK(to_double(Rational(DBL_MAX)) == DBL_MAX);
  CHECK(to_double(Rational(DBL_MAX) + pow2(970)) ==
        std::numeric_limits<double>::infinity());  // tie: even is 2^1024
  CHECK(to_double(Rational(DBL_MAX) + pow2(969)) == DBL_MAX);
}

// glibc's strtod is correctly rounded in the current rounding mode: an independent oracle.
TEST_CASE("to_double agrees with strtod in all four directions on random decimals") {
  std::mt19937_64 rng(20261123);
  const int modes[4] = {FE_TONEAREST, FE_TOWARDZERO, FE_UPWARD, FE_DOWNWARD};
  const Round dirs[4] = {Round::nearest_even, Round::toward_zero, Round::upward, Round::downward};
  int disagreements = 0;
  for (int n = 0; n < 20000; ++n) {
    std::ostringstream out;  // (not string operator+: g++ 12 -Wrestrict false positive)
    out << ((rng() & 1) ? "-" : "") << rng() % 1000000000000ULL << '.' << rng() << 'e'
        << int(rng() % 640) - 330;
    std::string text = out.str();
    Rational q = *cmx::parse_rational(text);
    for (int m = 0; m < 4; ++m) {
      std::fesetround(modes[m]);
      double expected = std::strtod(text.c_str(), nullptr);
      std::fesetround(FE_TONEAREST);
      if (to_double(q, dirs[m]) != expected) ++disagreements;
    }
  }
  CHECK(disagreements == 0);
}

TEST_CASE("enclosures are tight and contain the value") {
  std::mt19937_64 rng(7);
  for (int n = 0; n < 2000; ++n) {
    Rational q(cmx::Integer(std::to_string(rng())), cmx::Integer(std::to_string(rng() | 1)));
    q.canonicalize();
    auto box = cmx::enclose(q);
    CHECK(Rational(box.lo) <= q);
    CHECK(q <= Rational(box.hi));
    CHECK((box.is_point() || std::nextafter(box.lo, INFINITY) == box.hi));
    CHECK(box.is_point() == cmx::is_double(q));
  }
}

TEST_CASE("enclosures equal the directed roundings, doubles and dyadics of every size included") {
  std::mt19937_64 rng(23);
  auto check = [](const Rational& q) {
    const auto box = cmx::enclose(q);
    CHECK(box.lo == cmx::to_double(q, Round::downward));
    CHECK(box.hi == cmx::to_double(q, Round::upward));
  };
  for (int n = 0; n < 3000; ++n) {
    const int shift = int(rng() % 2200) - 1100;  // across the whole double range and beyond it
    cmx::Integer num(std::to_string(rng() >> (rng() % 64)));
    if (rng() & 1) num = -num;
    cmx::Integer den = 1;
    if (n % 3 == 0) den = cmx::Integer(std::to_string(rng() | 1));  // not dyadic
    Rational q(num, den);
    q.canonicalize();
    if (shift >= 0)
      q *= Rational(cmx::Integer(1) << std::size_t(shift));
    else
      q /= Rational(cmx::Integer(1) << std::size_t(-shift));
    CAPTURE(n);
    check(q);
    check(q + Rational(1, cmx::Integer(1) << 60));  // a 53-bit-plus value near it
  }
  for (double d :
       {1.0, -1.0, 0x1p-1000, 0x1.8p-1000, 0x1p1000, -0x1.fffffffffffffp999, 0x1p-1074, 0.1, 1e300})
    check(Rational(d));
}

TEST_CASE("round_to_dyadic keeps at most k bits and rounds the right way") {
  std::mt19937_64 rng(11);
  for (unsigned k : {1u, 2u, 8u, 24u, 53u, 100u}) {
    for (int n = 0; n < 300; ++n) {
      Rational q(cmx::Integer(std::to_string(rng())) - cmx::Integer(std::to_string(rng())),
                 cmx::Integer(std::to_string(rng() | 1)));
      q.canonicalize();
      if (q == 0) continue;
      auto down = cmx::round_to_dyadic(q, k, Round::downward);
      auto up = cmx::round_to_dyadic(q, k, Round::upward);
      auto near = cmx::round_to_dyadic(q, k);
      CHECK(cmx::bit_size(down.mantissa) <= k);
      CHECK(cmx::bit_size(up.mantissa) <= k);
      CHECK(down.value() <= q);
      CHECK(q <= up.value());
      CHECK((near.value() == down.value() || near.value() == up.value()));
      CHECK(abs(q - near.value()) <= abs(q - (near.value() == down.value() ? up.value() : down.value())));
    }
  }
  CHECK(cmx::round_to_dyadic(Rational(1, 3), 4).value() == Rational(11, 32));  // 0.01011 -> 0.01011(0)
  CHECK(cmx::round_to_dyadic(Rational(255), 4, Round::upward).value() == 256);
}
