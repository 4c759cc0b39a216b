#pragma once
// Chords: interior simplices (not on the boundary) whose vertices all lie on the boundary. They
// decide the topology of the interior vertices' full subcomplex, the initial cluster mesh: it is
// homotopy equivalent to the ball minus the full subcomplex on the boundary vertices, i.e. minus
// the chord faces and chord edges (and H2 vanishes, by Alexander duality, since every chord
// reaches the boundary). A chord face whose two sides hold interior vertices of different
// components separates them; a chord edge whose surrounding cycle is entirely interior is the axis
// of a handle (splitting it raises chi by one). Splitting exactly those makes the interior mesh
// simply connected with far fewer splits than the predecessor program's rule (split every chord
// face with three boundary edges and every chord edge), which is kept as the fallback.
//
// The functions split through a caller-provided function, so that a caller holding positions can
// mirror each split; it must update `boundary` and `interior` for the new vertex (0 and 1).
#include <cstddef>
#include <functional>
#include <vector>

#include "topology/tet_mesh.hpp"

namespace cmx::topology {

struct ChordContext {
  TetMesh& mesh;
  std::vector<char>& boundary;  // one flag per vertex
  std::vector<char>& interior;  // one flag per vertex: the cluster
  // Splits edge (a, b) (c == invalid_index) or face (a, b, c) and returns the new vertex.
  std::function<VertexId(VertexId a, VertexId b, VertexId c)> split;
};

// Interior edge between two boundary vertices.
[[nodiscard]] bool is_chord_edge(const TetMesh& m, const std::vector<char>& boundary, VertexId a, VertexId b);
// Interior face with its three vertices on the boundary.
[[nodiscard]] bool is_chord_face(const TetMesh& m, const std::vector<char>& boundary, const Triangle& f);
// Maximal runs of interior vertices along the cycle around edge ab (0 when none or when the whole
// cycle is interior; `all_interior` tells the latter).
[[nodiscard]] int interior_runs(const TetMesh& m, const std::vector<char>& interior, VertexId a, VertexId b,
                                bool& all_interior);

// Joins the interior mesh's components through the fewest chord faces (0-1 BFS over tets),
// splitting a chord edge of the face instead when it has one (that joins the same tets and removes
// the chord). Returns the number of splits; stops when one component is left or none can be joined.
std::size_t connect_interior(ChordContext& c);
// Splits every chord edge whose cycle is entirely interior. Returns the number of splits.
std::size_t fill_interior_handles(ChordContext& c);
// The fallback: every chord face with three boundary edges, then every chord edge. Afterwards no
// interior simplex has all its vertices on the boundary.
std::size_t split_all_chords(ChordContext& c);

// The interior mesh is empty, or connected with Euler characteristic 1.
[[nodiscard]] bool interior_simply_connected(const TetMesh& m, const std::vector<char>& interior);

// connect_interior and fill_interior_handles, then split_all_chords if still not simply
// connected: what topological expansion needs before it starts. Returns the number of splits.
std::size_t make_interior_simply_connected(ChordContext& c);

// The same on a bare mesh, split in place (topology/mesh_edits.hpp: no positions to mirror).
struct ChordSplits {
  std::vector<char> interior;  // one flag per vertex after the splits: the cluster
  std::size_t splits = 0;
};
ChordSplits make_interior_simply_connected(TetMesh& mesh);

}  // namespace cmx::topology
