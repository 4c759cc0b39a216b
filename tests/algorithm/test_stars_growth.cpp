// The bookkeeping of a growing star (algorithm/local/stars_growth.hpp): the shelling test and
// the local ball test, each against topology::check_ball on the same tets.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "algorithm/local/stars_growth.hpp"
#include "algorithm/local/stars_topology.hpp"
#include "test_stars_util.hpp"

using namespace cmx;
using namespace cmx::algorithm;
using cmx::test::identity_map;
using cmx::test::InitialMap;

namespace {

struct Fixture {
  InitialMap map = identity_map(5, 1, 0.0);  // a plain grid: cell (i, j, k) is [i, i+1] x ...
  topology::TetAdjacency adjacency = topology::tet_adjacency(map.mesh());
  std::vector<std::array<double, 3>> approx;
  std::vector<std::int32_t> owner = std::vector<std::int32_t>(map.mesh().tet_capacity(), stars::no_star);
  stars::GrowingStar star{map.mesh(), adjacency, approx, owner};

  Fixture() {
    for (const HPoint& p : map.target) approx.push_back(p.approx());
    star.start(0);
  }
  // The six tets of cell (i, j, k).
  std::vector<topology::TetId> cell(int i, int j, int k) const {
    std::vector<topology::TetId> out;
    for (topology::TetId t : map.mesh().live_tets()) {
      double c[3] = {0, 0, 0};
      for (topology::VertexId v : map.mesh().tet(t))
        for (int a = 0; a < 3; ++a) c[a] += to_double(cmx::test::coordinate(map, v, a)) / 4;
      if (int(c[0]) == i && int(c[1]) == j && int(c[2]) == k) out.push_back(t);
    }
    return out;
  }
  void add_cell(int i, int j, int k) {
    for (topology::TetId t : cell(i, j, k)) star.add(t);
  }
  // The local test's verdict on the whole star: no pinch at any vertex, and a sphere boundary.
  bool locally_ball() const {
    for (topology::TetId t : star.tets())
      for (topology::VertexId v : map.mesh().tet(t))
        if (star.pinch_at(v)) return false;
    return star.boundary_is_sphere();
  }
  topology::VertexId vertex(int i, int j, int k) const { return topology::VertexId(i + 6 * (j + 6 * k)); }
};

}  // namespace

TEST_CASE("a growing star keeps its boundary faces and finds pinches at a vertex and at an edge") {
  Fixture f;
  REQUIRE(f.cell(1, 1, 1).size() == 6);
  f.add_cell(1, 1, 1);
  CHECK(f.star.boundary().size() == 12);  // a cube: two triangles per side
  CHECK(f.locally_ball());
  // A second cell touching the first at one vertex only.
  f.add_cell(2, 2, 2);
  const std::optional<topology::Edge> at_vertex = f.star.pinch_at(f.vertex(2, 2, 2));
  REQUIRE(at_vertex);
  CHECK((*at_vertex)[1] == f.vertex(2, 2, 2));
  CHECK_FALSE(f.locally_ball());
  CHECK_FALSE(stars::check_ball_of(f.map.mesh(), f.star.tets()).ok);

  Fixture g;
  g.add_cell(1, 1, 1);
  g.add_cell(2, 2, 1);  // along the edge x = y = 2, z in [1, 2]
  const std::optional<topology::Edge> at_edge = g.star.pinch_at(g.vertex(2, 2, 1));
  REQUIRE(at_edge);
  CHECK((*at_edge)[0] == g.vertex(2, 2, 1));
  CHECK((*at_edge)[1] == g.vertex(2, 2, 2));
  // Filling the corner between them makes it a ball.
  g.add_cell(2, 1, 1);
  CHECK(g.locally_ball());
  CHECK(stars::check_ball_of(g.map.mesh(), g.star.tets()).ok);
  CHECK(g.star.boundary().size() == 2 * 14);  // an L of three cubes has 14 unit squares of boundary
}

TEST_CASE("a ring of cells is a manifold everywhere but its boundary is no sphere") {
  Fixture f;
  for (int i = 1; i <= 3; ++i)
    for (int j = 1; j <= 3; ++j)
      if (i != 2 || j != 2) f.add_cell(i, j, 1);
  for (topology::TetId t : f.star.tets())
    for (topology::VertexId v : f.map.mesh().tet(t)) CHECK_FALSE(f.star.pinch_at(v));
  CHECK_FALSE(f.star.boundary_is_sphere());
  CHECK_FALSE(stars::check_ball_of(f.map.mesh(), f.star.tets()).ok);
  f.add_cell(2, 2, 1);
  CHECK(f.star.boundary_is_sphere());
}

TEST_CASE("the local ball test and the shelling test agree with check_ball on random growth") {
  // Random tets next to the star, with no regard for topology: after each, the local test
  // (every vertex, and the boundary) must say what check_ball says; and a tet that passes the
  // shelling test must keep a ball a ball.
  std::size_t balls = 0, not_balls = 0, shellings = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    Fixture f;
    std::mt19937_64 rng(seed);
    f.star.add(f.cell(2, 2, 2)[0]);
    for (int step = 0; step < 120; ++step) {
      std::vector<topology::TetId> next;
      for (const stars::FaceRef& b : f.star.boundary())
        if (f.star.behind(b) != topology::invalid_index && !f.star.contains(f.star.behind(b))) next.push_back(f.star.behind(b));
      std::sort(next.begin(), next.end());
      next.erase(std::unique(next.begin(), next.end()), next.end());
      REQUIRE_FALSE(next.empty());
      const topology::TetId t = next[rng() % next.size()];
      const bool was_ball = stars::check_ball_of(f.map.mesh(), f.star.tets()).ok;
      const bool shells = f.star.extends_ball(t);
      f.star.add(t);
      const bool is_ball = stars::check_ball_of(f.map.mesh(), f.star.tets()).ok;
      CAPTURE(seed);
      CAPTURE(step);
      CHECK(f.locally_ball() == is_ball);
      if (was_ball && shells) {
        CHECK(is_ball);
        ++shellings;
      }
      (is_ball ? balls : not_balls) += 1;
    }
  }
  // Both verdicts occurred, and the shelling test was used.
  CHECK(balls > 50);
  CHECK(not_balls > 50);
  CHECK(shellings > 50);
}
