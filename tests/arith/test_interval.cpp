// Interval arithmetic (double and MPFR): results enclose the exact value, bounds are the tightest
// directed roundings, and the number traits behave as documented.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>

#include "arith/interval.hpp"
#include "arith/mpfr_interval.hpp"
#include "arith/number_traits.hpp"
#include "arith/rounding.hpp"

using namespace cmx;

namespace {
std::uint64_t state = 0x9876;
std::uint64_t next() {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}
double any_double(int spread = 60) {
  const double m = double(next() >> 11) * 0x1p-53 + 0.5;
  return std::ldexp(next() & 1 ? m : -m, int(next() % (2 * spread)) - spread);
}
Rational exact(double x) { return rational_from_double(x); }

template <class Op>
void check_tight(double a, double b, Op op, const Rational& value) {
  Interval r;
  {
    UpwardRoundingScope s;
    r = opaque(op(opaque(Interval(a)), opaque(Interval(b))));
  }
  CHECK(r.lo == to_double(value, Round::downward));
  CHECK(r.hi == to_double(value, Round::upward));
}
}  // namespace

TEST_CASE("double interval +, -, * on points give the two directed roundings") {
  for (int i = 0; i < 20000; ++i) {
    const double a = any_double(), b = any_double();
    check_tight(a, b, [](Interval x, Interval y) { return x + y; }, exact(a) + exact(b));
    check_tight(a, b, [](Interval x, Interval y) { return x - y; }, exact(a) - exact(b));
    check_tight(a, b, [](Interval x, Interval y) { return x * y; }, exact(a) * exact(b));
  }
}

TEST_CASE("double interval expressions enclose the exact rational value") {
  for (int i = 0; i < 5000; ++i) {
    // Enclosures of random rationals, combined in a determinant-like expression.
    Rational q[6];
    Interval x[6];
    for (int k = 0; k < 6; ++k) {
      q[k] = exact(any_double(20)) / Rational(int(next() % 1000) + 1);
      x[k] = NumberTraits<Interval>::from_rational(q[k]);
      REQUIRE(x[k].contains(to_double(q[k])));
    }
    Interval r;
    {
      UpwardRoundingScope s;
      Interval y[6];
      for (int k = 0; k < 6; ++k) y[k] = opaque(x[k]);
      r = opaque((y[0] - y[1]) * (y[2] + y[3]) - y[4] * y[5]);
    }
    const Rational v = (q[0] - q[1]) * (q[2] + q[3]) - q[4] * q[5];
    CHECK(exact(r.lo) <= v);
    CHECK(v <= exact(r.hi));
    if (const auto s = r.sign()) CHECK(*s == sign(v));
  }
}

TEST_CASE("interval sign: certain, zero or uncertain, and NaN is uncertain") {
  CHECK(Interval(1, 2).sign() == Sign::positive);
  CHECK(Interval(-2, -1).sign() == Sign::negative);
  CHECK(Interval(0, 0).sign() == Sign::zero);
  CHECK_FALSE(Interval(-1, 1).sign());
  CHECK_FALSE(Interval(0, 1).sign());
  CHECK_FALSE(Interval(NAN, 1).sign());
  CHECK_FALSE(Interval(-1, NAN).sign());
  // Overflow gives an infinite bound, still an enclosure with a certain sign.
  Interval big;
  {
    UpwardRoundingScope s;
    big = opaque(opaque(Interval(1e300)) * opaque(Interval(1e300)));
  }
  CHECK(big.hi == INFINITY);
  CHECK(big.sign() == Sign::positive);
}

TEST_CASE("MPFR intervals enclose, tighten with precision, and copy/move safely") {
  for (long bits : {24L, 53L, 113L, 300L}) {
    for (int i = 0; i < 500; ++i) {
      const Rational a = exact(any_double(20)) / Rational(int(next() % 1000) + 1);
      const Rational b = exact(any_double(20)) / Rational(int(next() % 1000) + 3);
      const MpfrInterval x(a, bits), y(b, bits);
      CHECK(x.contains(a));
      CHECK((x + y).contains(a + b));
      CHECK((x - y).contains(a - b));
      CHECK((x * y).contains(a * b));
      CHECK((-x).contains(-a));
      const MpfrInterval e = (x - y) * (x + y) - x * y;
      CHECK(e.contains((a - b) * (a + b) - a * b));
      CHECK(e.precision() == bits);
      if (const auto s = e.sign()) CHECK(*s == sign((a - b) * (a + b) - a * b));
    }
  }
  MpfrInterval third(Rational(1, 3), 200);
  CHECK(third.lo_double() <= 1.0 / 3);
  CHECK(third.hi_double() >= 1.0 / 3);
  MpfrInterval copy = third;
  MpfrInterval moved = std::move(copy);
  CHECK(moved.contains(Rational(1, 3)));
  copy = third;  // a moved-from interval may be assigned to
  CHECK(copy.contains(Rational(1, 3)));
  CHECK(MpfrInterval(Rational(0), 64).sign() == Sign::zero);
  CHECK_FALSE(third.sign() == Sign::zero);
  CHECK((third - third).contains(0));
  CHECK_FALSE((third - third).sign());
}

TEST_CASE("number traits") {
  static_assert(NumberTraits<Integer>::is_exact && NumberTraits<Rational>::is_exact);
  static_assert(!NumberTraits<double>::is_exact && !NumberTraits<Interval>::is_exact);
  static_assert(!NumberTraits<MpfrInterval>::is_exact);
  CHECK(NumberTraits<Rational>::from_double(0.5) == Rational(1, 2));
  CHECK(NumberTraits<Integer>::from_double(-12.0) == -12);
  CHECK_THROWS_AS(NumberTraits<Integer>::from_double(0.5), std::domain_error);
  CHECK(NumberTraits<Rational>::sign(Rational(-1, 3)) == Sign::negative);
  CHECK(NumberTraits<double>::sign(0.0) == Sign::zero);
  const Interval t = NumberTraits<Interval>::from_rational(Rational(1, 3));
  CHECK(t.lo < t.hi);
  CHECK_FALSE(NumberTraits<MpfrInterval>::sign(NumberTraits<MpfrInterval>::from_rational(Rational(1, 3), 80) -
                                               NumberTraits<MpfrInterval>::from_rational(Rational(1, 3), 80)));
}
