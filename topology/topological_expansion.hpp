#pragma once
// Topological expansion (paper Sec. 5.1): expand the cluster mesh greedily by Eq. (1) alone,
// without geometry (no star-shapification, no inflation).
//
// Order:
//   priority : paper Sec. 4.1.2 without the geometric criteria: k-manifold-expandable vertices
//              with lower k first (1, 2, 3, then Eq.(1)-expandable but not k-manifold), then more
//              expanded neighbours first (larger expansion cone), then lower vertex id.
//   index    : the expandable vertex with the lowest id.
//   strict-index : the same here (topological expansion has no classes); cmx map puts the id
//              before the class (algorithm/expansion/candidate_queue.hpp).
//   random:S : the expandable vertex first in a random permutation of the vertices drawn from
//              std::mt19937_64(S) (Fisher-Yates with our own bounded draw: platform-independent).
//   ,defer:A-B after any of them: the vertices with ids in [A, B) only when no other is
//              expandable (ExpansionOrder::deferred).
// After each expansion only the unexpanded neighbours of the expanded vertex are re-evaluated
// (lazy-deletion priority queue). A cluster vertex whose Lk• became empty (an isolated cluster
// vertex, e.g. the last one) is expanded automatically (paper Sec. 3).
// Cost: O(sum over expansions of d log d) = O(T log d) for bounded valence.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "topology/tet_mesh.hpp"

namespace cmx::topology {

enum class ExpansionOrderKind : std::uint8_t { priority, index, random, strict_index };

struct ExpansionOrder {
  ExpansionOrderKind kind = ExpansionOrderKind::priority;
  std::uint64_t seed = 0;  // random only
  // Vertices with ids in [defer_first, defer_end) come after every other expandable vertex, in
  // the same order among themselves: how an experiment steers expansion into a configuration it
  // built (bings_house_in_box numbers its house last). Empty by default.
  std::uint32_t defer_first = 0, defer_end = 0;
  [[nodiscard]] bool deferred(VertexId v) const { return v.idx() >= defer_first && v.idx() < defer_end; }
};

// "priority", "index", "strict-index" or "random:SEED" (SEED a decimal uint64), optionally
// followed by ",defer:A-B" (decimal ids, A < B: the range [A, B) is deferred). nullopt when
// malformed.
[[nodiscard]] std::optional<ExpansionOrder> parse_expansion_order(std::string_view text);
// What parse_expansion_order takes, for the messages that reject something else.
inline constexpr std::string_view expansion_order_syntax =
    "priority, index, strict-index or random:SEED, each optionally followed by ,defer:A-B with A < B";
[[nodiscard]] std::string to_string(const ExpansionOrder& order);

struct TopologicalExpansionResult {
  std::vector<VertexId> sequence;           // expanded vertices in order (automatic ones included)
  std::vector<std::uint8_t> sequence_k;     // per entry: 1,2,3 k-manifold, 0 other Eq.(1), 255 automatic
  // k_manifold_counts[k] for k = 1,2,3; [0] = expandable by Eq. (1) but not k-manifold.
  std::array<std::size_t, 4> k_manifold_counts{};
  std::size_t automatic = 0;                // isolated cluster vertices expanded automatically
  std::size_t initial_cluster_vertices = 0;
  // Stuck: the cluster mesh is non-empty, has >= 2 vertices and no vertex satisfies Eq. (1).
  // When the initial cluster mesh is simply connected this is a NOBUENOSS (Corollary 1).
  bool stuck = false;
  std::vector<VertexId> remaining;          // cluster vertices left when stuck, ascending
  std::int64_t remaining_euler = 0;         // chi and b0 of the remaining cluster mesh
  std::size_t remaining_components = 0;
  [[nodiscard]] std::size_t length() const { return sequence.size(); }
};

// Expands the cluster mesh of `initially_unexpanded` (one flag per vertex; empty = the interior
// vertices of m, the paper's setting). The mesh is not modified.
[[nodiscard]] TopologicalExpansionResult topological_expansion(const TetMesh& m, const ExpansionOrder& order,
                                                               std::span<const char> initially_unexpanded = {});

}  // namespace cmx::topology
