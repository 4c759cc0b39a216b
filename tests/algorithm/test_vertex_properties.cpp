// Per-vertex properties grow with the mesh they were made for (algorithm/vertex_properties.hpp).
#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "algorithm/embedding.hpp"

using namespace cmx;
using namespace cmx::algorithm;
using namespace cmx::topology::literals;

namespace {

// The unit tetrahedron, as source and target, nothing in the cluster.
Embedding unit_tet() {
  Embedding e;
  e.mesh = topology::TetMesh(4, topology::make_tets({{0, 1, 2, 3}}));
  e.source = {HPoint(0, 0, 0), HPoint(1, 0, 0), HPoint(0, 1, 0), HPoint(0, 0, 1)};
  e.target = e.source;
  e.unexpanded.assign(4, 0);
  e.boundary.assign(4, 1);
  return e;
}

}  // namespace

TEST_CASE("a vertex property grows with every split and new vertices get its fill value") {
  Embedding e = unit_tet();
  VertexProperty<std::uint32_t> p = e.properties.make<std::uint32_t>(e.num_vertices(), 7);
  REQUIRE(p.size() == 4);
  p[2_v] = 3;
  const VertexId m = e.split_edge(0_v, 1_v, HPoint(Rational(1, 2), 0, 0), false);
  CHECK(p.size() == e.num_vertices());
  CHECK(p[m] == 7);
  CHECK(p[2_v] == 3);
  const VertexId f = e.split_face(0_v, 2_v, 3_v, HPoint(0, Rational(1, 3), Rational(1, 3)), true);
  CHECK(p.size() == e.num_vertices());
  CHECK(p[f] == 7);
}

TEST_CASE("a copied embedding has no properties of its own and leaves the original's alone") {
  Embedding e = unit_tet();
  VertexProperty<char> p = e.properties.make<char>(e.num_vertices(), 0);
  Embedding copy = e;
  CHECK(copy.properties.live() == 0);
  copy.split_edge(0_v, 1_v, HPoint(Rational(1, 2), 0, 0), false);
  CHECK(copy.num_vertices() == 5);
  CHECK(p.size() == 4);  // the original did not change
  CHECK(e.properties.live() == 1);
}

TEST_CASE("a moved embedding takes its properties along, and a destroyed property drops out") {
  Embedding e = unit_tet();
  VertexProperty<int> kept = e.properties.make<int>(e.num_vertices(), 1);
  {
    VertexProperty<double> gone = e.properties.make<double>(e.num_vertices(), 0.5);
    CHECK(e.properties.live() == 2);
  }
  CHECK(e.properties.live() == 1);
  Embedding moved = std::move(e);
  moved.split_edge(0_v, 1_v, HPoint(Rational(1, 2), 0, 0), false);
  CHECK(kept.size() == moved.num_vertices());
  CHECK(kept[4_v] == 1);
  CHECK(moved.properties.live() == 1);
}
