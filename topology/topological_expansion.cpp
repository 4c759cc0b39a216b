#include "topology/topological_expansion.hpp"

#include <algorithm>
#include <charconv>
#include <numeric>
#include <queue>
#include <random>

#include "topology/cluster_links.hpp"
#include "topology/complex_queries.hpp"

namespace cmx::topology {

namespace {

// A whole decimal number of type T, nothing before or after it.
template <class T>
std::optional<T> parse_number(std::string_view digits) {
  T value = 0;
  const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || ec != std::errc{} || ptr != digits.data() + digits.size()) return std::nullopt;
  return value;
}

// The order without a deferral.
std::optional<ExpansionOrder> parse_base_order(std::string_view text) {
  if (text == "priority") return ExpansionOrder{ExpansionOrderKind::priority, 0};
  if (text == "index") return ExpansionOrder{ExpansionOrderKind::index, 0};
  if (text == "strict-index") return ExpansionOrder{ExpansionOrderKind::strict_index, 0};
  constexpr std::string_view prefix = "random:";
  if (text.substr(0, prefix.size()) != prefix) return std::nullopt;
  const std::optional<std::uint64_t> seed = parse_number<std::uint64_t>(text.substr(prefix.size()));
  if (!seed) return std::nullopt;
  return ExpansionOrder{ExpansionOrderKind::random, *seed};
}

std::string base_name(const ExpansionOrder& order) {
  switch (order.kind) {
    case ExpansionOrderKind::priority: return "priority";
    case ExpansionOrderKind::index: return "index";
    case ExpansionOrderKind::strict_index: return "strict-index";
    case ExpansionOrderKind::random: return "random:" + std::to_string(order.seed);
  }
  return "?";
}

}  // namespace

std::optional<ExpansionOrder> parse_expansion_order(std::string_view text) {
  constexpr std::string_view defer = ",defer:";
  const std::size_t at = text.find(defer);
  if (at == std::string_view::npos) return parse_base_order(text);
  std::optional<ExpansionOrder> order = parse_base_order(text.substr(0, at));
  const std::string_view range = text.substr(at + defer.size());
  const std::size_t dash = range.find('-');
  if (!order || dash == std::string_view::npos) return std::nullopt;
  const std::optional<std::uint32_t> first = parse_number<std::uint32_t>(range.substr(0, dash)),
                                     end = parse_number<std::uint32_t>(range.substr(dash + 1));
  if (!first || !end || *first >= *end) return std::nullopt;
  order->defer_first = *first;
  order->defer_end = *end;
  return order;
}

std::string to_string(const ExpansionOrder& order) {
  if (order.defer_first >= order.defer_end) return base_name(order);
  return base_name(order) + ",defer:" + std::to_string(order.defer_first) + "-" +
         std::to_string(order.defer_end);
}

namespace {

struct Entry {
  std::uint64_t key;
  VertexId v;
  std::uint32_t version;
  std::uint8_t k;  // manifold_k at evaluation time (still current when the entry is)
  bool operator>(const Entry& o) const { return key != o.key ? key > o.key : v > o.v; }
};

// Uniform draw in [0, bound) from raw 64-bit output (rejection sampling): std::uniform_int_
// distribution is implementation-defined, this is not.
std::uint64_t bounded(std::mt19937_64& rng, std::uint64_t bound) {
  const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max() -
                              std::numeric_limits<std::uint64_t>::max() % bound;
  std::uint64_t x;
  do x = rng();
  while (x >= limit);
  return x % bound;
}

// The cluster vertices to expand: the given flags (vertices of no tet dropped), or every
// interior vertex when none are given.
std::vector<char> initial_cluster(const TetMesh& m, std::span<const char> initially_unexpanded) {
  if (initially_unexpanded.empty()) return interior_vertex_flags(m);
  std::vector<char> unexp(m.num_vertices(), 0);
  for (std::size_t v = 0; v < unexp.size() && v < initially_unexpanded.size(); ++v)
    unexp[v] = (initially_unexpanded[v] != 0 && !m.tets_of(static_cast<VertexId>(v)).empty()) ? 1 : 0;
  return unexp;
}

// The rank of each vertex in a seeded random permutation (Fisher-Yates on mt19937_64).
std::vector<std::uint64_t> random_ranks(std::size_t n, std::uint64_t seed) {
  std::vector<std::uint64_t> rank(n);
  std::vector<VertexId> perm(n);
  std::iota(perm.begin(), perm.end(), VertexId{0});
  std::mt19937_64 rng(seed);
  for (std::size_t i = n; i > 1; --i) std::swap(perm[i - 1], perm[bounded(rng, i)]);
  for (std::size_t i = 0; i < n; ++i) rank[perm[i]] = i;
  return rank;
}

// Greedy topological expansion: a queue of expandable cluster vertices keyed by the order,
// re-evaluated lazily (versions) when a neighbour expands; isolated ones expand at once.
class GreedyExpansion {
 public:
  GreedyExpansion(const TetMesh& m, const ExpansionOrder& order, std::span<const char> initially_unexpanded)
      : m_(m), order_(order), unexp_(initial_cluster(m, initially_unexpanded)), version_(m.num_vertices(), 0) {
    cluster_ = static_cast<std::size_t>(std::count(unexp_.begin(), unexp_.end(), 1));
    r_.initial_cluster_vertices = cluster_;
    if (order.kind == ExpansionOrderKind::random) rank_ = random_ranks(m.num_vertices(), order.seed);
  }

