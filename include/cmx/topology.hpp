#pragma once
// Combinatorial queries on tetrahedral meshes given as plain index arrays (no coordinates): the
// ball check cmx::map_to_domain needs of its input, the boundary surface, and the topological
// expandability of a vertex of a cluster mesh (Eq. (1) of the Cluster-Mesh Expansion paper, Sec. 3;
// docs/topology.md).
//
//   cmx::BallCheck b = cmx::is_ball(tets, vertex_count);
//   if (!b.ok) std::cerr << b.message << '\n';  // e.g. "vertex 4: its tets form 2 ..."
//
// Vertices are 0 .. vertex_count-1. A cluster mesh is the full subcomplex on a set of
// "unexpanded" vertices U (every simplex whose vertices are all in U); Lk•(v) is the part of the
// link of v whose vertices are all in U.
//
// This header includes only the standard library and <cmx/types.hpp>.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cmx/types.hpp"

namespace cmx {

struct BallCheck {
  bool ok = false;
  std::string message;  // "" when ok; otherwise what is wrong and where (vertex, face, tet)
};

// Whether `tets` form a combinatorial 3-ball: no tet naming a vertex >= vertex_count, no repeated
// vertex in a tet, every vertex used, no duplicate tet, every face in at most two tets, tets
// oriented consistently across interior faces, connected, manifold edges and vertices (links
// discs or spheres), Euler characteristic 1, and the boundary a single 2-sphere. The first
// failure found, in that order, is reported. Coordinates are not looked at (orientation
// consistency is combinatorial; use cmx::orient3d for the geometric sign).
// Errors: none thrown for bad input; a bad index is ok = false with a message naming the tet.
// Time: O(T log d), memory O(T + vertex_count), d the largest number of tets around a vertex.
BallCheck is_ball(std::span<const Tet> tets, std::size_t vertex_count);

// The boundary faces (faces of exactly one tet), each oriented with its normal pointing out of
// its tet when the tets are positively oriented, in no particular order. Meaningful when every
// face lies in at most two tets (is_ball checks it).
// Errors: throws cmx::Error naming the tet when a tet names a vertex >= vertex_count.
// Time: O(T log d).
std::vector<std::array<std::uint32_t, 3>> boundary_faces(std::span<const Tet> tets, std::size_t vertex_count);

// Eq. (1): whether `vertex` of the cluster mesh on `cluster_vertices` (the unexpanded vertices,
// any order, repeats allowed) is topologically expandable: Lk•(vertex) is non-empty, connected
// and has Euler characteristic 1 (b0 = 1, chi = 1). An isolated cluster vertex (Lk• empty) is not
// expandable by Eq. (1) (the method expands it automatically).
// Preconditions: the tets form a ball (is_ball), vertex is one of cluster_vertices.
// Errors: throws cmx::Error when the tets are not a ball (with is_ball's message), an index is
// >= vertex_count, or vertex is not a cluster vertex.
// Time: O(T log d) (building the mesh and checking it); the query itself is O(d log d).
bool is_expandable(std::span<const Tet> tets, std::size_t vertex_count,
                   std::span<const std::uint32_t> cluster_vertices, std::uint32_t vertex);

// The outcome of expand_topologically.
struct TopologicalExpansion {
  bool complete = false;  // every cluster vertex was expanded: the cluster mesh is expandable
  // The expanded vertices in order (isolated cluster vertices, expanded automatically, included).
  std::vector<std::uint32_t> sequence;
  std::vector<std::uint32_t> remaining;  // when not complete: the cluster vertices left, ascending
  // Whether the initial cluster mesh was empty or connected with Euler characteristic 1. Getting
  // stuck from a simply connected cluster mesh means it contains a NOBUENOSS (Corollary 1).
  bool initially_simply_connected = false;
};

// Topological expansion (paper Sec. 5.1): expands the cluster mesh on `cluster_vertices` (empty:
// the interior vertices, the paper's setting) greedily by Eq. (1) alone, without geometry, in
// the given order: "priority" (k-manifold-expandable vertices with lower k first, then larger
// expansion cones, then lower index), "index" (lowest index first; "strict-index" is the same
// here, there being no classes) or "random:SEED". Unlike
// `cmx topo-expand` (without --raw) the mesh is taken as given: no chords are split first, so an
// interior that is not simply connected makes the expansion stuck, with
// initially_simply_connected false. The mesh is not modified; indices are the input's.
// Errors: throws cmx::Error when the tets are not a ball, an index is >= vertex_count, or the
// order does not parse. Getting stuck is a result (complete = false), not an error.
// Time: O(T log d) for bounded valence.
TopologicalExpansion expand_topologically(std::span<const Tet> tets, std::size_t vertex_count,
                                          std::span<const std::uint32_t> cluster_vertices = {},
                                          std::string_view order = "priority");

}  // namespace cmx
