#include "algorithm/doubles/decrowd.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "arith/rounding.hpp"

namespace cmx::algorithm {

namespace {

// log2 of |q| (-infinity for 0), without underflow: crowds sit as deep as 2^-940 from p_c.
double log2_abs(const Rational& q) {
  if (sgn(q) == 0) return -std::numeric_limits<double>::infinity();
  long en = 0, ed = 0;
  const double mn = mpz_get_d_2exp(&en, q.get_num_mpz_t());
  const double md = mpz_get_d_2exp(&ed, q.get_den_mpz_t());
  return std::log2(std::abs(mn) / md) + static_cast<double>(en - ed);
}

// The scale of p's distance from p_c: log2 of its largest coordinate difference (within 1 of
// log2 of the distance). Only order and gaps matter.
double log2_distance(const HPoint& c, const HPoint& p) {
  double out = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) out = std::max(out, log2_abs(p.coordinate(i) - c.coordinate(i)));
  return out;
}

// Interior vertices (with tets) by increasing log2_distance from p_c, then by id.
std::vector<std::pair<double, VertexId>> by_distance(const Embedding& e,
                                                     const std::vector<VertexId>& vertices) {
  std::vector<std::pair<double, VertexId>> out;
  out.reserve(vertices.size());
  for (VertexId v : vertices) out.emplace_back(log2_distance(e.center, e.target[v]), v);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<VertexId> interior_vertices(const Embedding& e) {
  std::vector<VertexId> out;
  for (VertexId v{0}; v < e.num_vertices(); ++v)
    if (!e.boundary[v] && !e.mesh.tets_of(v).empty()) out.push_back(v);
  return out;
}

HPoint scaled(const HPoint& c, const HPoint& p, const Rational& factor) {
  Rational x[3];
  for (int i = 0; i < 3; ++i) x[i] = c.coordinate(i) + factor * (p.coordinate(i) - c.coordinate(i));
  return HPoint(x[0], x[1], x[2]);
}

// The tets with a vertex among `movers` (flagged in `inside`) and a vertex outside them.
std::vector<TetId> joining_tets(const Embedding& e, const std::vector<VertexId>& movers,
                                const std::vector<char>& inside) {
  std::vector<TetId> out;
  for (VertexId v : movers)
    for (TetId t : e.mesh.tets_of(v)) {
      const auto& tet = e.mesh.tet(t);
      if (std::any_of(tet.begin(), tet.end(), [&](VertexId w) { return !inside[w]; })) out.push_back(t);
    }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// Applies the homothety of ratio 2^k about p_c to `movers`; undoes it unless `tets` stay positive.
bool scale_if_positive(Embedding& e, const std::vector<VertexId>& movers, const std::vector<TetId>& tets,
                       int k) {
  const Rational factor(Integer(1) << k);
  std::vector<HPoint> before;
  before.reserve(movers.size());
  for (VertexId v : movers) {
    before.push_back(e.target[v]);
    e.target[v] = scaled(e.center, e.target[v], factor);
  }
  const bool ok = std::all_of(tets.begin(), tets.end(),
                              [&](TetId t) { return e.orient_target(e.mesh.tet(t)) == Sign::positive; });
  if (!ok)
    for (std::size_t i = 0; i < movers.size(); ++i) e.target[movers[i]] = before[i];
  return ok;
}

// The largest k in [0, most] found by bisection with 2^k applied; validity need not be monotone
// in k, but every factor applied was checked.
int scale_most(Embedding& e, const std::vector<VertexId>& movers, const std::vector<TetId>& tets, int most) {
  int lo = 0, hi = most;
  while (lo < hi) {
    const int k = (lo + hi + 1) / 2;
    if (scale_if_positive(e, movers, tets, k - lo))
      lo = k;
    else
      hi = k - 1;
  }
  return lo;
}

}  // namespace

std::size_t scale_crowds(Embedding& e) {
  if (!e.arith.exact()) return 0;
  const auto order = by_distance(e, interior_vertices(e));
  constexpr double min_gap = 3;       // log2 of a factor 8
  constexpr int max_exponent = 1100;  // beyond any double's range
  std::size_t applied = 0;
  std::vector<char> inside(e.num_vertices(), 0);
  std::vector<VertexId> movers;
  double radius = -std::numeric_limits<double>::infinity();  // log2, of `movers` after the homotheties so far
  for (std::size_t i = 0; i + 1 < order.size(); ++i) {
    inside[order[i].second] = 1;
    movers.push_back(order[i].second);
    radius = std::max(radius, order[i].first);
    const double next = order[i + 1].first;
    if (!std::isfinite(radius) || next - radius < min_gap) continue;
    // Below the gap: the crowd's radius stays under half the next vertex's distance.
    const int most = std::min(max_exponent, static_cast<int>(std::floor(next - radius)) - 1);
    const int k = most < 1 ? 0 : scale_most(e, movers, joining_tets(e, movers, inside), most);
    if (k == 0) continue;
    ++applied;
    radius += k;
  }
  return applied;
}

std::vector<VertexId> crowd_around_center(const Embedding& e) {
  double extent = -std::numeric_limits<double>::infinity();
  for (VertexId v{0}; v < e.num_vertices(); ++v)
    if (e.boundary[v] && !e.mesh.tets_of(v).empty())
      extent = std::max(extent, log2_distance(e.center, e.target[v]));
  std::vector<VertexId> out = interior_vertices(e);  // ascending ids
  std::erase_if(out, [&](VertexId v) { return !(log2_distance(e.center, e.target[v]) < extent - 10); });
  return out;
}

double innermost_log2_distance(const Embedding& e, const std::vector<VertexId>& crowd) {
  double out = std::numeric_limits<double>::infinity();
  for (VertexId v : crowd) out = std::min(out, log2_distance(e.center, e.target[v]));
  return out;
}

std::size_t sweep_crowd(Embedding& e, const std::vector<VertexId>& crowd, const PlacementOptions& options,
                        std::size_t& lps) {
  std::vector<std::pair<double, VertexId>> order;
  order.reserve(crowd.size());
  for (VertexId v : crowd) order.emplace_back(-log2_distance(e.center, e.target[v]), v);
  std::sort(order.begin(), order.end());  // farthest first, then by id
  std::size_t moved = 0;
  for (const auto& [d, v] : order) {
    ++lps;
    if (recentre(e, v, options)) ++moved;
  }
  return moved;
}

}  // namespace cmx::algorithm
