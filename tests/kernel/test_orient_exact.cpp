#include <doctest/doctest.h>

#include "kernel/orient_exact.hpp"

using cmx::HPoint;
using cmx::Rational;
using cmx::Sign;

TEST_CASE("exact orient3d: unit tetrahedron and its mirror") {
  HPoint o, x = HPoint::from_doubles(1, 0, 0), y = HPoint::from_doubles(0, 1, 0), z = HPoint::from_doubles(0, 0, 1);
  CHECK(cmx::orient3d_exact(o, x, y, z) == Sign::positive);
  CHECK(cmx::orient3d_exact(o, y, x, z) == Sign::negative);
  CHECK(cmx::orient3d_exact(o, x, y, HPoint::from_doubles(3, -2, 0)) == Sign::zero);
}

TEST_CASE("exact orient3d on rationals with large and different W") {
  Rational t(1, 3), u(2, 7);
  HPoint a(Rational(1, 5), Rational(2, 9), Rational(-3, 11)), b(t, u, Rational(5, 13)), c(Rational(7, 17), 0, 1);
  // d = a + t (b - a) + u (c - a): exactly coplanar, however big W gets.
  HPoint d(a.coordinate(0) + t * (b.coordinate(0) - a.coordinate(0)) + u * (c.coordinate(0) - a.coordinate(0)),
           a.coordinate(1) + t * (b.coordinate(1) - a.coordinate(1)) + u * (c.coordinate(1) - a.coordinate(1)),
           a.coordinate(2) + t * (b.coordinate(2) - a.coordinate(2)) + u * (c.coordinate(2) - a.coordinate(2)));
  CHECK(cmx::orient3d_exact(a, b, c, d) == Sign::zero);
  HPoint above(d.coordinate(0), d.coordinate(1), d.coordinate(2) + Rational(1, 1000000007));
  Sign s = cmx::orient3d_exact(a, b, c, above);
  CHECK(s != Sign::zero);
  CHECK(cmx::orient3d_exact(b, a, c, above) == -s);
}

TEST_CASE("homogeneous points are canonical") {
  HPoint p = HPoint::from_homogeneous(2, 4, -6, -2);
  CHECK(p.W() == 1);
  CHECK(p.X() == -1);
  CHECK(p == HPoint(Rational(-1), Rational(-2), Rational(3)));
  CHECK(p.is_double());
  HPoint q(Rational(1, 3), 0, 0);
  CHECK_FALSE(q.is_double());
  CHECK(q.enclosure(0).lo < q.enclosure(0).hi);
  CHECK(cmx::midpoint(p, q) == HPoint(Rational(-1, 3), Rational(-1), Rational(3, 2)));
}
