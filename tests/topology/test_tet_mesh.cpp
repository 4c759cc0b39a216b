// TetMesh storage, queries and generators.
#include <doctest/doctest.h>

#include <algorithm>
#include <type_traits>

#include "topology/ball_check.hpp"
#include "topology/complex_queries.hpp"
#include "topology/consistency.hpp"
#include "topology/generators.hpp"
#include "topology/tet_mesh.hpp"
#include "topo_test_util.hpp"

using namespace cmx::topology;
using namespace cmx::topology::literals;

TEST_CASE("single tet: incidences, boundary, stars and links") {
  const TetMesh m = single_tet();
  CHECK(m.num_vertices() == 4);
  CHECK(m.num_tets() == 1);
  CHECK(check_incidences(m).ok);
  for (VertexId v{0}; v < 4; ++v) CHECK(m.tets_of(v).size() == 1);
  const auto bf = boundary_faces(m);
  REQUIRE(bf.size() == 4);
  // Outward orientation: the face opposite vertex 0 is (1,2,3) in that cyclic order.
  bool found = false;
  for (const auto& f : bf)
    if (f.opposite == 0) found = same_orientation(f.face, Triangle{1_v, 2_v, 3_v});
  CHECK(found);
  const SimplexSet lk = vertex_link(m, 0_v);
  CHECK(lk.vertices == std::vector<VertexId>{1_v, 2_v, 3_v});
  CHECK(lk.edges.size() == 3);
  CHECK(lk.triangles.size() == 1);
  CHECK(euler_characteristic(lk) == 1);
  const SimplexSet st = vertex_star(m, 0_v);
  CHECK(st.vertices == std::vector<VertexId>{0_v});
  CHECK(st.edges.size() == 3);
  CHECK(st.triangles.size() == 3);
  CHECK(st.tets.size() == 1);
  const SimplexSet cl = vertex_closure(m, 0_v);
  CHECK(euler_characteristic(cl) == 1);  // closed tet: 4 - 6 + 4 - 1
  const SimplexSet el = edge_link(m, 0_v, 1_v);
  CHECK(el.vertices == std::vector<VertexId>{2_v, 3_v});
  CHECK(el.edges == std::vector<Edge>{{2_v, 3_v}});
  // Restricted to the subset {0,1,2}: the link of 0 is the edge (1,2).
  const std::vector<char> sub{1, 1, 1, 0};
  const SimplexSet lr = vertex_link(m, 0_v, VertexSubset(sub));
  CHECK(lr.vertices == std::vector<VertexId>{1_v, 2_v});
  CHECK(lr.edges == std::vector<Edge>{{1_v, 2_v}});
  CHECK(lr.triangles.empty());
  const SimplexSet sr = vertex_star(m, 3_v, VertexSubset(sub));
  CHECK(sr.vertices.empty());  // 3 is not in the subset
}

TEST_CASE("two tets sharing a face: adjacency and closure") {
  const TetMesh m = two_tets_sharing_face();
  CHECK(check_ball(m).ok);
  const TetAdjacency adj = tet_adjacency(m);
  CHECK(adj.manifold);
  CHECK(adj.neighbor[0][0] == 1);  // across the face opposite vertex 0: (1,2,3)
  CHECK(adj.neighbor[1][3] == 0);
  CHECK(boundary_faces(m).size() == 6);
  CHECK(tets_around_face(m, 1_v, 2_v, 3_v).size() == 2);
  CHECK(tets_around_edge(m, 0_v, 4_v).empty());
  const SimplexSet ec = edge_closure(m, 1_v, 2_v);
  CHECK(ec.tets.size() == 2);
  CHECK(euler_characteristic(ec) == 1);
  CHECK(connected_components(ec) == 1);
  const SimplexSet es = edge_star(m, 1_v, 2_v);
  CHECK(es.edges == std::vector<Edge>{{1_v, 2_v}});
  CHECK(es.triangles.size() == 3);  // (0,1,2), (1,2,3), (1,2,4)
  CHECK(es.tets.size() == 2);
  CHECK(vertex_neighbors(m, 1_v) == std::vector<VertexId>{0_v, 2_v, 3_v, 4_v});
}

TEST_CASE("grid generators: numbering, counts, positive orientation, ball") {
  for (const GridTriangulation tri : {GridTriangulation::freudenthal, GridTriangulation::reflected}) {
    const GridComplex g = grid_complex(3, 2, 4, tri);
    CHECK(g.mesh.num_vertices() == 4 * 3 * 5);
    CHECK(g.mesh.num_tets() == 6 * 3 * 2 * 4);
    for (VertexId v{0}; v < g.mesh.num_vertices(); ++v) {
      const auto& c = g.coords[v];
      CHECK(v == static_cast<VertexId>(c[0] + 4 * (c[1] + 3 * c[2])));
    }
    for (TetId t : g.mesh.live_tets()) {
      const Tet& x = g.mesh.tet(t);
      CHECK(cmx::topology::test::orientation(g.coords[x[0]], g.coords[x[1]], g.coords[x[2]], g.coords[x[3]]) == 1);
    }
    const BallVerdict b = check_ball(g.mesh);
    CHECK_MESSAGE(b.ok, b.message);
    CHECK(b.euler == 1);
    CHECK(b.boundary_euler == 2);
    CHECK(check_incidences(g.mesh).ok);
  }
}

