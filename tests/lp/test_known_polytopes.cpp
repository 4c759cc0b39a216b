// Chebyshev centres with exact known answers, on every backend.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "arith/rounding.hpp"
#include "lp/chebyshev_center.hpp"
#include "lp/row_weights.hpp"
#include "lp_test_util.hpp"

using namespace cmx;
using namespace cmx::lp;
using cmx::lp::test::all_backends;

namespace {

// GLPK needs integer-scaled data below 2^53, which 53-bit weights of different binades exceed
// after the column scaling; 24-bit weights fit (see lp/glpk/glpk_backend.hpp).
unsigned weight_bits_for(const std::string& backend) { return backend == "glpk" ? 24 : 53; }

ChebyshevResult solve_with(const std::vector<HalfSpace>& h, const std::string& backend, Norm norm = Norm::l2_upper) {
  ChebyshevOptions o;
  o.backend = backend;
  o.norm = norm;
  o.weight_bits = weight_bits_for(backend);
  return chebyshev_center(h, o);
}

std::vector<HalfSpace> cube() {
  return {{1, 0, 0, 1}, {-1, 0, 0, 0}, {0, 1, 0, 1}, {0, -1, 0, 0}, {0, 0, 1, 1}, {0, 0, -1, 0}};
}

}  // namespace

TEST_CASE("unit cube: centre (1/2, 1/2, 1/2), r = 1/2, axis weights exactly 1") {
  CHECK(l2_upper_weight(1, 0, 0) == 1);
  CHECK(l2_upper_weight(0, -1, 0) == 1);
  CHECK(l2_upper_weight(0, 0, Rational(1, 4)) == Rational(1, 4));
  for (const auto& backend : all_backends())
    for (Norm norm : {Norm::l2_upper, Norm::l1}) {
      CAPTURE(backend);
      const ChebyshevResult r = solve_with(cube(), backend, norm);
      CHECK(r.status == ChebyshevStatus::interior);
      CHECK(r.radius == Rational(1, 2));
      for (const Rational& x : r.center) CHECK(x == Rational(1, 2));
    }
}

TEST_CASE("regular simplex: centre at the centroid, inradius exact with l1 weights") {
  // x, y, z >= 0 and x + y + z <= 1 (not regular in R^3, but symmetric): with l1 weights the
  // rows are -x + r <= 0 (three) and x + y + z + 3 r <= 1, so r = 1/6 at (1/6, 1/6, 1/6).
  const std::vector<HalfSpace> corner = {{-1, 0, 0, 0}, {0, -1, 0, 0}, {0, 0, -1, 0}, {1, 1, 1, 1}};
  // Regular tetrahedron with vertices (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1): faces
  // +-x +-y +-z <= 1 with an odd number of minus signs... i.e. x+y+z<=1 is not a face; the faces
  // are -x-y-z <= 1, -x+y+z <= 1, x-y+z <= 1, x+y-z <= 1; centroid 0, inradius 1/sqrt(3).
  const std::vector<HalfSpace> regular = {{-1, -1, -1, 1}, {-1, 1, 1, 1}, {1, -1, 1, 1}, {1, 1, -1, 1}};
  for (const auto& backend : all_backends()) {
    CAPTURE(backend);
    ChebyshevResult r = solve_with(corner, backend, Norm::l1);
    CHECK(r.status == ChebyshevStatus::interior);
    CHECK(r.radius == Rational(1, 6));
    for (const Rational& x : r.center) CHECK(x == Rational(1, 6));
    r = solve_with(regular, backend);
    CHECK(r.status == ChebyshevStatus::interior);
    for (const Rational& x : r.center) CHECK(x == 0);  // by symmetry: all weights are equal
    const Rational w = l2_upper_weight(1, 1, 1, weight_bits_for(backend));
    CHECK(w * w >= 3);
    CHECK(r.radius == 1 / w);
    CHECK(r.radius * r.radius * 3 <= 1);  // the ball fits: r <= 1/sqrt(3)
    CHECK(r.radius * r.radius * 3 > Rational(1) - Rational(1, 1000000));
  }
}

TEST_CASE("empty interior at a cluster point: kernel is a single point or a segment") {
  // Cone with apex (1, 2, 3) cut by a plane through the apex: the kernel is the apex alone.
  const std::vector<HalfSpace> point = {{-1, 0, 0, -1}, {0, -1, 0, -2}, {0, 0, -1, -3}, {1, 1, 1, 6}, {1, 1, 2, 9}};
  // x = 0, y = 0 (two pairs of opposite half-spaces), 0 <= z <= 1: a segment.
  const std::vector<HalfSpace> segment = {{1, 0, 0, 0}, {-1, 0, 0, 0}, {0, 1, 0, 0}, {0, -1, 0, 0}, {0, 0, 1, 1}, {0, 0, -1, 0}};
  for (const auto& backend : all_backends()) {
    CAPTURE(backend);
    ChebyshevResult r = solve_with(point, backend);
    CHECK(r.status == ChebyshevStatus::empty_interior);
    CHECK(r.radius == 0);
    CHECK(r.center == std::array<Rational, 3>{1, 2, 3});
    r = solve_with(segment, backend);
    CHECK(r.status == ChebyshevStatus::empty_interior);
    CHECK(r.radius == 0);
    CHECK(inside(segment, r.center));
    CHECK(r.center[0] == 0);
    CHECK(r.center[1] == 0);
  }
}

