#include "algorithm/local/remap_doubles.hpp"

#include <optional>
#include <string>
#include <utility>

#include "algorithm/run_control.hpp"
#include "algorithm/tuning.hpp"
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

// r's statistics with the last pass's local repair and double output, and the passes' time added.
// `seconds` is the time of every pass, the last one's included.
MapStatistics merged_statistics(const MapResult& r, const MapResult& again, std::string fallback, double seconds) {
  MapStatistics s = r.stats;
  s.local = again.stats.local;
  s.local.init = r.stats.local.init;
  s.local.fallback = std::move(fallback);
  // The star figures are the last pass's (what it re-mapped); the initial map's time is the first
  // map's and the last pass's.
  s.local.seconds_init += r.stats.local.seconds_init;
  s.collapsed += again.stats.collapsed;
  s.chebyshev_moves = again.stats.chebyshev_moves, s.snap_repaired = again.stats.snap_repaired;
  s.snap_rounds = again.stats.snap_rounds, s.snap_exact_rounds = again.stats.snap_exact_rounds;
  s.seconds_double += seconds;
  return s;
}

std::size_t bad_doubles(const MapResult& r) { return r.doubles.check.inverted + r.doubles.check.degenerate; }

// A map whose doubles were checked to the end: only then is its count of bad tets one to compare.
bool doubles_checked_to_the_end(const MapResult& again) {
  return again.outcome == MapOutcome::success && again.doubles.checked && !again.doubles.stopped_at_deadline;
}

}  // namespace

bool improves_on(std::size_t fewest_bad, const MapResult& again) {
  return doubles_checked_to_the_end(again) && bad_doubles(again) < fewest_bad;
}

RemapStep after_remap_pass(std::size_t passes, std::size_t fewest_bad, const MapResult& again) {
  if (!doubles_checked_to_the_end(again)) return RemapStep::stop;
  if (again.doubles.check.valid()) return RemapStep::adopt;
  return improves_on(fewest_bad, again) && passes < tuning::doubles_remap_passes ? RemapStep::go_on
                                                                                 : RemapStep::stop;
}

void remap_from_doubles(const MapOptions& options, const VerificationInput& in, double time_left, MapResult& r) {
  const RunControl::Clock::time_point start = RunControl::Clock::now();
  const std::size_t bad = bad_doubles(r);
  MapOptions second = options;
  second.init = InitialMapKind::given;
  second.remap_doubles = false;
  const std::string before = r.stats.local.fallback.empty() ? "" : r.stats.local.fallback + "; ";
  const std::string what = before + "the doubles left " + std::to_string(bad) + " tets inverted or flat; ";
  // A pass that leaves fewer bad tets but some is the start of the next: its stars are smaller,
  // around what it left (a different stall or order in one star's map can leave a crowd of its
  // own, bench/results/issue21-thin-combinatorial.md). Passes end when the count stops falling.
  // `last` is where the next pass starts, and the pass with the fewest bad tets so far (a pass
  // goes on only from fewer than before): it is kept when no pass gives valid doubles but it
  // leaves fewer than the first map. A pass that stops the passes because none is left can
  // still be the best one.
  std::optional<MapResult> last;
  std::size_t passes = 0, last_bad = bad;
  std::string counts = std::to_string(bad);  // inverted or flat tets after each pass
  for (RemapStep step = RemapStep::go_on; step == RemapStep::go_on;) {
    second.time_limit_seconds = 0;
    if (time_left > 0) {
      second.time_limit_seconds = time_left - seconds_since(start);
      if (second.time_limit_seconds <= 0) break;
    }
    MapResult again = map_to_domain(problem_from_doubles(last ? *last : r), second);
    step = after_remap_pass(++passes, last_bad, again);
    if (again.outcome == MapOutcome::success && again.doubles.checked)
      counts += " -> " + std::to_string(bad_doubles(again));
    if (step == RemapStep::stop && !improves_on(last_bad, again)) break;
    last_bad = bad_doubles(again);
    last = std::move(again);
  }
  const std::string in_passes =
      passes > 1 ? " in " + std::to_string(passes) + " passes (inverted or flat: " + counts + ")" : "";
  if (!last) {
    r.stats.local.fallback = what + "re-mapping from them" + in_passes + " gave no valid doubles either";
    return;
  }
  MapResult& again = *last;
  std::string done = what + "re-mapped from them" + in_passes + " (" +
                     std::to_string(again.stats.local.stars) + " stars, " +
                     std::to_string(again.stats.local.tets_in_stars) + " tets)";
  if (!again.doubles.check.valid())
    done +=
        "; no valid doubles either: kept the pass that left the fewest (" + std::to_string(last_bad) + ")";
  MapStatistics s = merged_statistics(r, again, std::move(done), seconds_since(start));
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
