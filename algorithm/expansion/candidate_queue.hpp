#pragma once
// The candidates of paper Alg. 1 line 5: the cluster vertices by class, then by the order of
// Sec. 4.1.2 (or `index`, `random:SEED`), deferred vertices after all others; in the planned order
// `strict-index` by vertex id first and class second. In a priority queue with lazy deletion (an entry is
// stale once its vertex's version has moved on, or once the vertex left the cluster), and the set of vertices
// whose star changed since they were last classified. Classification itself, which needs the cones and the
// LPs, is the loop's (ClusterExpander::evaluate, cluster_expansion.cpp).
#include <array>
#include <cstdint>
#include <optional>
#include <queue>
#include <vector>

#include "algorithm/embedding.hpp"
#include "topology/topological_expansion.hpp"

namespace cmx::algorithm::detail {

// The class of a candidate: simple expansions before star-shapification before inflation.
enum class Kind : std::uint8_t { automatic = 0, simple = 1, star_shapify = 2, inflate = 3 };

struct Entry {
  std::array<std::int64_t, 4> key;
  std::uint32_t version;
  VertexId v;
  Kind kind;
  std::uint8_t k;  // k-manifold expandability (0: other)
  bool operator>(const Entry& o) const { return key > o.key; }
};

class CandidateQueue {
 public:
  // The per-vertex state is a property of `e` and grows with it. `planned` > 0: a planned order,
  // the vertices below it by id before the class; vertices added during the run and automatic
  // expansions come first, and `order` breaks ties among them.
  CandidateQueue(Embedding& e, topology::ExpansionOrder order, std::size_t planned = 0);

  // v is to be classified again (once, however often it is marked before that).
  void mark(VertexId v);
  // Every cluster vertex of every tet around v, v included.
  void mark_star(VertexId v);
  // The last marked vertex, unmarked; none when no vertex is marked.
  std::optional<VertexId> take_marked();

  // Every entry of v queued so far is stale.
  void invalidate(VertexId v);
  // Queues v in class `kind` (k: its k-manifold expandability) under its current version.
  void push(VertexId v, Kind kind, int k, std::uint32_t expanded_neighbors);
  // The best entry that is current and whose vertex is still in the cluster.
  std::optional<Entry> pop();

 private:
  [[nodiscard]] std::array<std::int64_t, 4> key(Kind kind, int k, std::uint32_t expanded_neighbors,
                                                VertexId v) const;
  [[nodiscard]] std::array<std::int64_t, 4> order_key(Kind kind, int k, std::uint32_t expanded_neighbors,
                                                      VertexId v) const;
  [[nodiscard]] std::int64_t random_rank(VertexId v) const;  // v's place in the seeded permutation

  const Embedding& e_;
  topology::ExpansionOrder order_;
  std::size_t planned_;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue_;
  VertexProperty<std::uint32_t> version_;  // of v's queue entries
  VertexProperty<char> is_marked_;         // 1: v waits in marked_
  std::vector<VertexId> marked_;
};

}  // namespace cmx::algorithm::detail