TEST_CASE("subcomplex counts: Euler characteristic and components of induced subcomplexes") {
  const GridComplex g = grid_complex(3, 3, 3);
  const SubcomplexCounts all = subcomplex_counts(g.mesh);
  CHECK(all.euler == 1);
  CHECK(all.components == 1);
  CHECK(all.tets == 162);
  // Interior vertices of a 3x3x3 grid: the 2x2x2 block of points (1..2)^3 = one cube: chi 1.
  const std::vector<char> in = interior_vertex_flags(g.mesh);
  CHECK(std::count(in.begin(), in.end(), 1) == 8);
  const SubcomplexCounts c = subcomplex_counts(g.mesh, VertexSubset(in));
  CHECK(c.vertices == 8);
  CHECK(c.tets == 6);
  CHECK(c.euler == 1);
  CHECK(c.components == 1);
  // Two opposite corners only: two components, chi 2.
  std::vector<char> two(g.mesh.num_vertices(), 0);
  two[0] = two[g.mesh.num_vertices() - 1] = 1;
  const SubcomplexCounts t = subcomplex_counts(g.mesh, VertexSubset(two));
  CHECK(t.components == 2);
  CHECK(t.euler == 2);
  // The boundary vertex ring of the middle layer of a 3x3x1 slab minus its center: a cycle.
  const GridComplex ring = voxel_complex(3, 3, 1, cmx::topology::test::all_cells_but(3, 3, 1, {{1, 1, 0}}));
  const SubcomplexCounts rc = subcomplex_counts(ring.mesh);
  CHECK(rc.euler == 0);  // solid torus
}

TEST_CASE("remove_tet tombstones and compact renumbers consistently") {
  GridComplex g = grid_complex(2, 2, 2);
  TetMesh& m = g.mesh;
  m.remove_tet(TetId{5});
  m.remove_tet(TetId{17});
  m.remove_tet(TetId{5});  // no-op
  CHECK(m.num_tets() == 46);
  CHECK(m.tet_capacity() == 48);
  CHECK(!m.is_alive(TetId{5}));
  CHECK(check_incidences(m).ok);
  const Tet t20 = m.tet(TetId{20});
  const auto remap = m.compact();
  CHECK(remap[5] == invalid_index);
  CHECK(remap[20] == 18);
  CHECK(m.tet(TetId{18}) == t20);
  CHECK(m.tet_capacity() == 46);
  CHECK(check_incidences(m).ok);
}

TEST_CASE("TetMesh refuses out-of-range edits and stays consistent") {
  // An out-of-range tet is refused at insertion; a refused set_tet leaves the mesh unchanged.
  TetMesh m(4);
  CHECK(m.add_tet(make_tet({0, 1, 2, 7})) == invalid_index);
  CHECK(m.skipped_tets() == 1);
  CHECK(m.add_tet(make_tet({0, 1, 2, 3})) == 0);
  CHECK(check_incidences(m).ok);
  CHECK(m.set_tet(TetId{0}, make_tet({0, 1, 3, 2})));
  CHECK(check_incidences(m).ok);
  CHECK(!m.set_tet(TetId{0}, make_tet({0, 1, 3, 9})));
}

TEST_CASE("Vertex and tet handles are made from an index only explicitly and never from each other") {
  static_assert(!std::is_convertible_v<std::uint32_t, TetId>);
  static_assert(!std::is_convertible_v<std::uint32_t, VertexId>);
  static_assert(std::is_constructible_v<TetId, std::uint32_t>);
  static_assert(std::is_constructible_v<VertexId, std::uint32_t>);
  static_assert(!std::is_constructible_v<TetId, VertexId>);
  static_assert(!std::is_constructible_v<VertexId, TetId>);
  static_assert(std::is_convertible_v<TetId, std::uint32_t>);
  static_assert(std::is_convertible_v<VertexId, std::uint32_t>);
  // The mesh's queries take the kind they index: a tet where a vertex is expected does not compile.
  static_assert(std::is_invocable_v<decltype(&TetMesh::tets_of), const TetMesh&, VertexId>);
  static_assert(!std::is_invocable_v<decltype(&TetMesh::tets_of), const TetMesh&, TetId>);
  static_assert(std::is_invocable_v<decltype(&TetMesh::tet), const TetMesh&, TetId>);
  static_assert(!std::is_invocable_v<decltype(&TetMesh::tet), const TetMesh&, VertexId>);
  GridComplex g = grid_complex(1, 1, 1);
  const TetId t{3};
  CHECK(t.idx() == 3);
  CHECK(g.mesh.tet(t) == g.mesh.tet(3_tet));
  CHECK(invalid_tet == invalid_index);
  CHECK(invalid_vertex == invalid_index);
  const Tet& x = g.mesh.tet(t);
  for (const VertexId v : x) {
    const auto around = g.mesh.tets_of(v);
    CHECK(std::find(around.begin(), around.end(), t) != around.end());
  }
  CHECK(make_tet({4, 5, 6, 7}) == Tet{4_v, 5_v, 6_v, 7_v});
  CHECK(indices_of(make_tet({4, 5, 6, 7})) == TetIndices{4, 5, 6, 7});
}
