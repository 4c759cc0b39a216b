// The orientation determinants instantiated on every number type NumberTraits knows
// (kernel/orient_predicates.hpp: orient3d_in<T>, orient2d_in<T>), against the exact sign:
// exact types always agree, interval types agree whenever they are certain, and floating-point
// types (double, mpfr_float) agree whenever the semi-static filter certifies the double
// evaluation (a well-conditioned input: a more precise evaluation has a smaller error still).
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

#include "arith/number_traits_boost.hpp"
#include "kernel/orient_predicates.hpp"
#include "orient_cases.hpp"

using namespace cmx;
using namespace cmx::test;
using boost::multiprecision::cpp_rational;
using boost::multiprecision::mpfr_float;

namespace {

// Random, near-degenerate and exactly degenerate quadruples (tests/kernel/orient_quads.hpp).
std::vector<Quad> cases() {
  Rng rng(23);
  std::vector<Quad> out;
  for (int i = 0; i < 600; ++i) {
    Quad q;
    for (auto* p : {&q.a, &q.b, &q.c, &q.d})
      for (auto& x : *p) x = rng.uniform(-1, 1);
    out.push_back(q);
  }
  for (int i = 0; i < 600; ++i) {
    Quad q = i % 3 == 0 ? dyadic_coplanar(rng) : i % 3 == 1 ? mixed_coplanar(rng) : on_plane(rng);
    if (i % 2) perturb_ulps(rng, q);
    out.push_back(q);
  }
  return out;
}

// q scaled by a power of two so that every coordinate is an integer (for T = Integer), or false
// when that would overflow. The sign is unchanged: the determinant scales by a positive cube.
bool integer_valued(const Quad& q, Quad& out) {
  int shift = 0;
  for (const P3* p : {&q.a, &q.b, &q.c, &q.d})
    for (double x : *p)
      if (x != 0) {
        int e = 0;
        std::frexp(x, &e);
        shift = std::max(shift, 53 - e);
      }
  out = scaled(q, shift);
  for (const P3* p : {&out.a, &out.b, &out.c, &out.d})
    for (double x : *p)
      if (!std::isfinite(x)) return false;
  return true;
}

struct Tally {
  long compared = 0, certain = 0, wrong = 0;
};

enum class Kind { exact, interval, floating };

template <class T>
void check_orient3d(const std::vector<Quad>& quads, Kind kind, const char* name) {
  Tally t;
  for (const Quad& q : quads) {
    Quad in = q;
    if constexpr (std::is_same_v<T, Integer>)
      if (!integer_valued(q, in)) continue;
    const int exact = exact_sign(q);
    const UncertainSign s = orient3d_in<T>(in.a.data(), in.b.data(), in.c.data(), in.d.data());
    const bool well_conditioned =
        semistatic::orient3d(q.a.data(), q.b.data(), q.c.data(), q.d.data()).has_value();
    if (kind == Kind::exact) CHECK(s.has_value());
    if (!s || (kind == Kind::floating && !well_conditioned)) continue;
    ++t.certain;
    t.wrong += int(*s) != exact;
    ++t.compared;
  }
  MESSAGE(std::string(name), ": ", t.certain, " signs compared, ", t.wrong, " wrong");
  CHECK(t.wrong == 0);
  CHECK(t.compared > 500);  // random inputs are certain in every type
}

template <class T>
void check_orient2d_on_points(Kind kind, const char* name) {
  // Rational points near a line: b - a and c - a almost parallel.
  Rng rng(29);
  long wrong = 0, compared = 0;
  for (int i = 0; i < 300; ++i) {
    const Rational t(rng.below(2000) - 1000, 997);
    const HPoint a(Rational(rng.below(100), 7), Rational(1, 3), 0),
        b(Rational(2, 9), Rational(rng.below(50), 11), 0);
    Rational c[2];
    for (int k = 0; k < 2; ++k) c[k] = a.coordinate(k) + t * (b.coordinate(k) - a.coordinate(k));
    c[1] += Rational(i % 3 - 1, 1000003) / (i % 2 ? 1 : 1000003);
    const HPoint cp(c[0], c[1], 0);
    const Sign exact = orient2d_exact(a, b, cp);
    const UncertainSign s = orient2d_in<T>(a, b, cp);
    if (kind == Kind::exact) CHECK(s.has_value());
    const bool well_conditioned = i % 2 == 1 && i % 3 != 1;  // offset about 1e-6, not 0 or 1e-12
    if (!s || (kind == Kind::floating && !well_conditioned)) continue;
    ++compared;
    wrong += *s != exact;
  }
  MESSAGE(std::string(name), " orient2d on exact points: ", compared, " compared, ", wrong, " wrong");
  CHECK(wrong == 0);
  CHECK(compared > 0);
}

}  // namespace

TEST_CASE("orient3d_in on every number type agrees with the exact sign where it claims to") {
  const std::vector<Quad> quads = cases();
  check_orient3d<double>(quads, Kind::floating, "double");
  check_orient3d<Interval>(quads, Kind::interval, "Interval");
  check_orient3d<MpfrInterval>(quads, Kind::interval, "MpfrInterval");
  check_orient3d<Rational>(quads, Kind::exact, "Rational");
  check_orient3d<Integer>(quads, Kind::exact, "Integer");
  check_orient3d<cpp_rational>(quads, Kind::exact, "cpp_rational");
  check_orient3d<mpfr_float>(quads, Kind::floating, "mpfr_float");
}

TEST_CASE("orient2d_in on exact points in every number type with from_rational") {
  check_orient2d_on_points<double>(Kind::floating, "double");
  check_orient2d_on_points<Interval>(Kind::interval, "Interval");
  check_orient2d_on_points<MpfrInterval>(Kind::interval, "MpfrInterval");
  check_orient2d_on_points<Rational>(Kind::exact, "Rational");
  check_orient2d_on_points<cpp_rational>(Kind::exact, "cpp_rational");
  check_orient2d_on_points<mpfr_float>(Kind::floating, "mpfr_float");
  // Integer has no from_rational: its points are integer coordinates.
  const double a[2] = {0, 0}, b[2] = {3, 1}, c[2] = {6, 2}, d[2] = {6, 3};
  CHECK(orient2d_in<Integer>(a, b, c) == Sign::zero);
  CHECK(orient2d_in<Integer>(a, b, d) == Sign::positive);
  CHECK(orient2d_in<Integer>(a, d, b) == Sign::negative);
}
