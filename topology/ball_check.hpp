#pragma once
// Ball-topology validation of a TetMesh with a structured verdict.
//
// Checks, in this order (the first failure is reported):
//   empty mesh; tet with a repeated vertex; vertex used by no tet; duplicated tet; face in 3+
//   tets; inconsistent orientation across an interior face; disconnected (tets not connected
//   through faces); non-manifold edge (the tets around an edge are not one fan); non-manifold
//   vertex (the tets around a vertex are not connected through faces, e.g. two balls touching at
//   a vertex); vertex link neither a disc (boundary vertex) nor a sphere (interior vertex);
//   Euler characteristic V-E+F-T != 1; boundary not a single 2-sphere (disconnected or chi != 2).
// Passing all checks means: a connected, consistently oriented 3-manifold with boundary whose
// boundary is one 2-sphere and whose Euler characteristic is 1 (a ball up to homology).
// Cost: O(T log d) time, O(T) memory, with d the largest number of tets around a vertex.

#include <string>
#include <vector>

#include "topology/tet_mesh.hpp"

namespace cmx::topology {

enum class BallFailure {
  none,
  empty,
  degenerate_tet,            // simplex: the tet's 4 vertices
  isolated_vertex,           // simplex: the vertex
  duplicate_tet,             // simplex: the tet's vertices
  face_in_three_or_more_tets,// simplex: the face
  inconsistent_orientation,  // simplex: the face (as in the first tet)
  disconnected,              // simplex: a vertex of a second component
  non_manifold_edge,         // simplex: the edge
  non_manifold_vertex,       // simplex: the vertex
  vertex_link_not_disc_or_sphere,  // simplex: the vertex
  euler_characteristic,      // simplex: empty
  boundary_not_sphere,       // simplex: a boundary vertex (of a second boundary component if any)
};

[[nodiscard]] const char* to_string(BallFailure f);

struct BallVerdict {
  bool ok = false;
  BallFailure failure = BallFailure::none;
  std::vector<VertexId> simplex;  // the offending simplex (vertex ids), possibly empty
  std::string message;            // human-readable: what is wrong where
  // Counts gathered on the way (valid when the corresponding check was reached).
  std::size_t vertices = 0, edges = 0, faces = 0, tets = 0, boundary_faces = 0, boundary_vertices = 0;
  std::int64_t euler = 0, boundary_euler = 0;
};

[[nodiscard]] BallVerdict check_ball(const TetMesh& m);

}  // namespace cmx::topology
