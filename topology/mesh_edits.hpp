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
  VertexId new_vertex = invalid_vertex;
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

// A flip planned but not made: the tets it takes out and the ones it puts in (so that a caller
// can test the new tets' geometry before anything changes).
struct FlipPlan {
  bool ok = false;
  std::vector<TetId> old;
  std::vector<Tet> fresh;
  std::string message;  // why it is refused
};

struct FlipResult {
  bool ok = false;
  std::vector<Tet> removed;    // the vertices of the tets taken out (tombstoned)
  std::vector<TetId> created;  // new handles
  std::string message;
};

// 2-3 flip: the two tets sharing face abc, with apexes d and e, become three tets around the new
// edge de. Refused when abc is not in exactly two tets or de is already an edge. The new tets'
// orientation follows the old ones': with (d,p,q,r) an even permutation of d's tet, they are
// (p,q,d,e), (q,r,d,e), (r,p,d,e) (the positive orientation wherever the old pair is convex).
[[nodiscard]] FlipPlan plan_flip_23(const TetMesh& m, VertexId a, VertexId b, VertexId c);
// 3-2 flip: the three tets around edge de become two sharing the face pqr of the ring: (d,p,q,r)
// and (e,q,p,r), with (p,q,d,e) an even permutation of one of the three. Refused when de is not
// in exactly three tets, its ring is not three vertices, or pqr is already a face.
[[nodiscard]] FlipPlan plan_flip_32(const TetMesh& m, VertexId d, VertexId e);
// Makes a plan of this mesh, unchanged since it was planned (a refused plan changes nothing).
FlipResult apply_flip(TetMesh& m, const FlipPlan& plan);
FlipResult flip_23(TetMesh& m, VertexId a, VertexId b, VertexId c);
FlipResult flip_32(TetMesh& m, VertexId d, VertexId e);
// Undoes a flip: removes the tets it created, puts `removed` back (under new handles). Flips made
// after it must be undone first (in reverse order); their undoing may have moved its tets to new
// handles, which is why the created tets are found by their vertices.
void undo_flip(TetMesh& m, const FlipResult& flip);

}  // namespace cmx::topology
