#include "topology/topological_expansion.hpp"

#include <algorithm>
#include <charconv>
#include <numeric>
#include <queue>
#include <random>

#include "topology/cluster_links.hpp"
#include "topology/complex_queries.hpp"

namespace cmx::topology {

std::optional<ExpansionOrder> parse_expansion_order(std::string_view text) {
  if (text == "priority") return ExpansionOrder{ExpansionOrderKind::priority, 0};
  if (text == "index") return ExpansionOrder{ExpansionOrderKind::index, 0};
  constexpr std::string_view prefix = "random:";
  if (text.substr(0, prefix.size()) == prefix) {
    const std::string_view digits = text.substr(prefix.size());
    std::uint64_t seed = 0;
    const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), seed);
    if (digits.empty() || ec != std::errc{} || ptr != digits.data() + digits.size()) return std::nullopt;
    return ExpansionOrder{ExpansionOrderKind::random, seed};
  }
  return std::nullopt;
}

std::string to_string(const ExpansionOrder& order) {
  switch (order.kind) {
    case ExpansionOrderKind::priority: return "priority";
    case ExpansionOrderKind::index: return "index";
    case ExpansionOrderKind::random: return "random:" + std::to_string(order.seed);
  }
  return "?";
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

}  // namespace

TopologicalExpansionResult topological_expansion(const TetMesh& m, const ExpansionOrder& order,
                                                 std::span<const char> initially_unexpanded) {
  TopologicalExpansionResult r;
  const std::size_t n = m.num_vertices();
  std::vector<char> unexp;
  if (initially_unexpanded.empty()) unexp = interior_vertex_flags(m);
  else {
    unexp.assign(n, 0);
    for (std::size_t v = 0; v < n && v < initially_unexpanded.size(); ++v)
      unexp[v] = (initially_unexpanded[v] != 0 && !m.tets_of(static_cast<VertexId>(v)).empty()) ? 1 : 0;
  }
  std::size_t cluster = static_cast<std::size_t>(std::count(unexp.begin(), unexp.end(), 1));
  r.initial_cluster_vertices = cluster;

  std::vector<std::uint64_t> rank;
  if (order.kind == ExpansionOrderKind::random) {
    rank.resize(n);
    std::vector<VertexId> perm(n);
    std::iota(perm.begin(), perm.end(), 0u);
    std::mt19937_64 rng(order.seed);
    for (std::size_t i = n; i > 1; --i) std::swap(perm[i - 1], perm[bounded(rng, i)]);
    for (std::size_t i = 0; i < n; ++i) rank[perm[i]] = i;
  }

  std::vector<std::uint32_t> version(n, 0);
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  std::vector<VertexId> automatic;  // isolated cluster vertices waiting to be expanded
  ClusterLinkWorkspace ws;

  auto key_of = [&](VertexId v, const ClusterVertexStatus& st) -> std::uint64_t {
    switch (order.kind) {
      case ExpansionOrderKind::index: return v;
      case ExpansionOrderKind::random: return rank[v];
      case ExpansionOrderKind::priority: break;
    }
    const std::uint64_t cls = st.manifold_k == 0 ? 3 : static_cast<std::uint64_t>(st.manifold_k - 1);
    const std::uint64_t fewer = 0xffffu - std::min<std::uint32_t>(st.expanded_neighbors, 0xffffu);
    return (cls << 48) | (fewer << 32) | v;
  };
  auto evaluate = [&](VertexId v) {
    ++version[v];
    if (!unexp[v]) return;
    const ClusterVertexStatus st = classify_cluster_vertex(m, v, unexp, ws);
    if (st.unexpanded_link.vertices == 0) {
      automatic.push_back(v);
    } else if (st.expandable) {
      queue.push({key_of(v, st), v, version[v], static_cast<std::uint8_t>(st.manifold_k)});
    }
  };
  std::vector<std::uint8_t> k_at(n, 0);
  std::vector<VertexId> nbrs;
  auto expand = [&](VertexId v, std::uint8_t k) {
    unexp[v] = 0;
    --cluster;
    ++version[v];
    r.sequence.push_back(v);
    r.sequence_k.push_back(k);
    nbrs.clear();
    for (TetId t : m.tets_of(v))
      for (VertexId w : m.tet(t))
        if (w != v && unexp[w]) nbrs.push_back(w);
    std::sort(nbrs.begin(), nbrs.end());
    nbrs.erase(std::unique(nbrs.begin(), nbrs.end()), nbrs.end());
    for (VertexId w : nbrs) evaluate(w);  // evaluate() does not touch nbrs
  };
  auto drain_automatic = [&] {
    while (!automatic.empty()) {
      const VertexId v = automatic.back();
      automatic.pop_back();
      if (!unexp[v]) continue;
      ++r.automatic;
      expand(v, 255);
    }
  };

  for (VertexId v = 0; v < n; ++v)
    if (unexp[v]) evaluate(v);
  drain_automatic();
  while (cluster > 0) {
    bool found = false;
    while (!queue.empty()) {
      const Entry e = queue.top();
      queue.pop();
      if (!unexp[e.v] || e.version != version[e.v]) continue;  // stale
      found = true;
      // The entry is current: v's link has not changed since it was evaluated.
      ++r.k_manifold_counts[e.k];
      expand(e.v, e.k);
      break;
    }
    drain_automatic();
    if (!found && cluster > 0) {
      r.stuck = true;
      break;
    }
  }
  if (r.stuck) {
    for (VertexId v = 0; v < n; ++v)
      if (unexp[v]) r.remaining.push_back(v);
    const SubcomplexCounts c = subcomplex_counts(m, VertexSubset(unexp));
    r.remaining_euler = c.euler;
    r.remaining_components = c.components;
  }
  return r;
}

}  // namespace cmx::topology
