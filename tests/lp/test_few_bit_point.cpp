// Few-bit interior points: always strictly inside, never more bits than the start point.
#include <doctest/doctest.h>

#include "lp/few_bit_point.hpp"
#include "lp_test_util.hpp"

using namespace cmx;
using namespace cmx::lp;
using namespace cmx::lp::test;

TEST_CASE("point bits: numerator plus denominator bits, maximum over coordinates") {
  CHECK(point_bits({Rational(3, 4), 0, 1}) == 5);
  CHECK(point_bits({0, 0, 0}) == 1);  // 0 = 0/1: 0 + 1 bits
}

TEST_CASE("few-bit searches on random kernels: strictly inside, never longer than the centre") {
  std::mt19937_64 rng(314);
  int reduced[4] = {0, 0, 0, 0}, total = 0;
  for (unsigned bits : {10u, 40u, 200u})
    for (int rep = 0; rep < 12; ++rep) {
      const auto h = random_kernel(rng, 6 + std::size_t(rep) * 3, bits, rep % 2 == 1);
      const ChebyshevResult c = chebyshev_center(h);
      if (c.status != ChebyshevStatus::interior) continue;
      ++total;
      const std::size_t cb = point_bits(c.center);
      // A second point on the boundary: walk from the centre along +x to the first plane.
      Point3 other = c.center;
      std::optional<Rational> tmin;
      for (const auto& s : h)
        if (sgn(s.a) > 0) {
          const Rational t = (s.d - dot(s, c.center)) / s.a;
          if (!tmin || t < *tmin) tmin = t;
        }
      if (tmin) other[0] += *tmin;
      const FewBitResult rs[4] = {few_bits_by_doubles(h, c.center), few_bits_by_dyadics(h, c.center),
                                  few_bits_by_segment(h, c.center, other), few_bits_by_shift(h, c.center)};
      for (int k = 0; k < 4; ++k) {
        CAPTURE(k);
        CHECK(strictly_inside(h, rs[k].point));
        CHECK(rs[k].bits == point_bits(rs[k].point));
        CHECK(rs[k].bits <= cb);
        CHECK(rs[k].reduced == (rs[k].point != c.center));
        if (rs[k].reduced) ++reduced[k];
      }
      CHECK(rs[1].bits <= rs[0].bits);  // the dyadic search reaches 53 bits or fewer
    }
  MESSAGE("kernels " << total << ", reduced by doubles " << reduced[0] << ", dyadics " << reduced[1] << ", segment "
                     << reduced[2] << ", shift " << reduced[3]);
  CHECK(reduced[1] > total / 2);
}

TEST_CASE("few-bit searches: tiny kernels keep the centre, and a low-bit start on a segment") {
  // A thin slab 0 < x < 2^-100 around x = 2^-101: doubles work (2^-101 is a double).
  const Rational e = Rational(1, Integer(1) << 100);
  const std::vector<HalfSpace> slab = {{1, 0, 0, e}, {-1, 0, 0, 0}, {0, 1, 0, 1}, {0, -1, 0, 1}, {0, 0, 1, 1}, {0, 0, -1, 1}};
  const Point3 mid = {e / 2 + e / 7, Rational(1, 3), Rational(-2, 7)};
  REQUIRE(strictly_inside(slab, mid));
  const FewBitResult d = few_bits_by_dyadics(slab, mid);
  CHECK(strictly_inside(slab, d.point));
  CHECK(d.bits < point_bits(mid));
  // Segment: from a low-bit interior point toward a boundary point.
  const std::vector<HalfSpace> cube = {{1, 0, 0, 1}, {-1, 0, 0, 0}, {0, 1, 0, 1}, {0, -1, 0, 0}, {0, 0, 1, 1}, {0, 0, -1, 0}};
  const Point3 p = {Rational(1, 2), Rational(1, 2), Rational(1, 2)}, q = {1, Rational(1, 2), Rational(1, 2)};
  const FewBitResult s = few_bits_by_segment(cube, p, q);
  CHECK(strictly_inside(cube, s.point));
  CHECK(s.bits <= point_bits(p));
  CHECK_THROWS_AS(few_bits_by_doubles(cube, q), std::invalid_argument);  // q is not strictly inside
}
