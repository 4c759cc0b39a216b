// Motzkin certificates of open half-spaces without a common point (kernel/plane.hpp): never
// claimed when a common point exists, and found for the configurations a closed cone produces.
#include <doctest/doctest.h>

#include <random>

#include "kernel/plane.hpp"

using cmx::InnerHalfSpace;
using cmx::Integer;
using cmx::proves_no_common_point;

namespace {

InnerHalfSpace hs(long a, long b, long c, long w) {
  return {{Integer(a), Integer(b), Integer(c)}, Integer(w)};
}

long small(std::mt19937_64& rng, long range) {
  return long(rng() % std::uint64_t(2 * range + 1)) - range;
}

std::array<Integer, 3> random_normal(std::mt19937_64& rng) {
  std::array<Integer, 3> u;
  do {
    for (auto& c : u) c = small(rng, 50);
  } while (sgn(u[0]) == 0 && sgn(u[1]) == 0 && sgn(u[2]) == 0);
  return u;
}

Integer dot(const std::array<Integer, 3>& u, const std::array<Integer, 3>& p) {
  return u[0] * p[0] + u[1] * p[1] + u[2] * p[2];
}

}  // namespace

TEST_CASE("Motzkin certificates on small configurations") {
  CHECK(proves_no_common_point({hs(1, 0, 0, 0), hs(-1, 0, 0, 0)}));        // x < 0 and x > 0
  CHECK_FALSE(proves_no_common_point({hs(1, 0, 0, 1), hs(-1, 0, 0, 0)}));  // 0 < x < 1
  CHECK(proves_no_common_point({hs(2, 0, 0, 1), hs(-3, 0, 0, -2)}));       // x < 1/2 and x > 2/3
  CHECK_FALSE(proves_no_common_point({hs(1, 0, 0, 0), hs(0, 1, 0, 0)}));   // a quadrant
  // Three coplanar normals around the origin: x < 0, y < 0, x + y > 0.
  CHECK(proves_no_common_point({hs(1, 0, 0, 0), hs(0, 1, 0, 0), hs(-1, -1, 0, 0)}));
  CHECK_FALSE(proves_no_common_point({hs(1, 0, 0, 1), hs(0, 1, 0, 1), hs(-1, -1, 0, 0)}));
  // The outer sides of the four faces of a tetrahedron, and the apex of a closed cone.
  CHECK(proves_no_common_point({hs(-1, 0, 0, 0), hs(0, -1, 0, 0), hs(0, 0, -1, 0), hs(1, 1, 1, -1)}));
  CHECK_FALSE(proves_no_common_point({hs(-1, 0, 0, 0), hs(0, -1, 0, 0), hs(0, 0, -1, 0), hs(1, 1, 1, 1)}));
  CHECK(proves_no_common_point({hs(1, 0, 0, 0), hs(0, 1, 0, 0), hs(0, 0, 1, 0), hs(-1, -1, -1, 0)}));
  // Not proved (not claimed): one half-space, five, or normals with a two-dimensional nullspace.
  CHECK_FALSE(proves_no_common_point({hs(1, 0, 0, -1)}));
  CHECK_FALSE(proves_no_common_point(
      {hs(1, 0, 0, 0), hs(-1, 0, 0, 0), hs(0, 1, 0, 0), hs(0, -1, 0, 0), hs(0, 0, 1, 0)}));
}

TEST_CASE("Motzkin certificates: never with a common point, always for positively spanning normals") {
  std::mt19937_64 rng(7);
  int with_point = 0, closed = 0, proved = 0;
  for (int rep = 0; rep < 2000; ++rep) {
    const std::array<Integer, 3> p = {Integer(small(rng, 20)), Integer(small(rng, 20)),
                                      Integer(small(rng, 20))};
    const std::size_t k = 2 + rep % 3;
    std::vector<InnerHalfSpace> h(k);
    if (rep % 2 == 0) {
      // p strictly inside every half-space: no certificate may exist.
      for (auto& s : h) {
        s.u = random_normal(rng);
        s.w = dot(s.u, p) + 1 + Integer(long(rng() % 25));
      }
      ++with_point;
      CHECK_FALSE(proves_no_common_point(h));
      continue;
    }
    // The last normal is minus a positive combination of the others (in their span, so 0 lies in
    // the relative interior of their positive hull), offsets at or below p's: no common point.
    std::vector<Integer> y(k);
    std::array<Integer, 3> last{0, 0, 0};
    for (std::size_t i = 0; i + 1 < k; ++i) {
      h[i].u =
          k == 3 && i == 1 ? std::array<Integer, 3>{h[0].u[1], -h[0].u[0], h[0].u[2]} : random_normal(rng);
      y[i] = 1 + rng() % 5;
      for (int c = 0; c < 3; ++c) last[std::size_t(c)] -= y[i] * h[i].u[std::size_t(c)];
    }
    if (sgn(last[0]) == 0 && sgn(last[1]) == 0 && sgn(last[2]) == 0) continue;
    h[k - 1].u = last;
    for (auto& s : h) s.w = dot(s.u, p) - Integer(long(rng() % 3));
    ++closed;
    proved += proves_no_common_point(h);
  }
  CHECK(with_point == 1000);
  MESSAGE("closed configurations " << closed << ", proved " << proved);
  CHECK(proved >= closed * 9 / 10);  // a certificate is missed only on degenerate normals
}
