#pragma once
// Alg. 2 (paper Sec. 4.3) in cmx's setting: the boundary stays at its prescribed positions from
// the start, so only interior vertices are ever in the cluster mesh.
//
// The paper replays a shelling with every vertex unexpanded at first, boundary included, and
// "expands" a boundary vertex by giving it its prescribed position. cmx never moves a boundary
// vertex, so this replays the same steps with the boundary expanded from the start:
//   - a split of a simplex on the mesh boundary makes a boundary vertex (placed, geometrically,
//     at the matching point of the target surface, as the paper does);
//   - a split of an interior simplex of expanded vertices makes an expanded vertex at once
//     (placed at the centroid of their positions, each child tet's orientation is a positive
//     multiple of its parent's, and its cluster vertices are its parent's: a free split);
//   - a split of an interior simplex with a cluster vertex makes a cluster vertex (placed at the
//     shrink point, which keeps every invariant), expanded when its step comes;
//   - a step whose vertex is already expanded (a boundary vertex, a free split) is skipped.
// What it checks is the topological half of the fallback: that every vertex the replay expands
// satisfies Eq. (1) when its turn comes, and that the cluster mesh ends empty. It also counts the
// steps whose geometric half is known to be hard: an edge-split vertex of a cluster edge (x, y)
// whose star holds a tet (x, y, s, t) with s and t expanded, split into (m, y, s, t) and
// (x, m, s, t): while x and y sit at the shrink point these two ask m for opposite signs, so its
// cone is empty (docs/algorithm/expansion.md, "Replaying Alg. 2 with the boundary in place").

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "topology/shelling.hpp"
#include "topology/tet_mesh.hpp"

namespace cmx::topology {

struct FixedBoundaryReplay {
  bool ok = false;                         // every expansion satisfied Eq. (1) and the cluster ended empty
  std::size_t expansions = 0;              // interior vertices the replay expanded (original or split)
  std::size_t input_expansions = 0;        // of those, vertices of the input (the others split)
  std::size_t eq1_failures = 0;            // of those, not satisfying Eq. (1) at their turn
  std::size_t boundary_splits = 0;         // splits of simplices on the mesh boundary
  std::size_t free_splits = 0;             // splits of interior simplices of expanded vertices
  std::size_t cluster_splits = 0;          // splits of interior simplices with a cluster vertex
  std::size_t empty_cone_edge_splits = 0;  // cluster-edge splits facing the mirrored pair above
  std::size_t left = 0;                    // cluster vertices left at the end
  std::string first_failure;               // the first step that failed Eq. (1), when one did
  std::vector<char> step_expanded;         // per step: 1 when it expanded a cluster vertex (0: skipped)
  std::size_t checks = 0;                  // cluster meshes checked to be simply connected (check_every)
  std::size_t check_failures = 0;  // of those, not empty and not connected with Euler characteristic 1
  bool stopped = false;            // `stop_when` returned true (after `expansions` expansions)
};

// Asked after each expansion with the mesh and the cluster flags then; true stops the replay.
using ReplayStop = std::function<bool(const TetMesh& mesh, const std::vector<char>& unexpanded)>;

// Preconditions: `input` is the mesh `sequence` was computed from
// (shelling_to_expansion_sequence), `sequence.ok`, and check_ball(input).ok. O(T) plus the
// Eq. (1) tests, one per expansion. With check_every = k > 0 the cluster mesh is also checked
// before the first expansion, after every k-th and at the end to be empty or connected with
// Euler characteristic 1 (Corollary 1: Eq. (1) expansions keep it simply connected), O(T) each;
// a failed check fails the replay.
// `stop_when` (when given) can end the replay early, e.g. once greedy expansion could take over
// (algorithm/expansion/shelling_replay.cpp picks its plan so); `ok` is then false.
// `start` (when given, one flag per vertex of `input`) is the cluster to start from instead of
// every interior vertex: a replay planned again part-way, where some interior vertices are
// already expanded. Its steps whose vertex is expanded are skipped, as for boundary vertices.
[[nodiscard]] FixedBoundaryReplay replay_with_fixed_boundary(const TetMesh& input,
                                                             const ShellingExpansion& sequence,
                                                             std::size_t check_every = 0,
                                                             const ReplayStop& stop_when = {},
                                                             const std::vector<char>* start = nullptr);

// The fallback of paper Sec. 4.3 for a run without geometry (cmx topo-expand): split every
// chord of `input`, look for a shelling of the result (find_shelling, bounded by `options`) and,
// when one is found, convert it by Alg. 2 and replay it from the start with the boundary in
// place. The replay does not continue the greedy run that got stuck: as in the paper, the
// sequence is planned for the whole input.
//
// Why every chord first (topology/chords.hpp: interior simplices whose vertices all lie on the
// boundary): with the boundary expanded, the cluster mesh is homotopy equivalent to the remaining
// ball R minus its simplices spanned by boundary vertices. Without chords those all lie on the
// boundary of R, and a ball minus closed parts of its boundary stays contractible, so no step can
// leave a hole; a boundary split makes no chord either (its new edges to a boundary vertex lie in a
// boundary face). With chords, a chord inside R is a hole, and Eq. (1) fails: on the unknotted
// control ball 2 of 3 greedy shellings fail Eq. (1) at some step before its 316 chords are split,
// none after (tests/topology/test_shelling.cpp).
struct ChordSplit {
  std::array<VertexId, 3> simplex{invalid_vertex, invalid_vertex, invalid_vertex};  // edge: 2 ids
  VertexId vertex = invalid_vertex;  // the new interior vertex (a cluster vertex, expanded by a later step)
};

struct ShellingFallback {
  std::vector<ChordSplit> chords;    // the chord splits, in order, before the shelling
  std::size_t chord_expansions = 0;  // chord vertices the replay expanded (not in replay.input_expansions)
  bool shelling_found = false;
  std::size_t attempts = 0;      // greedy shelling attempts made
  std::size_t best_removed = 0;  // most tets one attempt removed (all of them when found)
  std::size_t tets = 0;          // tets of the mesh shelled (the input after the chord splits)
  bool stopped_at_deadline = false;
  bool replayed = false;             // a sequence was converted and replayed
  FixedBoundaryReplay replay;        // meaningful when `replayed`; its input_expansions: the input's own
  std::vector<ExpansionStep> steps;  // Alg. 2's sequence when `replayed` (replay.step_expanded: which ran)
  std::string message;               // one sentence: what was found and how the replay ended
};

// Precondition: check_ball(input).ok. O(attempts * T log T) plus the replay. `input` is taken by
// value since the chords are split in it: a caller done with its mesh moves it in.
// check_every: as for replay_with_fixed_boundary.
[[nodiscard]] ShellingFallback shelling_fallback(TetMesh input, const ShellingOptions& options = {},
                                                 std::size_t check_every = 0);

}  // namespace cmx::topology
