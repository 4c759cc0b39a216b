// Local edits keep incidences consistent, orientation consistent and balls balls.
#include <doctest/doctest.h>

#include <algorithm>
#include <iterator>
#include <random>

#include "topo_test_util.hpp"
#include "topology/ball_check.hpp"
#include "topology/complex_queries.hpp"
#include "topology/consistency.hpp"
#include "topology/generators.hpp"
#include "topology/mesh_edits.hpp"

using namespace cmx::topology;
using namespace cmx::topology::literals;

TEST_CASE("edge split: interior and boundary edges") {
  GridComplex g = grid_complex(2, 2, 2);
  TetMesh& m = g.mesh;
  const VertexId center{1 + 3 * (1 + 3 * 1)};
  const VertexId corner{0};
  // Interior edge center -> (2,2,2)? use a neighbor of the center.
  const VertexId far{2 + 3 * (2 + 3 * 2)};
  const std::size_t around = tets_around_edge(m, center, far).size();
  REQUIRE(around > 0);
  const std::size_t before = m.num_tets();
  const SplitResult r = split_edge(m, center, far);
  REQUIRE(r.ok);
  CHECK(r.new_vertex == 27);
  CHECK(r.modified.size() == around);
  CHECK(r.created.size() == around);
  CHECK(m.num_tets() == before + around);
  CHECK(m.tets_of(r.new_vertex).size() == 2 * around);
  CHECK(tets_around_edge(m, center, far).empty());
  CHECK(check_incidences(m).ok);
  CHECK(check_ball(m).ok);
  // A boundary edge.
  const SplitResult b = split_edge(m, corner, 1_v);
  REQUIRE(b.ok);
  CHECK(check_incidences(m).ok);
  CHECK(check_ball(m).ok);
  CHECK(boundary_vertex_flags(m)[b.new_vertex] == 1);
  // Not an edge.
  const SplitResult no = split_edge(m, corner, far);
  CHECK(!no.ok);
  CHECK(m.num_vertices() == 29);
}

TEST_CASE("face split 1->3: interior face (two tets) and boundary face (one tet)") {
  TetMesh m = two_tets_sharing_face();
  const SplitResult r = split_face(m, 1_v, 2_v, 3_v);
  REQUIRE(r.ok);
  CHECK(r.modified.size() == 2);
  CHECK(r.created.size() == 4);
  CHECK(m.num_tets() == 6);
  CHECK(check_incidences(m).ok);
  CHECK(check_ball(m).ok);
  CHECK(boundary_vertex_flags(m)[r.new_vertex] == 0);  // interior now
  const SplitResult s = split_face(m, 0_v, 1_v, 2_v);        // boundary face
  REQUIRE(s.ok);
  CHECK(s.created.size() == 2);
  CHECK(m.num_tets() == 8);
  CHECK(check_incidences(m).ok);
  CHECK(check_ball(m).ok);
  CHECK(!split_face(m, 0_v, 1_v, 4_v).ok);
}

TEST_CASE("random splits keep a consistent ball") {
  GridComplex g = grid_complex(3, 3, 2);
  TetMesh& m = g.mesh;
  std::mt19937_64 rng(3);
  for (int step = 0; step < 60; ++step) {
    const std::vector<TetId> live = m.live_tets();
    const Tet t = m.tet(live[rng() % live.size()]);
    const int i = static_cast<int>(rng() % 4), j = (i + 1 + static_cast<int>(rng() % 3)) % 4;
    SplitResult r;
    if (step % 2 == 0) {
      r = split_edge(m, t[i], t[j]);
    } else {
      const Triangle f = tet_face(t, i);
      r = split_face(m, f[0], f[1], f[2]);
    }
    REQUIRE(r.ok);
    const ConsistencyVerdict c = check_incidences(m);
    REQUIRE_MESSAGE(c.ok, c.message);
    const BallVerdict b = check_ball(m);
    REQUIRE_MESSAGE(b.ok, b.message);
  }
}

