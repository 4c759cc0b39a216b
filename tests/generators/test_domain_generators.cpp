// The project's own test domains: each is a ball, every tet is strictly positive in exact
// arithmetic, the perturbation really moves vertices (boundary ones too), and the same arguments
// give the same mesh.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include "generators/domain_generators.hpp"
#include "arith/rational.hpp"
#include "kernel/homogeneous_point.hpp"
#include "kernel/orient.hpp"
#include "topology/ball_check.hpp"
#include "topology/complex_queries.hpp"
#include "topology/nobuenoss.hpp"

using cmx::Rational;
using cmx::generators::GeneratedDomain;
namespace alg = cmx::generators;

namespace {

bool all_tets_positive(const GeneratedDomain& d) {
  std::vector<cmx::HPoint> p;
  for (const auto& x : d.positions) p.emplace_back(x[0], x[1], x[2]);
  for (auto t : d.mesh.live_tets()) {
    const auto& tet = d.mesh.tet(t);
    if (cmx::orient3d(p[tet[0]], p[tet[1]], p[tet[2]], p[tet[3]],
                      {cmx::FilterPolicy{cmx::FilterPolicy::Kind::exact}, nullptr}) != cmx::Sign::positive)
      return false;
  }
  return true;
}

bool is_integer_point(const std::array<Rational, 3>& p) {
  for (const auto& x : p)
    if (x.get_den() != 1) return false;
  return true;
}

struct MovedCounts {
  std::size_t interior = 0, boundary = 0, interior_total = 0, boundary_total = 0;
};
MovedCounts moved_vertices(const GeneratedDomain& d) {
  const auto on_boundary = cmx::topology::boundary_vertex_flags(d.mesh);
  MovedCounts c;
  for (std::size_t v = 0; v < d.positions.size(); ++v) {
    const bool moved = !is_integer_point(d.positions[v]);
    if (on_boundary[v]) c.boundary += moved, ++c.boundary_total;
    else c.interior += moved, ++c.interior_total;
  }
  return c;
}

void check_valid(const GeneratedDomain& d, bool doubles_exact = true) {
  REQUIRE(d.positions.size() == d.mesh.num_vertices());
  const auto verdict = cmx::topology::check_ball(d.mesh);
  INFO(verdict.message);
  CHECK(verdict.ok);
  CHECK(all_tets_positive(d));
  if (!doubles_exact) return;
  // The double positions are the exact ones (the offsets are short dyadics).
  const auto doubles = d.double_positions();
  for (std::size_t v = 0; v < doubles.size(); ++v)
    for (int a = 0; a < 3; ++a) REQUIRE(cmx::rational_from_double(doubles[v][std::size_t(a)]) == d.positions[v][std::size_t(a)]);
}

bool same(const GeneratedDomain& a, const GeneratedDomain& b) {
  if (a.positions != b.positions || a.mesh.num_tets() != b.mesh.num_tets()) return false;
  for (auto t : a.mesh.live_tets())
    if (a.mesh.tet(t) != b.mesh.tet(t)) return false;
  return true;
}

}  // namespace

TEST_CASE("perturbed_grid: a positive ball with interior and boundary vertices jittered, deterministically") {
  struct Size {
    std::uint32_t nx, ny, nz;
  };
  for (const Size s : {Size{1, 1, 1}, Size{2, 2, 2}, Size{4, 3, 2}, Size{5, 5, 5}}) {
    CAPTURE(s.nx);
    CAPTURE(s.ny);
    CAPTURE(s.nz);
    const auto plain = alg::perturbed_grid(s.nx, s.ny, s.nz, 7, 0.0);
    check_valid(plain);
    CHECK(plain.mesh.num_tets() == 6u * s.nx * s.ny * s.nz);
    CHECK(moved_vertices(plain).boundary == 0);
    CHECK(moved_vertices(plain).interior == 0);

    const auto jittered = alg::perturbed_grid(s.nx, s.ny, s.nz, 7);
    check_valid(jittered);
    const auto moved = moved_vertices(jittered);
    // A quarter-cell jitter keeps most Freudenthal tets positive: most vertices move.
    CHECK(2 * moved.boundary > moved.boundary_total);
    CHECK(2 * moved.interior >= moved.interior_total);
    CHECK(same(jittered, alg::perturbed_grid(s.nx, s.ny, s.nz, 7)));
    CHECK_FALSE(same(jittered, alg::perturbed_grid(s.nx, s.ny, s.nz, 8)));
  }
}

