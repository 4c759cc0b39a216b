#include "algorithm/expansion/subcluster.hpp"

#include <algorithm>
#include <map>

#include "algorithm/tuning.hpp"
#include "lp/chebyshev_center.hpp"
#include "topology/tet_mesh.hpp"

namespace cmx::algorithm {

namespace {

// The face of tet t opposite its only mover, when the tet constrains the movers (exactly one of
// them in t, the other corners at pairwise distinct positions).
std::optional<topology::Triangle> constraining_face(const Embedding& e, const topology::Tet& tet,
                                                    const std::vector<VertexId>& movers) {
  int count = 0, at = -1;
  for (int i = 0; i < 4; ++i)
    if (std::find(movers.begin(), movers.end(), tet[std::size_t(i)]) != movers.end()) ++count, at = i;
  if (count != 1) return std::nullopt;
  const topology::Triangle f = topology::tet_face(tet, at);
  const HPoint &a = e.target[f[0]], &b = e.target[f[1]], &c = e.target[f[2]];
  if (a == b || b == c || a == c) return std::nullopt;
  return f;
}

// The tets around the movers, each once.
std::vector<TetId> tets_around(const Embedding& e, const std::vector<VertexId>& movers) {
  std::vector<TetId> out;
  for (VertexId m : movers)
    for (TetId t : e.mesh.tets_of(m)) out.push_back(t);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// Cheap screen before any exact work: the float Chebyshev LP of the same rows sees a clearly open
// kernel. A set the screen drops is only a missed opportunity.
bool looks_open(const Embedding& e, const std::vector<VertexId>& movers) {
  FloatCone cone;
  for (TetId t : tets_around(e, movers))
    if (const auto f = constraining_face(e, e.mesh.tet(t), movers))
      cone.rows.push_back(float_inner_row(e.target[(*f)[0]], e.target[(*f)[1]], e.target[(*f)[2]]));
  const lp::FloatChebyshev g = lp::float_chebyshev(cone.rows);
  return g.optimal && g.radius > tuning::subcluster_open_radius * g.scale;
}

bool usable(const Placement& p) {
  return p.ok() && !p.rounded_outside;
}

// With every vertex of `set` at q (unexpanded), moves them out one at a time, each the first in
// `set` order that satisfies Eq. (1) and whose cone has interior. Leaves the moved ones expanded.
std::optional<std::vector<SubclusterMove>> leave_one_by_one(Embedding& e, std::vector<VertexId> set,
                                                            const PlacementOptions& options,
                                                            topology::ClusterLinkWorkspace& ws,
                                                            SubclusterCounters& counters) {
  std::vector<SubclusterMove> moves;
  while (!set.empty()) {
    std::size_t i = 0;
    for (; i < set.size(); ++i) {
      const topology::ClusterVertexStatus st =
          topology::classify_cluster_vertex(e.mesh, set[i], e.unexpanded, ws);
      if (!st.expandable && st.unexpanded_link.vertices != 0) continue;
      ++counters.exact_lps;
      Placement p = place_in_cone(coincidence_cone(e, {set[i]}), options);
      if (!usable(p)) continue;
      e.target[set[i]] = p.position;
      e.unexpanded[set[i]] = 0;
      moves.push_back({set[i], std::move(p), st.manifold_k});
      break;
    }
    if (i == set.size()) return std::nullopt;
    set.erase(set.begin() + std::ptrdiff_t(i));
  }
  return moves;
}

std::optional<std::vector<SubclusterMove>> try_set(Embedding& e, const std::vector<VertexId>& set,
                                                   const PlacementOptions& options,
                                                   topology::ClusterLinkWorkspace& ws,
                                                   SubclusterCounters& counters) {
  ++counters.candidates;
  if (!looks_open(e, set)) return std::nullopt;
  ++counters.exact_lps;
  const Placement q = place_in_cone(coincidence_cone(e, set), options);
  if (!usable(q)) return std::nullopt;
  for (VertexId s : set) e.target[s] = q.position;
  std::optional<std::vector<SubclusterMove>> moves = leave_one_by_one(e, set, options, ws, counters);
  for (VertexId s : set) {
    e.target[s] = e.center;
    e.unexpanded[s] = 1;
  }
  return moves;
}

}  // namespace

ExpansionCone coincidence_cone(const Embedding& e, const std::vector<VertexId>& movers) {
  ExpansionCone cone;
  cone.apex = movers.front();
  for (TetId t : tets_around(e, movers)) {
    const auto f = constraining_face(e, e.mesh.tet(t), movers);
    if (!f) continue;
    InnerHalfSpace h = inner_halfspace(e.target[(*f)[0]], e.target[(*f)[1]], e.target[(*f)[2]]);
    if (h.is_degenerate()) cone.degenerate = true;
    cone.halfspaces.push_back(std::move(h));
    ++cone.base_tets;
  }
  return cone;
}

std::vector<std::vector<VertexId>> subcluster_candidates(const Embedding& e, VertexId v, std::size_t max_size,
                                                         const topology::ExpansionOrder& order) {
  // Cluster neighbours of v and how many of v's side tets (v and exactly one other cluster vertex)
  // each is in.
  std::map<VertexId, int> side;
  for (TetId t : e.mesh.tets_of(v)) {
    const topology::Tet& tet = e.mesh.tet(t);
    const int others = e.unexpanded_count(tet) - 1;
    for (VertexId w : tet)
      if (w != v && e.unexpanded[w] && (!order.deferred(w) || order.deferred(v)))
        side[w] += others == 1 ? 1 : 0;
  }
  std::vector<std::pair<int, VertexId>> ranked;
  for (const auto& [w, n] : side) ranked.emplace_back(-n, w);
  std::sort(ranked.begin(), ranked.end());
  if (ranked.size() > 4) ranked.resize(4);
  const std::size_t n = ranked.size();
  std::vector<std::vector<VertexId>> out;
  if (max_size >= 2)
    for (std::size_t i = 0; i < n; ++i) out.push_back({v, ranked[i].second});
  if (max_size >= 3)
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) out.push_back({v, ranked[i].second, ranked[j].second});
  if (max_size >= 4)
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        for (std::size_t k = j + 1; k < n; ++k)
          out.push_back({v, ranked[i].second, ranked[j].second, ranked[k].second});
  return out;
}

std::optional<std::vector<SubclusterMove>> plan_subcluster(Embedding& e, VertexId v, std::size_t max_size,
                                                           const PlacementOptions& options,
                                                           topology::ClusterLinkWorkspace& ws,
                                                           SubclusterCounters& counters,
                                                           const topology::ExpansionOrder& order) {
  for (const std::vector<VertexId>& set : subcluster_candidates(e, v, max_size, order))
    if (auto moves = try_set(e, set, options, ws, counters)) return moves;
  return std::nullopt;
}

}  // namespace cmx::algorithm
