// The verifier's own orientation filter (verify_map.hpp) against an independent exact sign on
// hard double quadruples: near-coplanar, exactly coplanar, mixed magnitudes, and scaled to the
// ends of the exponent range where the filter must step aside.
#include <doctest/doctest.h>

#include "../kernel/orient_cases.hpp"
#include "algorithm/verify/verify_map.hpp"
#include "arith/rounding.hpp"
#include "kernel/orient_exact.hpp"

using namespace cmx;
using namespace cmx::test;

namespace {

int verifier_sign(const Quad& q) {
  auto h = [](const P3& p) { return HPoint::from_doubles(p[0], p[1], p[2]); };
  return int(algorithm::verification_orient(h(q.a), h(q.b), h(q.c), h(q.d)));
}

}  // namespace

TEST_CASE("the verifier's static filter never disagrees with the exact sign") {
  Rng r(20261129);
  int disagreements = 0, zeros = 0;
  for (int i = 0; i < 60000; ++i) {
    Quad q;
    switch (i % 4) {
      case 0: q = on_plane(r); break;
      case 1: q = dyadic_coplanar(r); break;
      case 2: q = mixed_coplanar(r); break;
      default: q = on_plane(r, 1e3); perturb_ulps(r, q); break;
    }
    if (i % 5 == 0) perturb_ulps(r, q);
    if (i % 7 == 0) q = scaled(q, (i % 2 ? 1 : -1) * (400 + r.below(600)));
    const int expected = exact_sign(q);
    zeros += expected == 0;
    if (verifier_sign(q) != expected) ++disagreements;
  }
  CHECK(disagreements == 0);
  CHECK(zeros > 1000);  // the hard cases are really there
}

TEST_CASE("the verifier's static filter steps aside where triple products would be subnormal") {
  // Differences near 2^-350 keep every coordinate in any plausible filter range while their
  // triple products fall below 2^-1022, where rounding is no longer relative: the window in
  // which a filter guarded on the differences alone answers wrong signs.
  Rng r(20261201);
  int disagreements = 0, decided = 0;
  for (int i = 0; i < 40000; ++i) {
    Quad q;
    switch (i % 3) {
      case 0: q = on_plane(r); break;
      case 1: q = mixed_coplanar(r); break;
      default: q = on_plane(r, 1e3); break;
    }
    perturb_ulps(r, q);
    q = scaled(q, -(290 + int(r.below(100))));
    const int expected = exact_sign(q);
    decided += expected != 0;
    if (verifier_sign(q) != expected) ++disagreements;
  }
  CHECK(disagreements == 0);
  CHECK(decided > 10000);
}

TEST_CASE("the verifier's interval filter on rational coordinates never disagrees with the exact sign") {
  // Coordinates that are not doubles (decimals, thirds) take the interval path: near-coplanar
  // quadruples moved off the plane by amounts near their enclosures' width.
  Rng r(20261202);
  int disagreements = 0, decided = 0;
  for (int i = 0; i < 20000; ++i) {
    const Quad q = on_plane(r, i % 3 == 0 ? 1e-3 : 1e3);
    auto h = [&](const P3& p, int k) {
      const Rational offset(Integer(int(r.below(7)) - 3), Integer(3) * (Integer(1) << (40 + 10 * (k % 3))));
      return HPoint(rational_from_double(p[0]) + offset, rational_from_double(p[1]) - offset, rational_from_double(p[2]));
    };
    const HPoint a = h(q.a, i), b = h(q.b, i + 1), c = h(q.c, i + 2), d = h(q.d, i);
    const Sign expected = orient3d_exact(a, b, c, d);
    decided += expected != Sign::zero;
    if (algorithm::verification_orient(a, b, c, d) != expected) ++disagreements;
  }
  CHECK(disagreements == 0);
  CHECK(decided > 5000);
}
