// Star growth (algorithm/local/stars.hpp) on the project's own domains with deliberately broken
// initial maps: every result must satisfy (a) to (d), checked by check_stars and again here.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "algorithm/local/stars.hpp"
#include "algorithm/map.hpp"
#include "algorithm/run_control.hpp"
#include "map_test_util.hpp"
#include "test_stars_util.hpp"

using namespace cmx;
using namespace cmx::algorithm;
using namespace cmx::generators;
using cmx::test::check_independently;
using cmx::test::count_defects;
using cmx::test::identity_map;
using cmx::test::InitialMap;

namespace {

StarSet grow(const InitialMap& m, StarOptions options = {}) {
  options.max_share = 1.0;
  return grow_stars(m.mesh(), m.target, m.boundary, options);
}

// Interior vertices of the layer next to the face x = cells, near the middle of that face, moved
// `by` along x: beyond the domain's boundary for by > 1.
void push_out(InitialMap& m, std::uint32_t cells, double by) {
  const double mid = cells / 2.0;
  cmx::test::move_interior(
      m,
      [&](topology::VertexId v) {
        return to_double(cmx::test::coordinate(m, v, 0)) > cells - 1.5 &&
               std::fabs(to_double(cmx::test::coordinate(m, v, 1)) - mid) < 1.6 &&
               std::fabs(to_double(cmx::test::coordinate(m, v, 2)) - mid) < 1.6;
      },
      [&](topology::VertexId) { return std::array<Rational, 3>{rational_from_double(by), Rational(0), Rational(0)}; });
}

}  // namespace

TEST_CASE("an initial map with every tet positive has no star") {
  const InitialMap m = identity_map(4);
  const StarSet s = grow_stars(m.mesh(), m.target, m.boundary);
  REQUIRE(s.ok);
  CHECK(s.stars.empty());
  CHECK(s.inverted == 0);
  CHECK(s.flat == 0);
  CHECK(s.tets_in_stars == 0);
  CHECK(s.states.size() == m.mesh().tet_capacity());
  CHECK(check_stars(m.mesh(), m.target, s) == "");
}

TEST_CASE("stars around random interior displacements satisfy the star conditions") {
  std::size_t repairs = 0, merges = 0, exact_lps = 0;
  for (std::uint64_t seed : {1u, 2u, 3u, 4u}) {
    for (double share : {0.1, 0.3, 1.0}) {
      CAPTURE(seed);
      CAPTURE(share);
      InitialMap m = identity_map(6, seed);
      cmx::test::displace_randomly(m, seed, share, 0.9);
      const std::size_t defects = count_defects(m);
      REQUIRE(defects > 0);
      const StarSet s = grow(m);
      check_independently(m, s);
      CHECK(s.inverted + s.flat == defects);
      CHECK(!s.stars.empty());
      repairs += s.repairs;
      merges += s.merges;
      exact_lps += s.exact_lps;
    }
  }
  // The paths beyond plain shelling steps ran: repairs of pinches, merges, exact kernel LPs.
  CHECK(repairs > 0);
  CHECK(merges > 0);
  MESSAGE(repairs << " repairs, " << merges << " merges, " << exact_lps << " exact LPs");
}

TEST_CASE("stars around a folded region satisfy the star conditions") {
  for (double shift : {0.0, 0.4, -0.7}) {
    CAPTURE(shift);
    InitialMap m = identity_map(7);
    cmx::test::fold(m, {3.5, 3.5, 3.5}, 1.6, shift);
    REQUIRE(count_defects(m) > 0);
    const StarSet s = grow(m);
    check_independently(m, s);
    // A fold of a small region stays local: well below the whole mesh.
    CHECK(s.tets_in_stars < m.mesh().num_tets() / 2);
  }
}

TEST_CASE("stars around a region mapped outside the domain keep the domain boundary") {
  InitialMap m = identity_map(6);
  push_out(m, 6, 2.5);
  REQUIRE(count_defects(m) > 0);
  const StarSet s = grow(m);
  check_independently(m, s);
  // The stars reach the domain boundary there: some boundary triangle of a star lies on it.
  const std::vector<topology::BoundaryFace> outer = topology::boundary_faces(m.mesh());
  std::size_t on_domain_boundary = 0;
  for (const Star& star : s.stars)
    for (const topology::Triangle& f : star.boundary)
      for (const topology::BoundaryFace& b : outer) on_domain_boundary += topology::same_orientation(f, b.face) ? 1 : 0;
  CHECK(on_domain_boundary > 0);
}