TEST_CASE("edge collapse: link condition refuses pinches, accepted collapses keep a ball") {
  // A single tet: collapsing any edge would flatten it; refused.
  TetMesh one = single_tet();
  CHECK(!satisfies_link_condition(one, 0_v, 1_v));
  CHECK(!collapse_edge(one, 0_v, 1_v).ok);
  CHECK(one.num_tets() == 1);
  // The diagonal of a single cube is an interior edge between two boundary vertices: the plain
  // link condition holds, the boundary rule refuses (the collapse would pinch the boundary).
  {
    const GridComplex cube = grid_complex(1, 1, 1);
    const SimplexSet la = vertex_link(cube.mesh, 0_v), lb = vertex_link(cube.mesh, 7_v),
                     lab = edge_link(cube.mesh, 0_v, 7_v);
    std::vector<VertexId> common;
    std::set_intersection(la.vertices.begin(), la.vertices.end(), lb.vertices.begin(), lb.vertices.end(),
                          std::back_inserter(common));
    CHECK(common == lab.vertices);
    CHECK(!satisfies_link_condition(cube.mesh, 0_v, 7_v));
  }
  // Undo an edge split by collapsing the new vertex.
  GridComplex g = grid_complex(2, 2, 2);
  const std::size_t tets = g.mesh.num_tets();
  const VertexId center{13}, far{26};
  const SplitResult s = split_edge(g.mesh, center, far);
  REQUIRE(s.ok);
  CHECK(satisfies_link_condition(g.mesh, center, s.new_vertex));
  const CollapseResult c = collapse_edge(g.mesh, center, s.new_vertex);
  REQUIRE(c.ok);
  CHECK(g.mesh.num_tets() == tets);
  CHECK(g.mesh.tets_of(s.new_vertex).empty());
  CHECK(check_incidences(g.mesh).ok);
  CHECK(tets_around_edge(g.mesh, center, far).size() == s.modified.size());
  // Soundness over all edges of a small grid: every accepted collapse leaves a ball (after
  // dropping the vertex left without tets), and some collapses are refused.
  const GridComplex h = grid_complex(2, 2, 1);
  std::size_t accepted = 0, refused = 0;
  for (VertexId a{0}; a < h.mesh.num_vertices(); ++a)
    for (VertexId b : vertex_neighbors(h.mesh, a)) {
      TetMesh m = h.mesh;
      const CollapseResult r = collapse_edge(m, a, b);
      if (!r.ok) {
        ++refused;
        CHECK(m.num_tets() == h.mesh.num_tets());
        continue;
      }
      ++accepted;
      REQUIRE(check_incidences(m).ok);
      // Renumber without b to run the ball check.
      std::vector<Tet> ts;
      for (TetId t : m.live_tets()) {
        Tet x = m.tet(t);
        for (VertexId& v : x) v = v > b ? VertexId{v - 1} : v;
        ts.push_back(x);
      }
      const BallVerdict bv = check_ball(TetMesh(m.num_vertices() - 1, ts));
      CHECK_MESSAGE(bv.ok, bv.message);
    }
  CHECK(accepted > 0);
  CHECK(refused > 0);
}

namespace {

using P = std::array<std::int32_t, 3>;

// Every live tet positive with the given integer positions.
bool all_positive(const TetMesh& m, const std::vector<P>& at) {
  for (TetId t : m.live_tets()) {
    const Tet& x = m.tet(t);
    if (cmx::topology::test::orientation(at[x[0]], at[x[1]], at[x[2]], at[x[3]]) <= 0) return false;
  }
  return true;
}

// The even permutation number k (0..11) of t.
Tet even_permutation(const Tet& t, int k) {
  static constexpr int perms[12][4] = {{0, 1, 2, 3}, {1, 2, 0, 3}, {2, 0, 1, 3}, {0, 2, 3, 1},
                                       {0, 3, 1, 2}, {1, 0, 3, 2}, {2, 3, 0, 1}, {3, 0, 2, 1},
                                       {1, 3, 2, 0}, {2, 1, 3, 0}, {3, 2, 1, 0}, {3, 1, 0, 2}};
  return {t[perms[k][0]], t[perms[k][1]], t[perms[k][2]], t[perms[k][3]]};
}

}  // namespace