TEST_CASE("perturbed_grid: a large amplitude rejects offsets but stays positive") {
  const auto d = alg::perturbed_grid(4, 4, 4, 99, 0.875);
  check_valid(d);
  const auto moved = moved_vertices(d);
  CHECK(moved.boundary + moved.interior < d.positions.size());  // some offsets were refused
  CHECK(moved.boundary + moved.interior > 0);
  // An amplitude with a long mantissa: exact rational positions that are not all doubles.
  const auto long_mantissa = alg::perturbed_grid(3, 3, 3, 99, 0.1);
  check_valid(long_mantissa, false);
  const auto doubles = long_mantissa.double_positions();
  bool all_doubles = true;
  for (std::size_t v = 0; v < doubles.size(); ++v)
    for (std::size_t a = 0; a < 3; ++a)
      all_doubles = all_doubles && cmx::rational_from_double(doubles[v][a]) == long_mantissa.positions[v][a];
  CHECK_FALSE(all_doubles);
}

TEST_CASE("voxel_ball: a thick, centred ball for every radius") {
  for (std::uint32_t r = 1; r <= 9; ++r) {
    CAPTURE(r);
    const auto plain = alg::voxel_ball(r, 3, 0.0);
    check_valid(plain);
    // Centred: the unperturbed vertex set is symmetric under p -> -p.
    Rational sum[3] = {0, 0, 0};
    for (const auto& p : plain.positions)
      for (int a = 0; a < 3; ++a) sum[a] += p[std::size_t(a)];
    CHECK(sum[0] == 0);
    CHECK(sum[1] == 0);
    CHECK(sum[2] == 0);
    const auto jittered = alg::voxel_ball(r, 3);
    check_valid(jittered);
    CHECK(same(jittered, alg::voxel_ball(r, 3)));
    if (r >= 2) {
      const auto moved = moved_vertices(jittered);
      CHECK(moved.interior_total > 0);  // thick: interior vertices exist
      CHECK(2 * moved.boundary > moved.boundary_total);
    }
  }
  // The cells kept are those whose centre is inside the sphere: radius 1 keeps the 8 cells
  // around the centre (centres at distance sqrt(3)/2), radius 2 keeps 32 of 64.
  CHECK(alg::voxel_ball(1, 0, 0.0).mesh.num_tets() == 6 * 8);
  CHECK(alg::voxel_ball(2, 0, 0.0).mesh.num_tets() == 6 * 32);
}

TEST_CASE("thin_slab: one layer has no interior vertex, two layers have few") {
  for (std::uint32_t layers : {1u, 2u}) {
    CAPTURE(layers);
    const auto d = alg::thin_slab(7, 5, 11, layers);
    check_valid(d);
    CHECK(same(d, alg::thin_slab(7, 5, 11, layers)));
    const auto moved = moved_vertices(d);
    if (layers == 1) CHECK(moved.interior_total == 0);
    else CHECK(moved.interior_total == 6u * 4u);  // the inner (i, j, 1) vertices
    // Most tets touch the boundary.
    const auto on_boundary = cmx::topology::boundary_vertex_flags(d.mesh);
    std::size_t touching = 0;
    for (auto t : d.mesh.live_tets()) {
      bool any = false;
      for (auto v : d.mesh.tet(t)) any = any || on_boundary[v];
      touching += any;
    }
    CHECK(2 * touching > d.mesh.num_tets());
  }
}

TEST_CASE("domain generators reject bad arguments") {
  CHECK_THROWS_AS((void)alg::perturbed_grid(0, 1, 1, 1), std::invalid_argument);
  CHECK_THROWS_AS((void)alg::perturbed_grid(1, 1, 1, 1, -0.5), std::invalid_argument);
  CHECK_THROWS_AS((void)alg::perturbed_grid(1, 1, 1, 1, std::numeric_limits<double>::infinity()), std::invalid_argument);
  CHECK_THROWS_AS((void)alg::perturbed_grid(70000, 70000, 1, 1), std::invalid_argument);
  CHECK_THROWS_AS((void)alg::voxel_ball(0, 1), std::invalid_argument);
  CHECK_THROWS_AS((void)alg::thin_slab(3, 3, 1, 3), std::invalid_argument);
  CHECK_THROWS_AS((void)alg::thin_slab(3, 3, 1, 0), std::invalid_argument);
}