TEST_CASE("flat tets are defects and get stars like inverted ones") {
  InitialMap m = identity_map(5);
  // An interior vertex moved onto the plane of the opposite face of one of its tets.
  const topology::VertexId v{3 * 36 + 3 * 6 + 3};  // grid vertex (3, 3, 3) of a 5x5x5 grid
  REQUIRE_FALSE(m.boundary[v]);
  const topology::TetId t = m.mesh().tets_of(v)[0];
  const topology::Triangle f = topology::tet_face(m.mesh().tet(t), topology::local_index(m.mesh().tet(t), v));
  const HPoint pts[3] = {m.target[f[0]], m.target[f[1]], m.target[f[2]]};
  const Rational third[3] = {Rational(1, 3), Rational(1, 3), Rational(1, 3)};
  m.target[v] = convex_combination(pts, third, 3);
  const StarSet s = grow(m);
  CHECK(s.flat >= 1);
  CHECK(s.states[t] == TetState::flat);
  check_independently(m, s);
}

TEST_CASE("two defects close together end in one star or in two tet-disjoint stars") {
  // Two folds at growing distance: at each, the stars are valid; close together they merge.
  bool merged = false, apart = false;
  for (double gap : {1.0, 2.0, 3.0, 4.0, 5.0}) {
    CAPTURE(gap);
    InitialMap m = identity_map(9);
    cmx::test::fold(m, {2.5, 4.5, 4.5}, 0.6, 0.3);
    cmx::test::fold(m, {2.5 + gap, 4.5, 4.5}, 0.6, 0.3);
    const StarSet s = grow(m);
    check_independently(m, s);
    merged = merged || s.merges > 0 || s.stars.size() == 1;
    apart = apart || s.stars.size() >= 2;
  }
  CHECK(merged);
  CHECK(apart);
}

TEST_CASE("star growth is deterministic") {
  InitialMap m = identity_map(6, 7);
  cmx::test::displace_randomly(m, 11, 0.4, 0.9);
  const StarSet a = grow(m);
  // The same problem again, from a mesh built anew.
  InitialMap again = identity_map(6, 7);
  again.target = m.target;
  const StarSet b = grow(again);
  REQUIRE(a.ok);
  REQUIRE(b.ok);
  REQUIRE(a.stars.size() == b.stars.size());
  for (std::size_t i = 0; i < a.stars.size(); ++i) {
    CHECK(a.stars[i].tets == b.stars[i].tets);
    CHECK(a.stars[i].boundary == b.stars[i].boundary);
    CHECK(a.stars[i].interior == b.stars[i].interior);
  }
  CHECK(a.kernel_tests == b.kernel_tests);
  CHECK(a.growth_steps == b.growth_steps);
}

TEST_CASE("star growth stops at the share limit and when the run control says stop") {
  InitialMap m = identity_map(6, 3);
  cmx::test::displace_randomly(m, 5, 1.0, 0.9);
  const StarSet all = grow(m);
  REQUIRE(all.ok);
  REQUIRE(all.tets_in_stars > 20);

  StarOptions tight;
  tight.max_share = double(all.tets_in_stars / 2) / double(m.mesh().num_tets());
  const StarSet cut = grow_stars(m.mesh(), m.target, m.boundary, tight);
  CHECK_FALSE(cut.ok);
  CHECK(cut.message.find("would hold more than") != std::string::npos);
  CHECK(cut.stars.empty());
  CHECK(double(cut.tets_in_stars) > tight.max_share * double(m.mesh().num_tets()));
  CHECK(check_stars(m.mesh(), m.target, cut) != "");

  std::size_t polls = 0;
  MapOptions map_options;
  map_options.stop = [&](std::string_view phase) {
    CHECK(phase == "stars");
    return ++polls > 5;
  };
  RunControl control(map_options, RunControl::Clock::now());
  StarOptions stopped;
  stopped.max_share = 1.0;
  stopped.control = &control;
  const StarSet s = grow_stars(m.mesh(), m.target, m.boundary, stopped);
  CHECK_FALSE(s.ok);
  CHECK(s.message == "stopped while growing stars");
  CHECK(polls == 6);
}

