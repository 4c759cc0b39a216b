#include "algorithm/expansion/smoothing.hpp"

#include <algorithm>
#include <array>
#include <unordered_set>

#include "algorithm/expansion/expansion_cone.hpp"
#include "arith/rounding.hpp"

namespace cmx::algorithm {

namespace {

bool touches_cluster(const Embedding& e, VertexId b) {
  for (TetId t : e.mesh.tets_of(b))
    for (VertexId w : e.mesh.tet(t))
      if (e.unexpanded[w]) return true;
  return false;
}

}  // namespace

std::vector<VertexId> smoothing_candidates(const Embedding& e, const std::vector<VertexId>& recent) {
  std::vector<VertexId> movers;
  for (VertexId v : recent)
    for (TetId t : e.mesh.tets_of(v))
      for (VertexId b : e.mesh.tet(t))
        if (!e.unexpanded[b] && !e.boundary[b] && touches_cluster(e, b)) movers.push_back(b);
  std::sort(movers.begin(), movers.end());
  movers.erase(std::unique(movers.begin(), movers.end()), movers.end());
  return movers;
}

std::optional<HPoint> laplacian_position(const Embedding& e, VertexId v) {
  std::array<Rational, 3> sum{Rational(0), Rational(0), Rational(0)};
  std::unordered_set<VertexId> seen;
  for (TetId t : e.mesh.tets_of(v))
    for (VertexId w : e.mesh.tet(t)) {
      if (w == v || e.unexpanded[w] || !seen.insert(w).second) continue;
      for (int i = 0; i < 3; ++i) sum[std::size_t(i)] += e.target[w].coordinate(i);
    }
  if (seen.empty()) return std::nullopt;
  const ExpansionCone cone = gather_expansion_cone(e, v);
  std::array<Rational, 3> aim;
  for (int i = 0; i < 3; ++i) aim[std::size_t(i)] = sum[std::size_t(i)] / Rational(std::int64_t(seen.size()));
  for (int attempt = 0; attempt < 4; ++attempt) {
    std::array<Rational, 3> q;
    for (int i = 0; i < 3; ++i) q[std::size_t(i)] = round_to_dyadic(aim[std::size_t(i)], 53).value();
    const HPoint candidate = e.arith.round(HPoint(q[0], q[1], q[2]));
    if (!(candidate == e.target[v]) && strictly_inside(cone, candidate)) return candidate;
    for (int i = 0; i < 3; ++i)
      aim[std::size_t(i)] = (aim[std::size_t(i)] + e.target[v].coordinate(i)) / Rational(2);
  }
  return std::nullopt;
}

}  // namespace cmx::algorithm