TEST_CASE("bings_house and knotted_hole: positive balls whose interior erodes to a NOBUENOSS") {
  const GeneratedDomain house = alg::bings_house(4, 2);
  CHECK(cmx::topology::check_ball(house.mesh).ok);
  std::vector<cmx::HPoint> p;
  for (const auto& x : house.positions) p.emplace_back(x[0], x[1], x[2]);
  std::size_t positive = 0;
  for (auto t : house.mesh.live_tets()) {
    const auto& tet = house.mesh.tet(t);
    positive += cmx::orient3d(p[tet[0]], p[tet[1]], p[tet[2]], p[tet[3]], cmx::PredicateContext::certain()) ==
                        cmx::Sign::positive
                    ? 1
                    : 0;
  }
  CHECK(positive == house.mesh.num_tets());
  CHECK(house.mesh.num_tets() == cmx::topology::bings_house_nobuenoss(4).mesh.num_tets());
  CHECK_THROWS_AS((void)alg::bings_house(5, 2), std::invalid_argument);
  CHECK_THROWS_AS((void)alg::bings_house(2, 2), std::invalid_argument);
  const GeneratedDomain knot = alg::knotted_hole(0, 0.0);
  CHECK(cmx::topology::check_ball(knot.mesh).ok);
  CHECK(knot.mesh.num_tets() == 59286);
  std::size_t integer = 0;
  for (const auto& x : knot.positions) integer += is_integer_point(x) ? 1 : 0;
  CHECK(integer == knot.positions.size());  // amplitude 0: the lattice itself
}

TEST_CASE("thin_fingers: a palm with bent fingers of W x W cells is a positive ball") {
  struct Size {
    std::uint32_t fingers, width, length;
  };
  for (const Size s : {Size{1, 2, 1}, Size{2, 2, 9}, Size{3, 3, 12}, Size{4, 2, 20}}) {
    CAPTURE(s.fingers);
    CAPTURE(s.width);
    CAPTURE(s.length);
    const GeneratedDomain plain = alg::thin_fingers(s.fingers, s.width, s.length, 0, 0.0);
    check_valid(plain);
    // The palm's (2F+1)W x 4W x 4W cells and F fingers of W x W x L, six tets each.
    const std::size_t w = s.width;
    const std::size_t cells = (2 * s.fingers + 1) * w * 4 * w * 4 * w + s.fingers * w * w * s.length;
    CHECK(plain.mesh.num_tets() == 6 * cells);
    // The tips: at height 4W + L, only finger columns (x within [W, 2FW]), each W cells wide,
    // shifted in y by the bend floor((L-1)^2 / 2L) from the base (both ways with two fingers).
    const Rational top(std::int64_t(4 * w + s.length));
    Rational lo_x(1000000), hi_x(-1000000), lo_y(1000000), hi_y(-1000000);
    std::size_t at_top = 0;
    for (const auto& p : plain.positions) {
      if (p[2] != top) continue;
      ++at_top;
      lo_x = std::min(lo_x, p[0]), hi_x = std::max(hi_x, p[0]);
      lo_y = std::min(lo_y, p[1]), hi_y = std::max(hi_y, p[1]);
    }
    CHECK(at_top == s.fingers * (w + 1) * (w + 1));
    CHECK(lo_x == Rational(std::int64_t(w)));
    CHECK(hi_x == Rational(std::int64_t(2 * s.fingers * w)));
    const std::int64_t bend = std::int64_t(s.length - 1) * (s.length - 1) / (2 * std::int64_t(s.length));
    const std::int64_t base = std::int64_t(s.length / 2 + 1 + 3 * w / 2);
    CHECK(hi_y == Rational(base + bend + std::int64_t(w)));
    CHECK(lo_y == Rational(s.fingers >= 2 ? base - bend : base + bend));
    const GeneratedDomain jittered = alg::thin_fingers(s.fingers, s.width, s.length, 5);
    check_valid(jittered);
    CHECK(same(jittered, alg::thin_fingers(s.fingers, s.width, s.length, 5)));
    CHECK(moved_vertices(jittered).interior_total > 0);
  }
  CHECK_THROWS_AS((void)alg::thin_fingers(0, 2, 5, 1), std::invalid_argument);
  CHECK_THROWS_AS((void)alg::thin_fingers(2, 1, 5, 1), std::invalid_argument);
  CHECK_THROWS_AS((void)alg::thin_fingers(2, 2, 0, 1), std::invalid_argument);
  CHECK_THROWS_AS((void)alg::thin_fingers(17, 2, 5, 1), std::invalid_argument);
}
