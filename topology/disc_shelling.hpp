#pragma once
// Shelling of a triangulated 2-disc onto the closed star of one of its vertices: the order in
// which a star-shapification that cannot fail would collapse an expansion cone's base onto its
// witness w (docs/algorithm/expansion.md, "Not built: a star-shapification that cannot fail").
// Combinatorics only; not yet used by the expansion loop.
//
// Triangles are removed one at a time, never one containing w, so that what is left stays a disc
// containing star(w), until star(w) alone is left. Triangle t of the remaining disc R is
// removable when
//   two of its edges are free (in no other triangle of R): its third vertex, an ear, has t as its
//     only triangle and leaves with it (an `ear` step); or
//   one edge (a, b) is free and the opposite vertex c is not on the boundary of R: R \ t is a disc
//     whose boundary runs a, c, b (a `free_edge` step; a geometric collapse splits (a, b) first,
//     so that the split vertex is an ear of valence 2).
// A triangle with no free edge, or with one whose opposite vertex is on the boundary (removing it
// would pinch R at that vertex), is not removable. The greedy order takes the first removable
// triangle in input order, so the result is deterministic. 2-balls are extendably shellable
// (Danaraj and Klee), so we expect the greedy order never to get stuck; a stuck run is reported,
// not hidden (`complete` false with the triangles left).
// Cost: O(F^2) for F triangles (bases are small: tens to a few hundred triangles).

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "topology/types.hpp"

namespace cmx::topology {

enum class DiscShellingKind : std::uint8_t { ear, free_edge };

struct DiscShellingStep {
  Triangle triangle{};  // as given in the input
  DiscShellingKind kind = DiscShellingKind::ear;
  // ear: the vertex that leaves the disc with the triangle; free_edge: the vertex opposite the
  // free edge (it becomes a boundary vertex).
  VertexId apex = invalid_vertex;
  Edge free_edge{invalid_vertex, invalid_vertex};  // free_edge steps: the free edge (a, b)
};

struct DiscShelling {
  bool complete = false;                // star(w) alone is left
  std::vector<DiscShellingStep> steps;  // in removal order
  std::vector<Triangle> left;           // the triangles left (star(w) when complete), input order
  std::string message;                  // why not complete, else empty
};

// Precondition for a meaningful result: `disc` is a triangulated 2-disc (every edge in one or two
// triangles, one boundary cycle, Euler characteristic 1) and w one of its vertices. Checked:
// every edge in at most two triangles, no repeated triangle, w a vertex of the disc (else
// `complete` false and the message names what is wrong).
[[nodiscard]] DiscShelling shell_disc_onto_star(std::span<const Triangle> disc, VertexId w);

// Whether `triangles` form a 2-disc: connected, every edge in one or two triangles, the boundary
// edges one cycle through distinct vertices, every vertex's triangles one fan, Euler
// characteristic 1. For tests and checks of the steps above.
[[nodiscard]] bool is_disc(std::span<const Triangle> triangles);

}  // namespace cmx::topology
