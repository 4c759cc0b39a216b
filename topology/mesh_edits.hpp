#pragma once
// Local edits of a TetMesh. Every edit keeps all incidences consistent (check_incidences) and
// keeps the orientation of every tet (a split tet's parts inherit its orientation). Edits refuse
// (ok = false, mesh untouched) instead of throwing.
//
// Handles: a split reuses each affected tet's slot for one of its parts ("modified") and appends
// the other parts ("created"); the new vertex gets the next vertex id (num_vertices() before).
// A collapse tombstones the tets around the edge ("removed") and rewrites the others ("modified").

#include <string>
#include <vector>

#include "topology/tet_mesh.hpp"

namespace cmx::topology {

struct SplitResult {
  bool ok = false;
  VertexId new_vertex = invalid_index;
  std::vector<TetId> modified;  // old handles, now one part each (they contain new_vertex)
  std::vector<TetId> created;   // new handles (they contain new_vertex)
  std::string message;          // why it was refused
};

// Splits edge ab at a new vertex m: every tet (a,b,c,d) becomes (m,b,c,d) and (a,m,c,d) (in
// the tet's own vertex order). Refused when ab is in no tet.
SplitResult split_edge(TetMesh& m, VertexId a, VertexId b);
// Splits face abc at a new vertex m (1 -> 3): each tet containing abc (one on the boundary, two
// inside) becomes three, by replacing a, b, c in turn with m. Refused when abc is in no tet.
SplitResult split_face(TetMesh& m, VertexId a, VertexId b, VertexId c);

struct CollapseResult {
  bool ok = false;
  std::vector<TetId> removed;   // tets that contained both vertices (tombstoned)
  std::vector<TetId> modified;  // tets where `gone` was replaced by `keep`
  std::string message;
};

// Link condition for collapsing edge ab in a 3-manifold with boundary: Lk(a) ∩ Lk(b) = Lk(ab)
// (vertices, edges, triangles), and, when a and b are both on the boundary, ab is a boundary
// edge and the same condition holds in the boundary surface (the usual "virtual vertex" rule).
[[nodiscard]] bool satisfies_link_condition(const TetMesh& m, VertexId a, VertexId b);
// Collapses edge (keep, gone) onto `keep`. Refused when the edge does not exist or the link
// condition fails. `gone` keeps its id and is left with no tet.
CollapseResult collapse_edge(TetMesh& m, VertexId keep, VertexId gone);

}  // namespace cmx::topology
