#include "algorithm/doubles/double_output.hpp"

#include <algorithm>
#include <deque>
#include <limits>
#include <unordered_map>
#include <utility>

#include "algorithm/doubles/decrowd.hpp"
#include "algorithm/expansion/expansion_cone.hpp"
#include "algorithm/run_control.hpp"
#include "algorithm/tuning.hpp"
#include "arith/rounding.hpp"
#include "kernel/orient.hpp"

namespace cmx::algorithm {

namespace {
bool passed(RunControl* control) {
  return control && control->should_stop("doubles");
}
std::size_t bad_tets(const DoubleCheck& c) {
  return c.inverted + c.degenerate;
}
}  // namespace

ChebyshevPassResult chebyshev_pass(Embedding& e, const PlacementOptions& options, RunControl* control) {
  ChebyshevPassResult r;
  for (VertexId v{0}; v < e.num_vertices(); ++v) {
    if (e.boundary[v] || e.unexpanded[v] || e.mesh.tets_of(v).empty()) continue;
    if (control && control->step("doubles", v, e.num_vertices())) break;
    ++r.lps;
    if (recentre(e, v, options)) ++r.moved;
  }
  return r;
}

std::array<double, 3> nearest_double(const HPoint& p) {
  return {to_double(p.coordinate(0)), to_double(p.coordinate(1)), to_double(p.coordinate(2))};
}

namespace {

// One pass over the tets with the doubles: how many they invert or flatten, and the interior
// vertices of those tets, ascending (what the next repair round moves).
struct Scan {
  DoubleCheck check;
  std::vector<VertexId> offenders;
};

Scan scan(const Embedding& e, const std::vector<std::array<double, 3>>& doubles) {
  Scan out;
  for (TetId t : e.mesh.live_tets()) {
    const topology::Tet& tet = e.mesh.tet(t);
    const Sign s = orient3d(doubles[tet[0]].data(), doubles[tet[1]].data(), doubles[tet[2]].data(),
                            doubles[tet[3]].data(), PredicateContext::certain());  // a check of output
    if (s == Sign::positive) continue;
    ++(s == Sign::negative ? out.check.inverted : out.check.degenerate);
    for (VertexId v : tet)
      if (!e.boundary[v]) out.offenders.push_back(v);
  }
  std::sort(out.offenders.begin(), out.offenders.end());
  out.offenders.erase(std::unique(out.offenders.begin(), out.offenders.end()), out.offenders.end());
  return out;
}

// One repair round: each offending vertex in turn (Gauss-Seidel: later ones see earlier moves).
std::size_t repair_round(Embedding& d, const std::vector<VertexId>& offenders,
                         std::vector<std::array<double, 3>>& doubles, const PlacementOptions& options,
                         std::size_t& lps) {
  std::size_t moved = 0;
  for (VertexId v : offenders) {
    // A face opposite v that the doubles make degenerate (two of its vertices on one double point,
    // or three on one line) cannot be fixed by moving v: it is left to its own vertices, which
    // offend too, and v only has to keep its other tets positive.
    ExpansionCone cone = gather_expansion_cone(d, v);
    std::erase_if(cone.halfspaces, [](const InnerHalfSpace& h) { return h.is_degenerate(); });
    cone.degenerate = false;
    if (cone.halfspaces.empty()) continue;
    const lp::ChebyshevResult c = lp::chebyshev_center(lp_halfspaces(cone), options.lp);
    ++lps;
    if (c.status != lp::ChebyshevStatus::interior) continue;
    const std::array<double, 3> q = {to_double(c.center[0]), to_double(c.center[1]), to_double(c.center[2])};
    const HPoint qh = HPoint::from_doubles(q[0], q[1], q[2]);
    if (q == doubles[v] || !strictly_inside(cone, qh)) continue;
    doubles[v] = q;
    d.target[v] = qh;
    ++moved;
  }
  return moved;
}

// `movers` ordered by graph distance from the vertices that do not move (then by id): a crowd
// opens from its rim inward, each vertex then sees its outer neighbours already moved out, so one
// round spreads it much further than id order does.
std::vector<VertexId> outside_in(const Embedding& e, const std::vector<VertexId>& movers) {
  std::unordered_map<VertexId, std::size_t> dist;
  for (VertexId v : movers) dist[v] = std::numeric_limits<std::size_t>::max();
  std::deque<VertexId> queue;
  for (VertexId v : movers)
    for (TetId t : e.mesh.tets_of(v))
      for (VertexId w : e.mesh.tet(t))
        if (!dist.count(w) && dist[v] != 1) {
          dist[v] = 1;
          queue.push_back(v);
        }
  while (!queue.empty()) {
    const VertexId v = queue.front();
    queue.pop_front();
    for (TetId t : e.mesh.tets_of(v))
      for (VertexId w : e.mesh.tet(t)) {
        auto it = dist.find(w);
        if (it != dist.end() && it->second > dist[v] + 1) {
          it->second = dist[v] + 1;
          queue.push_back(w);
        }
      }
  }
  std::vector<VertexId> order = movers;
  std::sort(order.begin(), order.end(),
            [&](VertexId a, VertexId b) { return std::pair(dist[a], a) < std::pair(dist[b], b); });
  return order;
}

// Exact Gauss-Seidel moves of the interior vertices of offending tets and of their interior
// neighbours (the exact map stays valid). Vertices that the exact map crowds closer together than
// doubles can separate (near p_c) move apart a little with every round.
std::size_t local_exact_round(Embedding& e, const std::vector<VertexId>& offenders,
                              const PlacementOptions& options, std::size_t& lps) {
  std::vector<VertexId> movers;
  for (VertexId v : offenders) {
    movers.push_back(v);
    for (TetId t : e.mesh.tets_of(v))
      for (VertexId w : e.mesh.tet(t))
        if (!e.boundary[w]) movers.push_back(w);
  }
  std::sort(movers.begin(), movers.end());
  movers.erase(std::unique(movers.begin(), movers.end()), movers.end());
  std::size_t moved = 0;
  for (VertexId v : outside_in(e, movers)) {
    ++lps;
    if (recentre(e, v, options)) ++moved;
  }
  return moved;
}

// Rounds of `round(offenders)` (which moves vertices, returns how many and may change the
// doubles) with `rescan()` after each, until the doubles are valid, a round moves nothing, `cap`
// rounds, or `patience` rounds without fewer bad tets.
template <class Round, class Rescan>
void repair_rounds(Scan& now, std::size_t& rounds, std::size_t cap, RunControl* control, Round round,
                   Rescan rescan) {
  constexpr std::size_t patience = 3;
  std::size_t best = bad_tets(now.check), stale = 0;
  while (rounds < cap && !now.check.valid() && stale < patience && !passed(control)) {
    ++rounds;
    const std::size_t moved = round(now.offenders);
    now = rescan();
    if (moved == 0) break;
    if (bad_tets(now.check) < best)
      best = bad_tets(now.check), stale = 0;
    else
      ++stale;
  }
}

std::vector<std::array<double, 3>> nearest_doubles(const Embedding& e) {
  std::vector<std::array<double, 3>> out;
  out.reserve(e.num_vertices());
  for (const HPoint& p : e.target) out.push_back(nearest_double(p));
  return out;
}

bool all_boundary(const Embedding& e, const topology::Tet& t) {
  return e.boundary[t[0]] && e.boundary[t[1]] && e.boundary[t[2]] && e.boundary[t[3]];
}

bool positive(const std::vector<std::array<double, 3>>& d, const topology::Tet& t) {
  return orient3d(d[t[0]].data(), d[t[1]].data(), d[t[2]].data(), d[t[3]].data(),
                  PredicateContext::certain()) == Sign::positive;
}

// Boundary vertices never move, so a tet of four boundary vertices that the nearest doubles of
// prescribed positions invert or flatten (positions that are not doubles: P06) cannot be repaired
// through interior vertices. One of its vertices takes another of the up to eight doubles around
// its exact position instead (within one ulp in each coordinate) when that leaves fewer such tets
// around it; first vertex, then candidate (x, y, xy, z, ...) that does. Interior tets it spoils
// are the interior repair's to fix. Returns the vertices changed with their doubles.
std::vector<std::pair<VertexId, std::array<double, 3>>> reround_boundary(const Embedding& e) {
  std::vector<std::array<double, 3>> d = nearest_doubles(e);
  const auto bad_around = [&](VertexId v) {
    std::size_t n = 0;
    for (TetId t : e.mesh.tets_of(v))
      if (all_boundary(e, e.mesh.tet(t)) && !positive(d, e.mesh.tet(t))) ++n;
    return n;
  };
  std::vector<std::pair<VertexId, std::array<double, 3>>> changed;
  for (TetId t : e.mesh.live_tets()) {
    const topology::Tet& tet = e.mesh.tet(t);
    if (!all_boundary(e, tet) || positive(d, tet)) continue;
    for (VertexId v : tet) {
      const std::array<double, 3> nearest = d[v];
      // The double on the exact value's other side: the other end of the point's cached
      // enclosure (nearest itself when the coordinate is a double).
      std::array<double, 3> other;
      for (int i = 0; i < 3; ++i) {
        const DoubleEnclosure& b = e.target[v].enclosure(i);
        other[std::size_t(i)] = nearest[std::size_t(i)] == b.lo ? b.hi : b.lo;
      }
      const std::size_t before = bad_around(v);
      bool better = false;
      for (unsigned mask = 1; mask < 8 && !better; ++mask) {
        std::array<double, 3> c = nearest;
        bool possible = true;
        for (std::size_t i = 0; i < 3; ++i)
          if (mask & (1u << i)) {
            possible = possible && other[i] != nearest[i];
            c[i] = other[i];
          }
        if (!possible) continue;
        d[v] = c;
        better = bad_around(v) < before;
      }
      if (better) {
        changed.emplace_back(v, d[v]);
        break;
      }
      d[v] = nearest;
    }
  }
  return changed;
}

// The sweeps of one pass (below): until the doubles are valid, 300 sweeps, or 10 sweeps in which
// neither the bad tets fell nor the innermost vertex moved out by a factor 2 (a deep funnel
// opens for many sweeps before its bad tets fall); the crowd keeps the positions of the best
// sweep (a sweep can make the doubles worse).
template <class Rescan>
void sweep_until_stale(Embedding& e, Scan& now, DoubleMap& out, const std::vector<VertexId>& crowd,
                       const PlacementOptions& options, RunControl* control, Rescan rescan) {
  const auto positions = [&] {
    std::vector<HPoint> p;
    p.reserve(crowd.size());
    for (VertexId v : crowd) p.push_back(e.target[v]);
    return p;
  };
  constexpr std::size_t cap = 300, patience = 10;
  std::vector<HPoint> best_positions = positions();
  std::size_t best = bad_tets(now.check), stale = 0;
  double deepest = innermost_log2_distance(e, crowd);  // progress too: the crowd opening
  for (std::size_t sweeps = 0; sweeps < cap && stale < patience && !now.check.valid() && !passed(control);) {
    ++sweeps, ++out.crowd_sweeps;
    const std::size_t moved = sweep_crowd(e, crowd, options, out.lps);
    out.chebyshev_moves += moved;
    rescan();
    if (moved == 0) break;
    if (bad_tets(now.check) < best) {
      best = bad_tets(now.check), stale = 0;
      best_positions = positions();
    } else if (const double d = innermost_log2_distance(e, crowd); d >= deepest + 1) {
      deepest = d, stale = 0;  // the innermost vertex moved out by a factor 2 at least
    } else {
      ++stale;
    }
  }
  if (now.check.valid() || bad_tets(now.check) == best) return;
  for (std::size_t i = 0; i < crowd.size(); ++i) e.target[crowd[i]] = best_positions[i];
  rescan();
}

// The crowds around p_c (decrowd.hpp): passes of homotheties then sweeps from the outermost
// vertex inward, until the doubles are valid, 8 passes, or a pass without fewer bad tets. A
// pass's sweeps open gaps that the next pass's homotheties use, so the bad tets fall over several
// passes where one pass alone stalls.
template <class Rounded>
void open_crowds(Embedding& e, Scan& now, DoubleMap& out, const PlacementOptions& options,
                 RunControl* control, Rounded rounded) {
  const auto rescan = [&] {
    out.target = rounded();
    now = scan(e, out.target);
  };
  constexpr int max_passes = 8;
  for (int pass = 0; pass < max_passes && !now.check.valid() && !passed(control); ++pass) {
    const std::size_t before = bad_tets(now.check);
    const std::size_t scalings = scale_crowds(e);
    out.crowd_scalings += scalings;
    if (scalings > 0) rescan();
    const std::vector<VertexId> crowd = crowd_around_center(e);
    if (now.check.valid() || crowd.empty()) return;
    sweep_until_stale(e, now, out, crowd, options, control, rescan);
    if (bad_tets(now.check) >= before) return;
  }
}

DoubleMap snap_doubles(Embedding& e, SnapPolicy policy, const PlacementOptions& options,
                       RunControl* control) {
  DoubleMap out;
  if (policy == SnapPolicy::repair) {
    // The pass exists to make the doubles valid: when the plain rounding already is, it is the
    // answer (the pass costs a large share of a run, spent for nothing when the doubles are valid).
    out.target = nearest_doubles(e);
    out.checked = true;
    out.check = scan(e, out.target).check;
    if (out.check.valid()) return out;
    out = {};
  }
  // Only `repair` may leave the nearest doubles, and only on the boundary (reround_boundary).
  const std::vector<std::pair<VertexId, std::array<double, 3>>> reround =
      policy == SnapPolicy::repair ? reround_boundary(e) : decltype(reround_boundary(e)){};
  const auto rounded = [&] {
    std::vector<std::array<double, 3>> d = nearest_doubles(e);
    for (const auto& [v, q] : reround) d[v] = q;
    return d;
  };
  out.boundary_rerounded = reround.size();
  if (policy == SnapPolicy::chebyshev_pass || policy == SnapPolicy::repair) {
    const ChebyshevPassResult pass = chebyshev_pass(e, options, control);
    out.chebyshev_moves = pass.moved;
    out.lps += pass.lps;
  }
  out.target = rounded();
  if (policy == SnapPolicy::none) return out;
  out.checked = true;
  Scan now = scan(e, out.target);
  out.check = now.check;
  if (policy != SnapPolicy::repair || now.check.valid()) return out;

  open_crowds(e, now, out, options, control, rounded);
  out.check = now.check;
  if (now.check.valid()) return out;

  // First in the exact map, where every move is safe; then among the doubles (algorithm/tuning.hpp).
  repair_rounds(
      now, out.exact_rounds, tuning::exact_repair_rounds, control,
      [&](const std::vector<VertexId>& offenders) {
        const std::size_t moved = local_exact_round(e, offenders, options, out.lps);
        out.chebyshev_moves += moved;
        out.target = rounded();
        return moved;
      },
      [&] { return scan(e, out.target); });
  out.check = now.check;
  if (now.check.valid()) return out;

  // The double map as an embedding of its own (exact positions = the doubles), so that cones are
  // read with every neighbour where the doubles put it.
  Embedding d;
  d.mesh = e.mesh;
  d.boundary = e.boundary;
  d.unexpanded.assign(e.num_vertices(), 0);
  d.filter = e.filter;
  d.target.reserve(e.num_vertices());
  for (const auto& q : out.target) d.target.push_back(HPoint::from_doubles(q[0], q[1], q[2]));
  repair_rounds(
      now, out.rounds, tuning::double_repair_rounds, control,
      [&](const std::vector<VertexId>& offenders) {
        const std::size_t moved = repair_round(d, offenders, out.target, options, out.lps);
        out.repaired += moved;
        return moved;
      },
      [&] { return scan(d, out.target); });
  out.check = now.check;
  return out;
}

}  // namespace

DoubleMap make_double_map(Embedding& e, SnapPolicy policy, const PlacementOptions& options,
                          RunControl* control) {
  const std::vector<HPoint> before = control && control->can_stop() ? e.target : std::vector<HPoint>{};
  DoubleMap out = snap_doubles(e, policy, options, control);
  if (!out.checked || out.check.valid() || !passed(control)) return out;
  // Cut short by the time limit: where it stopped depends on timing, so undo every move and give
  // the plain rounding of the exact map as it was (the same whenever the limit is hit).
  e.target = before;
  DoubleMap plain = snap_doubles(e, SnapPolicy::nearest, options, {});
  plain.stopped_at_deadline = true;
  plain.lps = out.lps;
  return plain;
}

}  // namespace cmx::algorithm
