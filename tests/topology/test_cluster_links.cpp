// Cluster-mesh combinatorics: paper Sec. 3.2 (Props. 1-3, Corollary 1, Eq. (1)), Figs. 4 and 6.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>

#include "topology/ball_check.hpp"
#include "topology/cluster_links.hpp"
#include "topology/complex_queries.hpp"
#include "topology/generators.hpp"
#include "topology/topological_expansion.hpp"
#include "topo_test_util.hpp"

using namespace cmx::topology;
using namespace cmx::topology::literals;
using cmx::topology::test::hex_bipyramid_cone;

namespace {

// Flags for the given vertices.
std::vector<char> flags_of(std::size_t n, std::initializer_list<std::uint32_t> vs) {
  std::vector<char> f(n, 0);
  for (std::uint32_t v : vs) f[v] = 1;
  return f;
}

// Random vertex subset of a grid (each vertex with probability p).
std::vector<char> random_subset(std::size_t n, double p, std::mt19937_64& rng) {
  std::vector<char> f(n, 0);
  for (auto& x : f) x = (rng() % 1000) < static_cast<std::uint64_t>(p * 1000) ? 1 : 0;
  return f;
}

}  // namespace

// Bipyramid vertex names: v=0, b (north)=1, s (south)=2, p_i = 3+i.
TEST_CASE("Fig. 4 (inflation case) in 3D: expanded link = two triangles sharing vertex b") {
  const TetMesh m = hex_bipyramid_cone();
  REQUIRE(check_ball(m).ok);
  // Expanded: b, p0, p1, p3, p4. Unexpanded: v, s, p2, p5.
  const std::vector<char> U = flags_of(9, {0, 2, 3 + 2, 3 + 5});
  ClusterLinkWorkspace ws;
  const LinkStats out = expanded_link_stats(m, 0_v, U, ws);
  CHECK(out.vertices == 5);
  CHECK(out.edges == 6);
  CHECK(out.triangles == 2);
  CHECK(out.euler == 1);
  CHECK(out.components == 1);
  const SimplexSet lko = expanded_link(m, 0_v, U);
  CHECK(lko.triangles == std::vector<Triangle>{{1_v, 3_v, 4_v}, {1_v, 6_v, 7_v}});
  // Lk• is the path p2 - s - p5: simply connected, so v is expandable (Eq. (1)) ...
  const LinkStats in = unexpanded_link_stats(m, 0_v, U, ws);
  CHECK(in.vertices == 3);
  CHECK(in.edges == 2);
  CHECK(in.triangles == 0);
  CHECK(in.simply_connected());
  CHECK(is_topologically_expandable(m, 0_v, U, ws));
  CHECK(manifold_expandability(m, 0_v, U, ws) == 2);
  // ... but only up to inflation: the cone base is pinched at b.
  CHECK(expanded_link_cut_vertices(m, 0_v, U) == std::vector<VertexId>{1_v});
}

TEST_CASE("cut vertices of Lk°: a lone vertex or a dangling edge has no fan") {
  const TetMesh m = hex_bipyramid_cone();
  // Everything unexpanded but b: Lk°(v) = {b}, the 3D version of the paper's 2D inflation case.
  const std::vector<char> only_b = flags_of(9, {0, 2, 3, 4, 5, 6, 7, 8});
  ClusterLinkWorkspace ws;
  CHECK(is_topologically_expandable(m, 0_v, only_b, ws));
  CHECK(expanded_link_cut_vertices(m, 0_v, only_b) == std::vector<VertexId>{1_v});
  // Lk°(v) = the edge (b, p0): both ends lack a triangle.
  const std::vector<char> edge = flags_of(9, {0, 2, 4, 5, 6, 7, 8});
  CHECK(expanded_link_stats(m, 0_v, edge, ws).simply_connected());
  CHECK(expanded_link_cut_vertices(m, 0_v, edge) == std::vector<VertexId>{1_v, 3_v});
  // Lk°(v) = a disc of two triangles (b,p0,p1), (b,p1,p2): no cut vertex.
  const std::vector<char> disc = flags_of(9, {0, 2, 6, 7, 8});
  CHECK(expanded_link_cut_vertices(m, 0_v, disc).empty());
}

TEST_CASE("invariant: a tet is degenerate iff it has >= 2 unexpanded vertices") {
  const std::vector<char> U{1, 1, 0, 0, 1};
  CHECK(is_degenerate_tet(make_tet({0, 1, 2, 3}), U));
  CHECK(!is_degenerate_tet(make_tet({0, 2, 3, 5}), U));  // vertex 5 beyond the flags: expanded
  CHECK(is_degenerate_tet(make_tet({2, 3, 4, 0}), U));
  CHECK(!is_degenerate_tet(make_tet({2, 3, 4, 5}), U));
  const TetMesh m = two_tets_sharing_face();
  CHECK(count_degenerate_tets(m, U) == 2);  // (0,1,2,3) has 0, 1; (1,2,3,4) has 1, 4
  CHECK(count_degenerate_tets(m, std::vector<char>{1, 1, 0, 0, 0}) == 1);
}

