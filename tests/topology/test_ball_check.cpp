// Ball-topology validation: one case per failure kind, each naming the offending simplex.
#include <doctest/doctest.h>

#include <algorithm>

#include "topology/ball_check.hpp"
#include "topology/generators.hpp"
#include "topo_test_util.hpp"

using namespace cmx::topology;
using cmx::topology::test::all_cells_but;

namespace {
BallVerdict verdict_of(std::size_t n, std::vector<TetIndices> tets) { return check_ball(TetMesh(n, tets)); }
bool simplex_is(const BallVerdict& v, std::vector<std::uint32_t> s) {
  std::vector<std::uint32_t> a = indices_of(v.simplex);
  std::sort(a.begin(), a.end());
  std::sort(s.begin(), s.end());
  return a == s;
}
}  // namespace

TEST_CASE("ball: valid balls pass") {
  CHECK(check_ball(single_tet()).ok);
  CHECK(check_ball(two_tets_sharing_face()).ok);
  CHECK(check_ball(cmx::topology::test::hex_bipyramid_cone()).ok);
  CHECK(check_ball(grid_complex(4, 3, 2).mesh).ok);
  // An L-shaped voxel ball.
  CHECK(check_ball(voxel_complex(2, 2, 1, all_cells_but(2, 2, 1, {{1, 1, 0}})).mesh).ok);
}

TEST_CASE("ball: empty mesh") { CHECK(check_ball(TetMesh(3)).failure == BallFailure::empty); }

TEST_CASE("ball: degenerate tet (repeated vertex)") {
  const BallVerdict v = verdict_of(4, {{0, 1, 1, 2}});
  CHECK(v.failure == BallFailure::degenerate_tet);
  CHECK(v.message.find("repeats vertex 1") != std::string::npos);
}

TEST_CASE("ball: isolated vertex") {
  const BallVerdict v = verdict_of(5, {{0, 1, 2, 3}});
  CHECK(v.failure == BallFailure::isolated_vertex);
  CHECK(simplex_is(v, {4}));
}

TEST_CASE("ball: duplicate tet (same or flipped orientation)") {
  BallVerdict v = verdict_of(4, {{0, 1, 2, 3}, {0, 1, 2, 3}});
  CHECK(v.failure == BallFailure::duplicate_tet);
  CHECK(simplex_is(v, {0, 1, 2, 3}));
  v = verdict_of(5, {{0, 1, 2, 3}, {1, 2, 3, 4}, {1, 0, 2, 3}});
  CHECK(v.failure == BallFailure::duplicate_tet);
  CHECK(simplex_is(v, {0, 1, 2, 3}));
}

TEST_CASE("ball: face in three tets") {
  const BallVerdict v = verdict_of(6, {{0, 1, 2, 3}, {1, 2, 3, 4}, {1, 3, 2, 5}});
  CHECK(v.failure == BallFailure::face_in_three_or_more_tets);
  CHECK(simplex_is(v, {1, 2, 3}));
  CHECK(v.message.find("3 tets") != std::string::npos);
}

TEST_CASE("ball: inconsistent orientation") {
  const BallVerdict v = verdict_of(5, {{0, 1, 2, 3}, {1, 3, 2, 4}});
  CHECK(v.failure == BallFailure::inconsistent_orientation);
  CHECK(simplex_is(v, {1, 2, 3}));
  // Flipping one tet of a grid is found too.
  GridComplex g = grid_complex(2, 2, 2);
  Tet x = g.mesh.tet(TetId{13});
  std::swap(x[0], x[1]);
  g.mesh.set_tet(TetId{13}, x);
  CHECK(check_ball(g.mesh).failure == BallFailure::inconsistent_orientation);
}

TEST_CASE("ball: disconnected") {
  const BallVerdict v = verdict_of(8, {{0, 1, 2, 3}, {4, 5, 6, 7}});
  CHECK(v.failure == BallFailure::disconnected);
  CHECK(v.simplex.size() == 1);
  CHECK(v.simplex[0] >= 4);
}

