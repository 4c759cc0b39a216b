#include "algorithm/local/remap_doubles.hpp"

#include <string>
#include <utility>

#include "algorithm/verify/output_statistics.hpp"
#include "arith/rounding.hpp"
#include "topology/complex_queries.hpp"

namespace cmx::algorithm {

bool wants_remap_from_doubles(const MapOptions& options, const MapResult& r) {
  // applied_snap_policy is `nearest` for a non-exact arith: the repair, and so this, only in exact runs.
  return options.remap_doubles && applied_snap_policy(options) == SnapPolicy::repair &&
         r.outcome == MapOutcome::success && r.doubles.checked && !r.doubles.check.valid() &&
         !r.doubles.stopped_at_deadline;
}

MapProblem problem_from_doubles(const MapResult& r) {
  MapProblem p;
  p.tets = r.tets;
  const auto exact = [](const HPoint& q) { return Point3{q.coordinate(0), q.coordinate(1), q.coordinate(2)}; };
  for (const HPoint& q : r.source) p.source.push_back(exact(q));
  const std::vector<char> boundary = topology::boundary_vertex_flags(topology::TetMesh(r.source.size(), r.tets));
  for (std::uint32_t v = 0; v < boundary.size(); ++v)
    if (boundary[v]) {
      p.boundary_vertices.push_back(v);
      p.boundary_positions.push_back(exact(r.target[v]));
    }
  // The nearest doubles, not the repaired ones: the repair spreads its moves over the crowd's
  // neighbours, and the stars grown around them hold far more of the mesh than around the nearest
  // doubles (bench/results/map-local-repair.md, "gargoyle_star's doubles").
  const auto nearest = [](const Rational& q) { return rational_from_double(to_double(q)); };
  for (const HPoint& q : r.target)
    p.initial_target.push_back({nearest(q.coordinate(0)), nearest(q.coordinate(1)), nearest(q.coordinate(2))});
  return p;
}

namespace {

// r's statistics with the second pass's local repair, double output and time added.
MapStatistics merged_statistics(const MapResult& r, const MapResult& again, std::string fallback) {
  MapStatistics s = r.stats;
  s.local = again.stats.local;
  s.local.init = r.stats.local.init;
  s.local.fallback = std::move(fallback);
  // The star figures are the re-map's (what it re-mapped); the initial map's time is both passes'.
  s.local.seconds_init += r.stats.local.seconds_init;
  s.collapsed += again.stats.collapsed;
  s.chebyshev_moves = again.stats.chebyshev_moves, s.snap_repaired = again.stats.snap_repaired;
  s.snap_rounds = again.stats.snap_rounds, s.snap_exact_rounds = again.stats.snap_exact_rounds;
  s.seconds_double += again.stats.seconds_total;
  return s;
}

}  // namespace

void remap_from_doubles(const MapOptions& options, const VerificationInput& in, double time_left, MapResult& r) {
  const std::size_t bad = r.doubles.check.inverted + r.doubles.check.degenerate;
  MapOptions second = options;
  second.init = InitialMapKind::given;
  second.remap_doubles = false;
  second.time_limit_seconds = time_left;
  const std::string before = r.stats.local.fallback.empty() ? "" : r.stats.local.fallback + "; ";
  const std::string what = before + "the doubles left " + std::to_string(bad) + " tets inverted or flat; ";
  MapResult again = map_to_domain(problem_from_doubles(r), second);
  if (!(again.outcome == MapOutcome::success && again.doubles.check.valid())) {
    r.stats.local.fallback = what + "re-mapping from them gave no valid doubles either";
    return;
  }
  MapStatistics s = merged_statistics(r, again,
                                      what + "re-mapped from them (" + std::to_string(again.stats.local.stars) +
                                          " stars, " + std::to_string(again.stats.local.tets_in_stars) + " tets)");
  r.tets = std::move(again.tets);
  r.source = std::move(again.source);
  r.target = std::move(again.target);
  r.doubles = std::move(again.doubles);
  output_statistics(r.tets.size(), r.target, s);
  r.stats = s;
  r.verification = verify_map(in, r.tets, r.source, r.target);
  if (!r.verification.ok())
    throw MapError(MapErrorKind::internal, "re-mapped from its doubles, the map fails verification: " +
                                               r.verification.first_failure);
}

}  // namespace cmx::algorithm
