// Chords and the simple connectivity of the interior mesh (topology/chords.hpp).
#include <doctest/doctest.h>

#include <vector>

#include "topology/ball_check.hpp"
#include "topology/chords.hpp"
#include "topology/cluster_links.hpp"
#include "topology/complex_queries.hpp"
#include "topology/generators.hpp"
#include "topology/mesh_edits.hpp"

using namespace cmx::topology;

namespace {

struct Flags {
  TetMesh m;
  std::vector<char> boundary, interior;
  std::size_t splits_made = 0;
  ChordContext context() {
    return {m, boundary, interior, [this](VertexId a, VertexId b, VertexId c) {
              const SplitResult r = c == invalid_index ? split_edge(m, a, b) : split_face(m, a, b, c);
              REQUIRE(r.ok);
              boundary.push_back(0);
              interior.push_back(1);
              ++splits_made;
              return r.new_vertex;
            }};
  }
};

Flags flags_of(TetMesh m) {
  Flags f{std::move(m), {}, {}};
  f.boundary = boundary_vertex_flags(f.m);
  f.interior = interior_vertex_flags(f.m);
  return f;
}

// Two 2x3x3 blocks of cells joined through the middle cell of a 1x3x3 slab: the slab's vertices
// are all on the boundary, so the two interiors are separated by chords.
TetMesh chord_wall_mesh() {
  std::vector<char> keep(5 * 3 * 3, 0);
  auto cell = [](int i, int j, int k) { return i + 5 * (j + 3 * k); };
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        if (i != 2 || (j == 1 && k == 1)) keep[std::size_t(cell(i, j, k))] = 1;
  return voxel_complex(5, 3, 3, keep).mesh;
}

}  // namespace

TEST_CASE("chord edges and faces are recognised") {
  // A 2x1x1 grid: every vertex is on the boundary; its inner face x = 1 is made of chords.
  Flags f = flags_of(grid_complex(2, 1, 1).mesh);
  std::size_t chord_faces = 0, chord_edges = 0;
  for (TetId t : f.m.live_tets())
    for (int i = 0; i < 4; ++i)
      if (is_chord_face(f.m, f.boundary, tet_face(f.m.tet(t), i))) ++chord_faces;
  for (VertexId a{0}; a < f.m.num_vertices(); ++a)
    for (VertexId b{a + 1}; b < f.m.num_vertices(); ++b)
      if (is_chord_edge(f.m, f.boundary, a, b)) ++chord_edges;
  CHECK(chord_faces > 0);
  CHECK(chord_edges > 0);
  // On a 3x3x3 grid the interior (8 vertices) is already simply connected: nothing to split.
  Flags g = flags_of(grid_complex(3, 3, 3).mesh);
  CHECK(interior_simply_connected(g.m, g.interior));
  auto c = g.context();
  CHECK(make_interior_simply_connected(c) == 0);
}

TEST_CASE("a mesh without interior vertices gets an interior, simply connected, by splitting chords") {
  Flags f = flags_of(grid_complex(3, 2, 1).mesh);
  REQUIRE(cluster_mesh_counts(f.m, f.interior).vertices == 0);
  auto c = f.context();
  CHECK(split_all_chords(c) > 0);
  CHECK(check_ball(f.m).ok);
  CHECK(interior_simply_connected(f.m, f.interior));
  CHECK(cluster_mesh_counts(f.m, f.interior).vertices > 0);
}

TEST_CASE("an interior cut in two by a chord wall is joined through the fewest chord faces") {
  // A 5x2x2 grid whose x = 2 layer is all boundary vertices? Build it from a voxel complex: two
  // 2x2x2 blocks joined by a one-cell-thick slab of cells; the slab's vertices are all boundary
  // vertices except none, so the two interiors are separated by chords.
  Flags f = flags_of(chord_wall_mesh());
  REQUIRE(check_ball(f.m).ok);
  const auto before = cluster_mesh_counts(f.m, f.interior);
  CHECK(before.components == 2);
  auto c = f.context();
  const std::size_t splits = connect_interior(c);
  CHECK(splits >= 1);
  CHECK(cluster_mesh_counts(f.m, f.interior).components == 1);
  CHECK(check_ball(f.m).ok);
  (void)make_interior_simply_connected(c);
  CHECK(interior_simply_connected(f.m, f.interior));
}

TEST_CASE("the bare-mesh chord splits give the callback version's mesh and interior") {
  Flags f = flags_of(chord_wall_mesh());
  auto c = f.context();
  const std::size_t splits = make_interior_simply_connected(c);
  REQUIRE(splits > 0);

  TetMesh bare = chord_wall_mesh();
  const ChordSplits s = make_interior_simply_connected(bare);
  CHECK(s.splits == splits);
  CHECK(s.interior == f.interior);
  REQUIRE(bare.num_vertices() == f.m.num_vertices());
  CHECK(bare.live_tets().size() == f.m.live_tets().size());
  for (TetId t : bare.live_tets()) CHECK(bare.tet(t) == f.m.tet(t));
  CHECK(interior_simply_connected(bare, s.interior));
  CHECK(check_ball(bare).ok);
}