TEST_CASE("ball: non-manifold edge (two tets sharing only an edge)") {
  const BallVerdict v = verdict_of(6, {{0, 1, 2, 3}, {0, 1, 4, 5}});
  CHECK(v.failure == BallFailure::non_manifold_edge);
  CHECK(simplex_is(v, {0, 1}));
  // Two voxel cubes sharing only an edge.
  const GridComplex g = voxel_complex(2, 2, 1, all_cells_but(2, 2, 1, {{1, 0, 0}, {0, 1, 0}}));
  const BallVerdict w = check_ball(g.mesh);
  CHECK(w.failure == BallFailure::non_manifold_edge);
  REQUIRE(w.simplex.size() == 2);
  for (VertexId a : w.simplex) CHECK((g.coords[a][0] == 1 && g.coords[a][1] == 1));
}

TEST_CASE("ball: non-manifold vertex (two balls touching at a vertex)") {
  const BallVerdict v = verdict_of(7, {{0, 1, 2, 3}, {0, 4, 5, 6}});
  CHECK(v.failure == BallFailure::non_manifold_vertex);
  CHECK(simplex_is(v, {0}));
  const GridComplex g = voxel_complex(2, 2, 2, all_cells_but(2, 2, 2, {{1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                                                                       {0, 0, 1}, {1, 0, 1}, {0, 1, 1}}));
  const BallVerdict w = check_ball(g.mesh);
  CHECK(w.failure == BallFailure::non_manifold_vertex);
  REQUIRE(w.simplex.size() == 1);
  CHECK(g.coords[w.simplex[0]] == std::array<std::int32_t, 3>{1, 1, 1});
}

TEST_CASE("ball: vertex link an annulus") {
  // Six of the eight cells around the center point, missing two opposite ones: the center's
  // star is connected, every edge is manifold, but its link is an annulus.
  const GridComplex g = voxel_complex(2, 2, 2, all_cells_but(2, 2, 2, {{0, 1, 0}, {1, 0, 1}}));
  const BallVerdict w = check_ball(g.mesh);
  CHECK(w.failure == BallFailure::vertex_link_not_disc_or_sphere);
  REQUIRE(w.simplex.size() == 1);
  CHECK(g.coords[w.simplex[0]] == std::array<std::int32_t, 3>{1, 1, 1});
}

TEST_CASE("ball: solid torus has Euler characteristic 0") {
  const GridComplex g = voxel_complex(3, 3, 1, all_cells_but(3, 3, 1, {{1, 1, 0}}));
  const BallVerdict w = check_ball(g.mesh);
  CHECK(w.failure == BallFailure::euler_characteristic);
  CHECK(w.euler == 0);
  CHECK(w.message.find("= 0") != std::string::npos);
}

TEST_CASE("ball: solid torus with a cavity has chi 1 but its boundary is not a sphere") {
  std::vector<std::array<std::uint32_t, 3>> removed{{1, 1, 1}};
  for (std::uint32_t k = 0; k < 3; ++k) removed.push_back({3, 3, k});
  const GridComplex g = voxel_complex(7, 7, 3, all_cells_but(7, 7, 3, removed));
  const BallVerdict w = check_ball(g.mesh);
  CHECK(w.failure == BallFailure::boundary_not_sphere);
  CHECK(w.euler == 1);
  CHECK(w.message.find("2 components") != std::string::npos);
  // A ball with a cavity: boundary of two spheres, chi 2, caught by the Euler check.
  const GridComplex h = voxel_complex(3, 3, 3, all_cells_but(3, 3, 3, {{1, 1, 1}}));
  CHECK(check_ball(h.mesh).failure == BallFailure::euler_characteristic);
}

TEST_CASE("ball: cost is linear enough for 1e5+ tets") {
  const GridComplex g = grid_complex(30, 30, 30);  // 162000 tets
  const BallVerdict v = check_ball(g.mesh);
  CHECK(v.ok);
  CHECK(v.tets == 162000);
  CHECK(v.boundary_faces == 6 * 2 * 30 * 30);
}