  TopologicalExpansionResult run() {
    for (VertexId v{0}; v < m_.num_vertices(); ++v)
      if (unexp_[v]) evaluate(v);
    drain_automatic();
    while (cluster_ > 0) {
      const bool found = expand_next();
      drain_automatic();
      if (!found && cluster_ > 0) {
        r_.stuck = true;
        break;
      }
    }
    if (r_.stuck) report_remaining();
    return std::move(r_);
  }

 private:
  // The top bit puts deferred vertices after all others; every order's key fits below it.
  std::uint64_t key_of(VertexId v, const ClusterVertexStatus& st) const {
    const std::uint64_t deferred = order_.deferred(v) ? std::uint64_t{1} << 63 : 0;
    switch (order_.kind) {
      case ExpansionOrderKind::index:
      case ExpansionOrderKind::strict_index:
        return deferred | v;
      case ExpansionOrderKind::random:
        return deferred | rank_[v];
      case ExpansionOrderKind::priority: break;
    }
    const std::uint64_t cls = st.manifold_k == 0 ? 3 : static_cast<std::uint64_t>(st.manifold_k - 1);
    const std::uint64_t fewer = 0xffffu - std::min<std::uint32_t>(st.expanded_neighbors, 0xffffu);
    return deferred | (cls << 48) | (fewer << 32) | v;
  }

  void evaluate(VertexId v) {
    ++version_[v];
    if (!unexp_[v]) return;
    const ClusterVertexStatus st = classify_cluster_vertex(m_, v, unexp_, ws_);
    if (st.unexpanded_link.vertices == 0) automatic_.push_back(v);
    else if (st.expandable) queue_.push({key_of(v, st), v, version_[v], static_cast<std::uint8_t>(st.manifold_k)});
  }

  void expand(VertexId v, std::uint8_t k) {
    unexp_[v] = 0;
    --cluster_;
    ++version_[v];
    r_.sequence.push_back(v);
    r_.sequence_k.push_back(k);
    nbrs_.clear();
    for (TetId t : m_.tets_of(v))
      for (VertexId w : m_.tet(t))
        if (w != v && unexp_[w]) nbrs_.push_back(w);
    std::sort(nbrs_.begin(), nbrs_.end());
    nbrs_.erase(std::unique(nbrs_.begin(), nbrs_.end()), nbrs_.end());
    for (VertexId w : nbrs_) evaluate(w);  // evaluate() does not touch nbrs_
  }

  void drain_automatic() {
    while (!automatic_.empty()) {
      const VertexId v = automatic_.back();
      automatic_.pop_back();
      if (!unexp_[v]) continue;
      ++r_.automatic;
      expand(v, 255);
    }
  }

  // Expands the best current queue entry; false when none is current.
  bool expand_next() {
    while (!queue_.empty()) {
      const Entry e = queue_.top();
      queue_.pop();
      if (!unexp_[e.v] || e.version != version_[e.v]) continue;  // stale
      // The entry is current: v's link has not changed since it was evaluated.
      ++r_.k_manifold_counts[e.k];
      expand(e.v, e.k);
      return true;
    }
    return false;
  }

  void report_remaining() {
    for (VertexId v{0}; v < m_.num_vertices(); ++v)
      if (unexp_[v]) r_.remaining.push_back(v);
    const SubcomplexCounts c = subcomplex_counts(m_, VertexSubset(unexp_));
    r_.remaining_euler = c.euler;
    r_.remaining_components = c.components;
  }

  const TetMesh& m_;
  const ExpansionOrder& order_;
  std::vector<char> unexp_;
  std::vector<std::uint32_t> version_;
  std::vector<std::uint64_t> rank_;
  std::size_t cluster_ = 0;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue_;
  std::vector<VertexId> automatic_;  // isolated cluster vertices waiting to be expanded
  std::vector<VertexId> nbrs_;
  ClusterLinkWorkspace ws_;
  TopologicalExpansionResult r_;
};

}  // namespace

TopologicalExpansionResult topological_expansion(const TetMesh& m, const ExpansionOrder& order,
                                                 std::span<const char> initially_unexpanded) {
  return GreedyExpansion(m, order, initially_unexpanded).run();
}

}  // namespace cmx::topology
