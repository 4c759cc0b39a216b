// Orienting a complex given only combinatorially (topology/coherent_orientation.hpp).
#include <doctest/doctest.h>

#include <random>

#include "topology/coherent_orientation.hpp"
#include "topology/complex_queries.hpp"
#include "topology/generators.hpp"

using namespace cmx::topology;
using namespace cmx::topology::literals;

namespace {

// Every interior face listed in opposite cyclic orders by its two tets.
bool coherent(const TetMesh& m) {
  const TetAdjacency adj = tet_adjacency(m);
  for (TetId t : m.live_tets())
    for (int i = 0; i < 4; ++i) {
      const TetId u = adj.neighbor[t][i];
      if (u == invalid_tet) continue;
      VertexId apex = invalid_vertex;
      for (VertexId w : m.tet(u))
        if (!contains(m.tet(t), w)) apex = w;
      if (same_orientation(tet_face(m.tet(t), i), tet_face(m.tet(u), local_index(m.tet(u), apex)))) return false;
    }
  return true;
}

}  // namespace

TEST_CASE("a grid complex with tets turned over at random is oriented back to its own orientation") {
  GridComplex g = grid_complex(3, 3, 2);
  REQUIRE(coherent(g.mesh));
  const TetMesh original = g.mesh;
  std::mt19937_64 rng(7);
  std::size_t turned = 0;
  for (TetId t : g.mesh.live_tets()) {
    if (t == 0_tet || rng() % 3 != 0) continue;  // the first tet keeps the global sign
    Tet x = g.mesh.tet(t);
    std::swap(x[0], x[1]);
    REQUIRE(g.mesh.set_tet(t, x));
    ++turned;
  }
  REQUIRE(turned > 0);
  REQUIRE_FALSE(coherent(g.mesh));
  const CoherentOrientation r = orient_coherently(g.mesh);
  CHECK(r.ok);
  CHECK(r.flipped == turned);
  CHECK(coherent(g.mesh));
  for (TetId t : g.mesh.live_tets()) {  // same orientation as before the turning, tet by tet
    const Tet& a = g.mesh.tet(t);
    const Tet& b = original.tet(t);
    CHECK(same_orientation(tet_face(a, local_index(a, b[0])), tet_face(b, 0)));
  }
}

TEST_CASE("a coherent complex is left as it is, and a face in three tets is refused with its name") {
  TetMesh two = two_tets_sharing_face();
  const CoherentOrientation r = orient_coherently(two);
  CHECK(r.ok);
  CHECK(r.flipped == 0);
  TetMesh three(6, make_tets({{0, 1, 2, 3}, {1, 2, 3, 4}, {1, 3, 2, 5}}));
  const CoherentOrientation bad = orient_coherently(three);
  CHECK_FALSE(bad.ok);
  CHECK(bad.message.find("three or more tets") != std::string::npos);
}
