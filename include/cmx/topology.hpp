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

// One step of the expansion sequence that Alg. 2 (paper Sec. 4.3) makes from a shelling: split
// `split` (an edge: two ids, a face: three; kind vertex: none) making `vertex`, then expand it.
struct ReplayStep {
  enum class Kind : std::uint8_t { vertex, edge_split, face_split };
  Kind kind = Kind::vertex;
  std::array<std::uint32_t, 3> split{UINT32_MAX, UINT32_MAX, UINT32_MAX};  // unused ids: UINT32_MAX
  std::uint32_t vertex = UINT32_MAX;  // split vertices get ids vertex_count, vertex_count + 1, ... in order
  bool expanded = false;              // false: it was expanded already (boundary or free split): skipped
};

// The outcome of replay_shelling.
struct ShellingReplay {
  bool shelling_found = false;
  std::size_t attempts = 0;          // greedy shelling attempts made
  std::size_t best_removed = 0;      // most tets one attempt removed (every tet when found)
  bool completed = false;            // a shelling was replayed and every interior vertex was expanded
  std::size_t expansions = 0;        // cluster vertices the replay expanded
  std::size_t input_expansions = 0;  // of those, vertices of the input
  std::size_t chord_expansions =
      0;                         // of those, vertices splitting chords (the others: Alg. 2's split vertices)
  std::size_t eq1_failures = 0;  // expansions that did not satisfy Eq. (1) at their turn
  std::size_t left = 0;          // cluster vertices never expanded
  std::size_t boundary_splits = 0;  // splits of boundary simplices (boundary vertices: not expanded)
  std::size_t cluster_splits = 0;   // splits of simplices with a cluster vertex (expanded in turn)
  std::size_t free_splits = 0;      // splits of interior simplices of expanded vertices (not expanded)
  // Expansions of a vertex splitting a cluster edge (x, y) with a tet (x, y, s, t), s and t
  // expanded, around it: their geometric cone is empty while x and y sit at the shrink point,
  // which is why cmx::map_to_domain does not replay shellings (docs/algorithm/expansion.md).
  std::size_t empty_cone_edge_splits = 0;
  std::size_t checks = 0, check_failures = 0;  // with check_every > 0
  std::string message;                         // one sentence: the search's and the replay's verdict
  // The chord splits made first (interior edges and faces whose vertices all lie on the boundary;
  // with the boundary in place a chord leaves a hole in the cluster mesh and Eq. (1) can fail):
  // their vertices are interior, numbered from vertex_count on, and expanded by later steps.
  std::vector<ReplayStep> chords;
  std::vector<ReplayStep>
      steps;  // the sequence, when a shelling was found; its split vertices follow the chords'
};

// The shelling fallback of paper Sec. 4.3, topology only, in cmx's setting: splits every chord,
// looks for a shelling of the ball (at most `attempts` greedy attempts, seeded by `seed`; not
// finding one proves nothing), converts it by Alg. 2 and replays it from the start with the boundary vertices
// expanded and the interior ones in the cluster mesh, checking Eq. (1) at every expansion. This is
// what `cmx topo-expand` runs when its greedy expansion is stuck. With check_every = k > 0 the
// cluster mesh is also checked, before the first expansion, after every k-th and at the end, to
// be empty or connected with Euler characteristic 1 (Corollary 1), O(T) per check: a failed
// check makes `completed` false and is counted in `check_failures`.
// Errors: throws cmx::Error when the tets are not a ball, an index is >= vertex_count, or
// attempts is 0. Not finding a shelling is a result (shelling_found = false), not an error.
// Time: O(attempts * T log T) for bounded valence, plus the replay.
ShellingReplay replay_shelling(std::span<const Tet> tets, std::size_t vertex_count, std::uint64_t seed = 1,
                               std::size_t attempts = 8, std::size_t check_every = 0);

}  // namespace cmx