TEST_CASE("stars in a perturbed exact map of the global method") {
  // Targets with many bits: the map of a small grid onto a sphere, interior vertices displaced.
  const GeneratedDomain d = perturbed_grid(3, 3, 3, 2);
  const MapResult r = cmx::test::map_checked(cmx::test::problem_from(d, "sphere"));
  InitialMap m;
  m.domain.mesh = topology::TetMesh(r.target.size(), r.tets);
  for (const HPoint& p : r.source) m.domain.positions.push_back({p.coordinate(0), p.coordinate(1), p.coordinate(2)});
  m.target = r.target;
  m.boundary = topology::boundary_vertex_flags(m.domain.mesh);
  CHECK(count_defects(m) == 0);
  std::size_t moved = 0;
  cmx::test::move_interior(
      m, [&](topology::VertexId) { return moved++ % 3 == 0; },
      [&](topology::VertexId v) {
        // A half turn about the z axis for every third interior vertex: folds across the axis.
        return std::array<Rational, 3>{-2 * m.target[v].coordinate(0), -2 * m.target[v].coordinate(1), Rational(0)};
      });
  REQUIRE(count_defects(m) > 0);
  check_independently(m, grow(m));
}

TEST_CASE("without free_defects the stars still satisfy the star conditions, but leave defects fixed") {
  InitialMap m = identity_map(7, 2);
  cmx::test::displace_randomly(m, 9, 0.3, 0.9);
  StarOptions plain;
  plain.free_defects = false;
  const StarSet s = grow(m, plain);
  REQUIRE(s.ok);
  CHECK(check_stars(m.mesh(), m.target, s) == "");
  // Some defect then has all four vertices on its star's boundary: only a split could repair it.
  std::size_t fixed = 0;
  for (const Star& star : s.stars) {
    CHECK(cmx::test::star_is_ball(m.mesh(), star));
    for (topology::TetId t : star.tets) {
      const topology::Tet& x = m.mesh().tet(t);
      const bool free = std::any_of(x.begin(), x.end(), [&](topology::VertexId v) {
        return std::binary_search(star.interior.begin(), star.interior.end(), v);
      });
      fixed += cmx::test::defect(m, t) && !free ? 1 : 0;
    }
  }
  CHECK(fixed > 0);
  check_independently(m, grow(m));
}

TEST_CASE("star growth skips dead tet slots") {
  InitialMap m = identity_map(6);
  cmx::test::fold(m, {3, 3, 3}, 1.1, 0.3);
  // Every tet of the fold's centre vertex moved to a new slot: their old slots are tombstones.
  const topology::VertexId centre{3 + 7 * (3 + 7 * 3)};
  const std::vector<topology::TetId> around(m.mesh().tets_of(centre).begin(), m.mesh().tets_of(centre).end());
  for (topology::TetId t : around) {
    const topology::Tet x = m.mesh().tet(t);
    m.domain.mesh.remove_tet(t);
    REQUIRE(m.domain.mesh.add_tet(x) != topology::invalid_index);
  }
  REQUIRE(m.mesh().tet_capacity() > m.mesh().num_tets());
  const StarSet s = grow(m);
  check_independently(m, s);
  for (topology::TetId t : around) CHECK(s.states[t] == TetState::positive);
  for (const Star& star : s.stars)
    for (topology::TetId t : star.tets) CHECK(m.mesh().is_alive(t));
}

TEST_CASE("grow_stars refuses targets and flags of the wrong size") {
  const InitialMap m = identity_map(2);
  std::vector<HPoint> short_target(m.target.begin(), m.target.end() - 1);
  CHECK_THROWS_AS((void)grow_stars(m.mesh(), short_target, m.boundary), std::invalid_argument);
  std::vector<char> short_flags(m.boundary.begin(), m.boundary.end() - 1);
  CHECK_THROWS_AS((void)grow_stars(m.mesh(), m.target, short_flags), std::invalid_argument);
}
