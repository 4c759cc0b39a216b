#include "generators/disjoint_paths.hpp"

#include <algorithm>
#include <cmath>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/successive_shortest_path_nonnegative_weights.hpp>

namespace cmx::generators {
namespace {

using Traits = boost::adjacency_list_traits<boost::vecS, boost::vecS, boost::directedS>;
using Graph = boost::adjacency_list<
    boost::vecS, boost::vecS, boost::directedS, boost::no_property,
    boost::property<boost::edge_capacity_t, long,
                    boost::property<boost::edge_residual_capacity_t, long,
                                    boost::property<boost::edge_reverse_t, Traits::edge_descriptor,
                                                    boost::property<boost::edge_weight_t, double>>>>>;

// The flow network: each vertex v split into in(v) = 2v and out(v) = 2v + 1 joined by an arc of
// capacity 1, so that at most one path passes through it; each edge {u, v} becomes the arcs
// out(u) -> in(v) and out(v) -> in(u). The targets have no inner arc (no path passes through
// them) but an arc in(t) -> sink each; `from` sends from out(from).
class Network {
 public:
  explicit Network(std::size_t vertices) : g_(2 * vertices + 1), sink_(2 * vertices) {}

  void add_arc(std::size_t a, std::size_t b, double cost) {
    const auto forward = boost::add_edge(a, b, g_).first;
    const auto backward = boost::add_edge(b, a, g_).first;
    boost::put(boost::edge_capacity, g_, forward, 1L);
    boost::put(boost::edge_capacity, g_, backward, 0L);
    boost::put(boost::edge_weight, g_, forward, cost);
    boost::put(boost::edge_weight, g_, backward, -cost);
    boost::put(boost::edge_reverse, g_, forward, backward);
    boost::put(boost::edge_reverse, g_, backward, forward);
  }
  static std::size_t in(std::uint32_t v) { return 2 * std::size_t{v}; }
  static std::size_t out(std::uint32_t v) { return 2 * std::size_t{v} + 1; }
  std::size_t sink() const { return sink_; }

  // Flow through arc a -> b (1 when a path uses it).
  bool carries(const Graph::edge_descriptor& e) const {
    return boost::get(boost::edge_capacity, g_, e) == 1 &&
           boost::get(boost::edge_residual_capacity, g_, e) == 0;
  }
  Graph& graph() { return g_; }
  const Graph& graph() const { return g_; }

 private:
  Graph g_;
  std::size_t sink_;
};

// The vertex a path leaves out(v) for, or -1.
long next_on_path(const Network& net, std::uint32_t v) {
  for (const auto& e : boost::make_iterator_range(boost::out_edges(Network::out(v), net.graph())))
    if (net.carries(e)) return static_cast<long>(boost::target(e, net.graph()) / 2);
  return -1;
}

}  // namespace

std::vector<std::vector<std::uint32_t>> disjoint_paths(
    const std::vector<std::vector<std::uint32_t>>& neighbors,
    const std::function<double(std::uint32_t, std::uint32_t)>& length, std::uint32_t from,
    std::span<const std::uint32_t> to, const std::vector<char>& blocked) {
  const std::size_t n = neighbors.size();
  std::vector<char> is_target(n, 0);
  for (auto t : to) is_target[t] = 1;
  Network net(n);
  for (std::uint32_t v = 0; v < n; ++v) {
    if (v != from && !is_target[v] && !blocked[v]) net.add_arc(Network::in(v), Network::out(v), 0);
    if (is_target[v]) net.add_arc(Network::in(v), net.sink(), 0);
  }
  // Integer-valued costs: the lengths scaled to 1 .. 2^20, so that every sum of potentials is exact
  // (with fractional costs the reduced costs round to tiny negative values, which the
  // shortest-path step refuses). They are stored as doubles all the same: the solver adds its
  // "unreached" distance (the type's maximum) to itself for vertices no path reaches, which
  // overflows a signed integer (undefined behaviour) but is a plain infinity in a double.
  std::vector<std::vector<double>> lengths(n);
  double longest = 0;
  for (std::uint32_t u = 0; u < n; ++u)
    for (auto v : neighbors[u]) longest = std::max(longest, lengths[u].emplace_back(length(u, v)));
  const auto cost = [&](double l) { return 1 + std::round(l / longest * 0x1p20); };
  for (std::uint32_t u = 0; u < n; ++u) {
    if (u != from && (is_target[u] || blocked[u])) continue;  // no path leaves a target or a blocked vertex
    for (std::size_t k = 0; k < neighbors[u].size(); ++k) {
      const auto v = neighbors[u][k];
      if (v != from && !blocked[v]) net.add_arc(Network::out(u), Network::in(v), cost(lengths[u][k]));
    }
  }
  boost::successive_shortest_path_nonnegative_weights(net.graph(), Network::out(from), net.sink());

  // Each arc that carries flow out of `from` starts one path; the chain of flow arcs from it
  // ends at the path's target.
  std::vector<std::vector<std::uint32_t>> by_target(to.size());
  for (const auto& e : boost::make_iterator_range(boost::out_edges(Network::out(from), net.graph()))) {
    if (!net.carries(e)) continue;
    std::vector<std::uint32_t> path{from};
    auto v = static_cast<std::uint32_t>(boost::target(e, net.graph()) / 2);
    while (!is_target[v]) {
      path.push_back(v);
      const long next = next_on_path(net, v);
      if (next < 0) return {};
      v = static_cast<std::uint32_t>(next);
    }
    path.push_back(v);
    for (std::size_t k = 0; k < to.size(); ++k)
      if (to[k] == v) by_target[k] = std::move(path);
  }
  for (const auto& p : by_target)
    if (p.empty()) return {};
  return by_target;
}

}  // namespace cmx::generators