TEST_CASE("Fig. 6 left: simply connected Lk• and Lk°, vertex expandable, no cut vertex") {
  const TetMesh m = hex_bipyramid_cone();
  // Unexpanded: v, s, p0, p1 (a triangle fan of Lk: (s,p1,p0)).
  const std::vector<char> U = flags_of(9, {0, 2, 3, 4});
  ClusterLinkWorkspace ws;
  const ClusterVertexStatus st = classify_cluster_vertex(m, 0_v, U, ws);
  CHECK(st.expandable);
  CHECK(st.unexpanded_link.triangles == 1);
  CHECK(st.manifold_k == 3);
  CHECK(st.expanded_neighbors == 5);
  CHECK(expanded_link_stats(m, 0_v, U, ws).simply_connected());
  CHECK(expanded_link_cut_vertices(m, 0_v, U).empty());
}

TEST_CASE("Fig. 6 right: Lk• a cycle splits Lk° in two, vertex not expandable") {
  const TetMesh m = hex_bipyramid_cone();
  // Unexpanded: v, b, p0, s, p3: Lk• is the 4-cycle b-p0-s-p3.
  const std::vector<char> U = flags_of(9, {0, 1, 3, 2, 6});
  ClusterLinkWorkspace ws;
  const LinkStats in = unexpanded_link_stats(m, 0_v, U, ws);
  CHECK(in.vertices == 4);
  CHECK(in.edges == 4);
  CHECK(in.euler == 0);
  CHECK(in.components == 1);
  CHECK(!is_topologically_expandable(m, 0_v, U, ws));
  CHECK(manifold_expandability(m, 0_v, U, ws) == 0);
  const LinkStats out = expanded_link_stats(m, 0_v, U, ws);
  CHECK(out.components == 2);  // {p1,p2} and {p4,p5}
  CHECK(out.euler == 2);
}

TEST_CASE("k-manifold expandability: 1, 2, 3 and branching tree") {
  const TetMesh m = hex_bipyramid_cone();
  ClusterLinkWorkspace ws;
  CHECK(manifold_expandability(m, 0_v, flags_of(9, {0, 1}), ws) == 1);          // one cluster edge
  CHECK(manifold_expandability(m, 0_v, flags_of(9, {0, 3, 4, 5}), ws) == 2);    // path p0-p1-p2
  CHECK(manifold_expandability(m, 0_v, flags_of(9, {0, 1, 3, 4, 5}), ws) == 3); // disc of 2 triangles
  // A tree with a branch point: b - p0, b - p2, b - p4 plus nothing else is not induced (p's are
  // not adjacent to each other: p0,p2,p4), so Lk• = star tree at b: expandable, not k-manifold.
  const std::vector<char> tree = flags_of(9, {0, 1, 3, 5, 7});
  CHECK(is_topologically_expandable(m, 0_v, tree, ws));
  CHECK(manifold_expandability(m, 0_v, tree, ws) == 0);
  // Whole link unexpanded (a sphere) or empty: not expandable.
  CHECK(!is_topologically_expandable(m, 0_v, flags_of(9, {0, 1, 2, 3, 4, 5, 6, 7, 8}), ws));
  CHECK(!is_topologically_expandable(m, 0_v, flags_of(9, {0}), ws));
}

TEST_CASE("Proposition 1: chi(M• \\ St(v)) = chi(M•) + chi(Lk•(v)) - 1") {
  const GridComplex g = grid_complex(5, 4, 4);
  std::mt19937_64 rng(7);
  ClusterLinkWorkspace ws;
  std::size_t checked = 0, chi_one = 0;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<char> U = random_subset(g.mesh.num_vertices(), 0.6, rng);
    const std::int64_t before = subcomplex_counts(g.mesh, VertexSubset(U)).euler;
    for (int k = 0; k < 10; ++k) {
      const VertexId v = static_cast<VertexId>(rng() % g.mesh.num_vertices());
      if (!U[v]) continue;
      const LinkStats lk = unexpanded_link_stats(g.mesh, v, U, ws);
      U[v] = 0;
      const std::int64_t after = subcomplex_counts(g.mesh, VertexSubset(U)).euler;
      U[v] = 1;
      CHECK(after == before + lk.euler - 1);
      CHECK((after == before) == (lk.euler == 1));
      ++checked;
      chi_one += lk.euler == 1 ? 1 : 0;
    }
  }
  CHECK(checked > 100);
  CHECK(chi_one > 0);
  CHECK(chi_one < checked);
}