TEST_CASE("infeasible, unbounded, slab, zero rows, no rows") {
  const std::vector<HalfSpace> infeasible = {{1, 0, 0, 0}, {-1, 0, 0, -1}};
  const std::vector<HalfSpace> octant = {{-1, 0, 0, 0}, {0, -1, 0, 0}, {0, 0, -1, 0}};
  const std::vector<HalfSpace> slab = {{1, 0, 0, 2}, {-1, 0, 0, 0}};
  const std::vector<HalfSpace> zero_ok = {{0, 0, 0, 0}, {1, 0, 0, 1}, {-1, 0, 0, 0}, {0, 0, 0, 5}};
  const std::vector<HalfSpace> zero_bad = {{1, 0, 0, 1}, {0, 0, 0, Rational(-1, 3)}};
  for (const auto& backend : all_backends()) {
    CAPTURE(backend);
    CHECK(solve_with(infeasible, backend).status == ChebyshevStatus::infeasible);
    CHECK(solve_with(octant, backend).status == ChebyshevStatus::unbounded);
    CHECK(solve_with({}, backend).status == ChebyshevStatus::unbounded);
    ChebyshevResult r = solve_with(slab, backend);
    CHECK(r.status == ChebyshevStatus::interior);  // r bounded although the slab is not
    CHECK(r.radius == 1);
    CHECK(r.center[0] == 1);
    r = solve_with(zero_ok, backend);
    CHECK(r.status == ChebyshevStatus::interior);
    CHECK(r.radius == Rational(1, 2));
    CHECK(solve_with(zero_bad, backend).status == ChebyshevStatus::infeasible);
  }
}

TEST_CASE("l2-upper weights are rigorous upper bounds") {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 2000; ++i) {
    const unsigned bits = 1 + unsigned(i % 200);
    const Rational a = test::random_rational(rng, bits), b = test::random_rational(rng, bits),
                   c = test::random_rational(rng, (i % 3) ? bits : 1000);
    const Rational s = a * a + b * b + c * c;
    for (unsigned wb : {53u, 24u, 8u, 80u}) {
      const Rational w = l2_upper_weight(a, b, c, wb);
      CHECK(w * w >= s);
      if (sgn(s) > 0 && wb >= 24) CHECK(w * w <= s * (1 + Rational(1, 1 << 20)));
    }
    CHECK(l1_weight(a, b, c) == abs(a) + abs(b) + abs(c));
  }
  // Huge and tiny components use the MPFR path.
  const Rational huge = Rational(Integer(1) << 3000), tiny = Rational(Integer(1), Integer(1) << 3000);
  CHECK(l2_upper_weight(huge, huge, 0) * l2_upper_weight(huge, huge, 0) >= 2 * huge * huge);
  CHECK(l2_upper_weight(tiny, 0, 0) == tiny);
  CHECK(parse_norm("l2-upper") == Norm::l2_upper);
  CHECK(parse_norm("l1") == Norm::l1);
  CHECK_FALSE(parse_norm("linf"));
}

TEST_CASE("the float Chebyshev guess is close to the certified radius, and flat kernels guess about zero") {
  std::mt19937_64 rng(77);
  int compared = 0;
  for (int rep = 0; rep < 200; ++rep) {
    const auto h = cmx::lp::test::random_kernel(rng, 8 + std::size_t(rep % 40), 30);
    const ChebyshevResult exact = chebyshev_center(h);
    if (exact.status != ChebyshevStatus::interior) continue;  // some random kernels are unbounded
    ++compared;
    std::vector<std::array<double, 4>> rows;
    for (const HalfSpace& x : h) rows.push_back({to_double(x.a), to_double(x.b), to_double(x.c), to_double(x.d)});
    const FloatChebyshev guess = float_chebyshev(rows);
    REQUIRE(guess.optimal);
    const double r = to_double(exact.radius);
    CHECK(std::fabs(guess.radius - r) <= 1e-9 * std::max(r, guess.scale));
  }
  CHECK(compared > 100);
  // The unit cube squeezed to the plane z = 0: no interior; the guess is zero up to rounding.
  std::vector<HalfSpace> flat = {{1, 0, 0, 1}, {-1, 0, 0, 1}, {0, 1, 0, 1}, {0, -1, 0, 1}, {0, 0, 1, 0}, {0, 0, -1, 0}};
  const FloatChebyshev g = float_chebyshev({{1, 0, 0, 1}, {-1, 0, 0, 1}, {0, 1, 0, 1}, {0, -1, 0, 1}, {0, 0, 1, 0}, {0, 0, -1, 0}});
  REQUIRE(g.optimal);
  CHECK(std::fabs(g.radius) <= 1e-12);
  CHECK(chebyshev_center(flat).status == ChebyshevStatus::empty_interior);
}
