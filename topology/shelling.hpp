#pragma once
// Shelling of a ball (paper Sec. 4.3) and its conversion to an expansion sequence (Alg. 2).
//
// A shelling here is a removal order c_0, ..., c_{n-1} of all tets such that the remaining tets
// form a ball after each removal. Tet t of the remaining ball R is removable when it has 1, 2 or
// 3 free faces (faces on the boundary of R) and
//   t ∩ ∂R = closure of its free faces (no other vertex/edge of t on the boundary), and
//   t ∩ (R \ t) = closure of its shared faces (no other vertex/edge of t in another tet);
// both are then 2-discs and R \ t is a ball. With j = #shared faces: j = 1 leaves the vertex
// opposite the shared face to t alone, j = 2 the edge common to the two free faces.
// find_shelling removes removable tets greedily (candidates re-checked when a neighbour goes),
// ordered by a seeded random priority; a greedy run can get stuck on a shellable ball, so it
// retries with new seeds. Bound: at most `max_attempts` runs, each O(T log T): the rule is
// answered from counts kept per vertex and edge (topology/shelling_counts.hpp), not star walks.
// Not finding a shelling within the bound proves nothing (the ball may still be shellable).

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "topology/complex_queries.hpp"
#include "topology/tet_mesh.hpp"

namespace cmx::topology {

struct ShellingOptions {
  std::size_t max_attempts = 8;
  std::uint64_t seed = 1;
  // Polled before each batch of attempts but the first (an attempt is not cut short): once it
  // returns true no new attempt starts. The caller's deadline, or any other reason to stop.
  std::function<bool()> should_stop;
  // Attempts run at once (0: the machine's cores; never more than max_attempts). The result is
  // the same for every count; only how many attempts a deadline lets start can differ.
  std::size_t threads = 1;
  // When given (one flag per vertex: interior to the mesh), removable tets are taken cheapest
  // step first, the seeded priority breaking ties, for Alg. 2 replayed with the boundary in place
  // (algorithm/expansion/shelling_replay.cpp): a step whose vertex or split simplex has a
  // boundary vertex changes no cluster mesh (cost 0); otherwise the cost is the number of faces
  // the tet shares: a removal by an interior vertex of its own (1), a split of an interior edge
  // (2, the step that needs inflation), a split of a free interior face (3). Without it the
  // seeded priority alone orders them.
  const std::vector<char>* interior = nullptr;
};

struct ShellingResult {
  bool found = false;
  std::vector<TetId> order;  // removal order (all live tets) when found
  std::size_t attempts = 0;
  std::size_t best_removed = 0;  // most tets removed by one attempt
  bool stopped_at_deadline = false;  // fewer than max_attempts ran because of options.should_stop
  std::string message;
};

// Precondition: check_ball(m).ok.
[[nodiscard]] ShellingResult find_shelling(const TetMesh& m, const ShellingOptions& options = {});

// Removability of live tet t within the remaining set (remaining[t] != 0, one flag per tet
// slot), per the rule above. `adj` = tet_adjacency(m).
[[nodiscard]] bool is_shelling_removable(const TetMesh& m, const TetAdjacency& adj, TetId t,
                                         const std::vector<char>& remaining, std::size_t remaining_count);

enum class ExpansionStepKind : std::uint8_t { plain_vertex, edge_split, face_split };

// One step of an expansion sequence: optionally split a simplex of the cell (creating
// `vertex`), then expand `vertex`. `split` holds the edge (2 ids) or face (3 ids) split, in the
// mesh as it is just before this step.
struct ExpansionStep {
  ExpansionStepKind kind = ExpansionStepKind::plain_vertex;
  TetId cell = invalid_tet;   // the shelling cell this step removes (input handle)
  std::array<VertexId, 3> split{invalid_vertex, invalid_vertex, invalid_vertex};
  VertexId vertex = invalid_vertex;  // the vertex expanded
  bool automatic = false;           // the very last vertex (expanded with the second-last)
};

struct ShellingExpansion {
  TetMesh mesh;                     // the input after all splits (vertex ids as in the steps)
  std::vector<ExpansionStep> steps;
  bool ok = false;
  std::string message;
};

// Alg. 2: every vertex (boundary included) starts unexpanded; for each cell of the shelling the
// cell is removed from the cluster mesh by expanding one vertex: the vertex opposite its only
// shared face (j = 1), a new vertex splitting the edge of its two free faces (j = 2), or a new
// vertex splitting its free face (j = 3). The last cell's vertices are expanded one by one.
// Splitting new vertices get ids num_vertices(), num_vertices()+1, ... in step order, so a caller
// replaying the steps with split_edge/split_face gets the same ids.
[[nodiscard]] ShellingExpansion shelling_to_expansion_sequence(const TetMesh& m, const std::vector<TetId>& shelling);

}  // namespace cmx::topology