TEST_CASE("Proposition 2: removing v keeps a connected M• connected iff Lk•(v) is connected "
          "(M• simply connected), and Lk• connected always suffices") {
  const GridComplex g = grid_complex(5, 5, 4);
  std::mt19937_64 rng(11);
  ClusterLinkWorkspace ws;
  // Forward direction on random connected subsets.
  std::size_t forward = 0;
  for (int trial = 0; trial < 30; ++trial) {
    std::vector<char> U = random_subset(g.mesh.num_vertices(), 0.7, rng);
    if (subcomplex_counts(g.mesh, VertexSubset(U)).components != 1) continue;
    for (int k = 0; k < 10; ++k) {
      const VertexId v = static_cast<VertexId>(rng() % g.mesh.num_vertices());
      if (!U[v]) continue;
      const LinkStats lk = unexpanded_link_stats(g.mesh, v, U, ws);
      if (lk.components != 1) continue;
      U[v] = 0;
      CHECK(subcomplex_counts(g.mesh, VertexSubset(U)).components == 1);
      U[v] = 1;
      ++forward;
    }
  }
  CHECK(forward > 20);
  // Both directions on simply connected cluster meshes met during a random expansion.
  std::vector<char> U = interior_vertex_flags(g.mesh);
  const auto seq = topological_expansion(g.mesh, {ExpansionOrderKind::random, 3}).sequence;
  std::size_t both = 0, disconnecting = 0;
  for (std::size_t s = 0; s + 2 < seq.size(); s += 3) {
    for (VertexId v{0}; v < U.size(); v = VertexId{v + 5}) {
      if (!U[v]) continue;
      const LinkStats lk = unexpanded_link_stats(g.mesh, v, U, ws);
      U[v] = 0;
      const std::size_t b0 = subcomplex_counts(g.mesh, VertexSubset(U)).components;
      U[v] = 1;
      CHECK((b0 == 1) == (lk.components == 1));
      disconnecting += b0 != 1 ? 1 : 0;
      ++both;
    }
    for (std::size_t t = s; t < s + 3; ++t) U[seq[t]] = 0;
  }
  CHECK(both > 50);
  CHECK(disconnecting > 0);
}

TEST_CASE("Proposition 3: Lk°(v) simply connected iff Lk•(v) simply connected (interior v)") {
  // Every split of the bipyramid link into expanded / unexpanded vertices.
  const TetMesh m = hex_bipyramid_cone();
  ClusterLinkWorkspace ws;
  std::size_t yes = 0;
  for (std::uint32_t mask = 0; mask < (1u << 8); ++mask) {
    std::vector<char> U(9, 0);
    U[0] = 1;
    for (int i = 0; i < 8; ++i) U[1 + i] = (mask >> i) & 1 ? 1 : 0;
    const bool in = unexpanded_link_stats(m, 0_v, U, ws).simply_connected();
    const bool out = expanded_link_stats(m, 0_v, U, ws).simply_connected();
    CHECK(in == out);
    yes += in ? 1 : 0;
  }
  CHECK(yes > 0);
  CHECK(yes < 256);
  // And on grid interior vertices with random unexpanded sets.
  const GridComplex g = grid_complex(4, 4, 4);
  std::mt19937_64 rng(5);
  const std::vector<char> interior = interior_vertex_flags(g.mesh);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<char> U = random_subset(g.mesh.num_vertices(), 0.5, rng);
    for (VertexId v{0}; v < U.size(); ++v) {
      if (!interior[v]) continue;
      U[v] = 1;
      CHECK(unexpanded_link_stats(g.mesh, v, U, ws).simply_connected() ==
            expanded_link_stats(g.mesh, v, U, ws).simply_connected());
    }
  }
}

TEST_CASE("Corollary 1: expanding Eq.(1) vertices keeps the cluster mesh simply connected") {
  const GridComplex g = grid_complex(5, 4, 4);
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const TopologicalExpansionResult r = topological_expansion(g.mesh, {ExpansionOrderKind::random, seed});
    REQUIRE(!r.stuck);
    std::vector<char> U = interior_vertex_flags(g.mesh);
    ClusterLinkWorkspace ws;
    std::size_t degenerate = count_degenerate_tets(g.mesh, U);
    std::size_t cluster_edges = cluster_mesh_counts(g.mesh, U).edges;
    std::size_t stalled = 0;
    for (std::size_t s = 0; s + 1 < r.sequence.size(); ++s) {
      const VertexId v = r.sequence[s];
      CHECK(is_topologically_expandable(g.mesh, v, U, ws));
      U[v] = 0;
      const SubcomplexCounts c = cluster_mesh_counts(g.mesh, U);
      CHECK(c.components == 1);
      CHECK(c.euler == 1);
      // Each expansion strictly reduces the number of degenerate simplices: the zero-length
      // edges (cluster edges) strictly, the degenerate tets weakly. The tets alone need not
      // drop: when v has a single expanded neighbour x, every tet at v keeps >= 2 unexpanded
      // vertices (the invariant of topology/cluster_links.hpp is about simplices, not only tets).
      CHECK(c.edges < cluster_edges);
      cluster_edges = c.edges;
      const std::size_t now = count_degenerate_tets(g.mesh, U);
      CHECK(now <= degenerate);
      stalled += now == degenerate ? 1 : 0;
      degenerate = now;
    }
    CHECK(degenerate == 0);
    CHECK(stalled < r.sequence.size() / 2);
  }
}