TEST_CASE("2-3 and 3-2 flips keep every tet positive whatever the stored vertex order") {
  // p, q, r: a triangle; d below it, e above it, both over its inside (a convex pair).
  const std::vector<P> at{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, -3}, {1, 1, 3}};
  const VertexId p{0}, q{1}, r{2}, d{3}, e{4};
  for (int k = 0; k < 12; ++k) {
    CAPTURE(k);
    // (d, p, q, r) and (e, q, p, r) are positive; store them in the k-th even order.
    TetMesh m(
        5, std::vector<Tet>{even_permutation({d, p, q, r}, k), even_permutation({e, q, p, r}, (k + 5) % 12)});
    REQUIRE(all_positive(m, at));
    const FlipResult f = flip_23(m, r, p, q);
    REQUIRE(f.ok);
    CHECK(f.removed.size() == 2);
    CHECK(m.num_tets() == 3);
    CHECK(tets_around_edge(m, d, e).size() == 3);
    CHECK(all_positive(m, at));
    CHECK(check_incidences(m).ok);
    CHECK(check_ball(m).ok);
    CHECK_FALSE(flip_23(m, p, q, d).ok);  // a boundary face: one tet only
    const FlipResult back = flip_32(m, e, d);
    REQUIRE(back.ok);
    CHECK(m.num_tets() == 2);
    CHECK(tets_around_face(m, p, q, r).size() == 2);
    CHECK(all_positive(m, at));
    CHECK(check_ball(m).ok);
    undo_flip(m, back);
    CHECK(m.num_tets() == 3);
    CHECK(tets_around_edge(m, d, e).size() == 3);
    CHECK(all_positive(m, at));
  }
}

TEST_CASE("flips are refused where they would duplicate an edge or a face") {
  GridComplex g = grid_complex(2, 2, 2);
  TetMesh& m = g.mesh;
  const TetMesh before = m;
  // An edge in more than three tets, and an interior face whose apexes are already joined is
  // looked for among the grid's faces: every refusal leaves the mesh as it was.
  const VertexId center{1 + 3 * (1 + 3 * 1)};
  for (VertexId v : vertex_neighbors(m, center)) {
    if (tets_around_edge(m, center, v).size() == 3) continue;
    CHECK_FALSE(flip_32(m, center, v).ok);
  }
  CHECK(m.num_tets() == before.num_tets());
  CHECK(check_incidences(m).ok);
  std::size_t refused = 0, made = 0;
  for (TetId t : m.live_tets()) {
    const Tet x = m.tet(t);
    const FlipResult f = flip_23(m, x[0], x[1], x[2]);
    if (!f.ok) {
      ++refused;
      continue;
    }
    ++made;
    CHECK(check_incidences(m).ok);
    CHECK(check_ball(m).ok);
    undo_flip(m, f);
  }
  CHECK(refused > 0);
  CHECK(made > 0);
  CHECK(m.num_tets() == before.num_tets());
  CHECK(check_ball(m).ok);
}

TEST_CASE("a 3-2 flip is refused on a boundary edge in three tets (an open fan, found by fuzz_flips)") {
  GridComplex g = grid_complex(2, 2, 2);
  TetMesh& m = g.mesh;
  const std::vector<char> on_boundary = boundary_vertex_flags(m);
  std::size_t open_fans = 0;
  for (TetId t : m.live_tets()) {
    const Tet x = m.tet(t);
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const std::vector<TetId> around = tets_around_edge(m, x[i], x[j]);
        if (around.size() != 3) continue;
        std::vector<VertexId> ring;
        for (TetId u : around)
          for (VertexId v : m.tet(u))
            if (v != x[i] && v != x[j]) ring.push_back(v);
        std::sort(ring.begin(), ring.end());
        ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
        const FlipPlan plan = plan_flip_32(m, x[i], x[j]);
        if (ring.size() == 4) {
          ++open_fans;
          CHECK(on_boundary[x[i]]);
          CHECK(on_boundary[x[j]]);
          CHECK_FALSE(plan.ok);
        } else {
          CHECK(ring.size() == 3);
        }
      }
  }
  CHECK(open_fans > 0);
  CHECK(check_incidences(m).ok);
}
