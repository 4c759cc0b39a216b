#include "algorithm/local/local_repair.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <mutex>

#include "algorithm/doubles/double_output.hpp"
#include "algorithm/local/initial_map.hpp"
#include "algorithm/local/stars.hpp"
#include "algorithm/map_error.hpp"
#include "algorithm/run_control.hpp"
#include "algorithm/tuning.hpp"
#include "algorithm/verify/output_statistics.hpp"
#include "arith/rounding.hpp"
#include "kernel/orient.hpp"
#include "topology/complex_queries.hpp"
#include "topology/indexed_tasks.hpp"

namespace cmx::algorithm {
namespace {

using Clock = std::chrono::steady_clock;
using topology::Tet;
using topology::TetId;
using topology::Triangle;
using topology::VertexId;

Point3 point_of(const HPoint& p) { return {p.coordinate(0), p.coordinate(1), p.coordinate(2)}; }

// One star as a problem of its own. Local vertex i is global vertex `global[i]` (the star's
// vertices in increasing order); its interior vertices are free, the others prescribed where the
// initial map put them.
struct StarProblem {
  MapProblem problem;
  std::vector<VertexId> global;
};

VertexId local_id(const std::vector<VertexId>& global, VertexId g) {
  return VertexId(std::lower_bound(global.begin(), global.end(), g) - global.begin());
}

StarProblem star_problem(const Star& star, const ValidatedProblem& v, const std::vector<HPoint>& target) {
  StarProblem sp;
  sp.global = star.vertices;
  for (TetId t : star.tets) {
    Tet x = v.mesh.tet(t);
    for (VertexId& w : x) w = local_id(sp.global, w);
    sp.problem.tets.push_back(x);
  }
  for (std::size_t i = 0; i < sp.global.size(); ++i) {
    const VertexId g = sp.global[i];
    sp.problem.source.push_back(point_of(v.source[g]));
    if (std::binary_search(star.interior.begin(), star.interior.end(), g)) continue;
    sp.problem.boundary_vertices.push_back(std::uint32_t(i));
    sp.problem.boundary_positions.push_back(point_of(target[g]));
  }
  return sp;
}

// What mapping one star gave: its result, or the exception it threw, and its trace rows.
struct StarRun {
  std::optional<MapResult> result;
  std::exception_ptr error;
  std::vector<TraceRow> trace;
};

// The star's options: the shrink method with everything else as the caller asked; the run's
// stop hook and time limit through the shared control (serialised: a hook need not be
// thread-safe), no progress of its own, trace rows kept to be replayed in star order.
MapOptions star_options(const MapOptions& options, std::mutex& lock, RunControl& control, StarRun& run,
                        std::size_t index) {
  MapOptions o = options;
  o.init = InitialMapKind::shrink;
  o.remap_doubles = false;
  o.time_limit_seconds = 0;
  o.progress = nullptr;
  o.stop = [&lock, &control](std::string_view) {
    const std::lock_guard<std::mutex> hold(lock);
    return control.should_stop("stars");
  };
  o.trace = nullptr;
  o.before_fallback = nullptr;  // stars run in threads; the hook is for a single global run
  o.threads = 1;                // the stars are what runs on the threads (a star's shelling search too)
  if (options.trace)
    o.trace = [&run, index](const TraceRow& row) {
      TraceRow r = row;
      r.star = index + 1;
      run.trace.push_back(r);
    };
  return o;
}

// Maps every star, `threads` at once; results in star order whatever the schedule.
std::vector<StarRun> map_stars(const std::vector<StarProblem>& problems, const MapOptions& options,
                               RunControl& control, std::size_t threads) {
  std::vector<StarRun> runs(problems.size());
  std::mutex lock;
  std::size_t done = 0;
  topology::run_indexed(problems.size(), threads, [&](std::size_t i) {
    try {
      runs[i].result = map_to_domain(problems[i].problem, star_options(options, lock, control, runs[i], i));
    } catch (...) {
      runs[i].error = std::current_exception();  // first_failure decides what it means
    }
    const std::lock_guard<std::mutex> hold(lock);
    control.report("stars", ++done, problems.size());
    return false;
  });
  return runs;
}

// The first star that did not map, as the outcome of the whole run (nullopt: all mapped).
std::optional<MapResult> first_failure(std::vector<StarRun>& runs) {
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::string star = "star " + std::to_string(i + 1) + " of " + std::to_string(runs.size());
    if (runs[i].error) {
      try {
        std::rethrow_exception(runs[i].error);
      } catch (const MapError& e) {
        // A star satisfies every condition of a problem by construction: not being one is a bug.
        throw MapError(MapErrorKind::internal, star + " is not a valid mapping problem: " + e.what());
      }
    }
    MapResult& r = *runs[i].result;
    if (r.outcome == MapOutcome::success) continue;
    MapResult out;
    out.outcome = r.outcome;
    out.message = star + ": " + r.message;
    out.loss = r.loss;
    return out;
  }
  return std::nullopt;
}

// Every counter of a star's run added to the whole run's (times are the caller's).
void add_counts(MapStatistics& into, const MapStatistics& s) {
  for (auto [a, b] : {std::pair{&into.split_topology, s.split_topology},
                      {&into.split_all_boundary_tet, s.split_all_boundary_tet},
                      {&into.split_no_shrink_point, s.split_no_shrink_point}, {&into.split_fallback, s.split_fallback},
                      {&into.expansions_simple, s.expansions_simple},
                      {&into.expansions_star_shapified, s.expansions_star_shapified},
                      {&into.expansions_inflated, s.expansions_inflated},
                      {&into.expansions_automatic, s.expansions_automatic},
                      {&into.expansions_subcluster, s.expansions_subcluster},
                      {&into.subcluster_expansions, s.subcluster_expansions},
                      {&into.subcluster_candidates, s.subcluster_candidates}, {&into.pushes, s.pushes},
                      {&into.bends, s.bends}, {&into.relaxations, s.relaxations},
                      {&into.shelled_star_shapifications, s.shelled_star_shapifications},
                      {&into.base_edge_splits, s.base_edge_splits},
                      {&into.shelled_pushes, s.shelled_pushes},
                      {&into.shelled_pushes_left, s.shelled_pushes_left},
                      {&into.smoothing_moves, s.smoothing_moves}, {&into.inflation_splits, s.inflation_splits},
                      {&into.isolated_inflations, s.isolated_inflations},
                      {&into.collapsed, s.collapsed}, {&into.merged, s.merged},
                      {&into.relocating_collapses, s.relocating_collapses}, {&into.flip_collapses, s.flip_collapses},
                      {&into.refinement_collapses, s.refinement_collapses},
                      {&into.chebyshev_moves, s.chebyshev_moves}, {&into.snap_exact_rounds, s.snap_exact_rounds},
                      {&into.snap_repaired, s.snap_repaired}, {&into.snap_rounds, s.snap_rounds},
                      {&into.snap_crowd_scalings, s.snap_crowd_scalings},
                      {&into.snap_crowd_sweeps, s.snap_crowd_sweeps},
                      {&into.snap_boundary_rerounded, s.snap_boundary_rerounded}, {&into.lps, s.lps},
                      {&into.lps_certified, s.lps_certified}, {&into.lps_fell_back, s.lps_fell_back},
                      {&into.lp_float_guesses, s.lp_float_guesses},
                      {&into.placements_float_centre, s.placements_float_centre},
                      {&into.closed_by_support, s.closed_by_support}})
    *a += b;
  for (int k = 0; k < 4; ++k) into.k_manifold[k] += s.k_manifold[k];
  into.merge_stopped_at_time_limit = into.merge_stopped_at_time_limit || s.merge_stopped_at_time_limit;
  into.filter += s.filter;
}

// A triangle rotated so that its smallest vertex comes first (same orientation): equal
// triangles compare equal.
Triangle canonical(Triangle t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

// The stitched map as it is being built: the input's vertices first (their positions as the
// initial map has them), then the vertices the stars added, star by star.
struct Stitched {
  std::vector<Tet> tets;
  std::vector<HPoint> source, target;
  std::vector<std::array<double, 3>> doubles;
  std::vector<char> moved;  // per vertex: interior to a star or added (its doubles are the star's)
  std::vector<VertexId> first_new;  // per star: the global id of its first added vertex
};

// The star's refined tets in place of its own; its boundary must be the star's, triangle for
// triangle (the method refines only inside a problem's boundary), else a bug.
void stitch_star(const Star& star, const StarProblem& sp, const MapResult& rs, Stitched& out) {
  std::vector<VertexId> global = sp.global;
  out.first_new.push_back(VertexId(out.target.size()));
  for (std::size_t i = sp.global.size(); i < rs.target.size(); ++i) {
    global.push_back(VertexId(out.target.size()));
    out.source.push_back(rs.source[i]);
    out.target.push_back(rs.target[i]);
    out.doubles.push_back(rs.doubles.target[i]);
    out.moved.push_back(1);
  }
  for (VertexId g : star.interior) {
    const VertexId i = local_id(sp.global, g);
    out.target[g] = rs.target[i];
    out.doubles[g] = rs.doubles.target[i];
    out.moved[g] = 1;
  }
  std::vector<Triangle> expected, got;
  for (const Triangle& f : star.boundary) expected.push_back(canonical(f));
  for (const topology::BoundaryFace& f : topology::boundary_faces(topology::TetMesh(rs.target.size(), rs.tets))) {
    Triangle t = f.face;
    for (VertexId& w : t) w = global[w];
    got.push_back(canonical(t));
  }
  std::sort(expected.begin(), expected.end());
  std::sort(got.begin(), got.end());
  if (expected != got) throw MapError(MapErrorKind::internal, "a star's map changed the star's boundary");
  for (Tet t : rs.tets) {
    for (VertexId& w : t) w = global[w];
    out.tets.push_back(t);
  }
}

// Tets outside the stars as they are, then each star's refinement; positions likewise.
Stitched stitch(const ValidatedProblem& v, const StarSet& stars, const std::vector<StarProblem>& problems,
                const std::vector<StarRun>& runs, const std::vector<HPoint>& target) {
  Stitched out;
  out.source = v.source;
  out.target = target;
  for (const HPoint& p : target) out.doubles.push_back(nearest_double(p));
  out.moved.assign(target.size(), 0);
  std::vector<char> in_star(v.mesh.tet_capacity(), 0);
  for (const Star& star : stars.stars)
    for (TetId t : star.tets) in_star[t] = 1;
  for (TetId t : v.mesh.live_tets())
    if (!in_star[t]) out.tets.push_back(v.mesh.tet(t));
  for (std::size_t k = 0; k < stars.stars.size(); ++k) stitch_star(stars.stars[k], problems[k], *runs[k].result, out);
  return out;
}

void star_statistics(const StarSet& stars, std::size_t input_tets, LocalRepairStatistics& ls) {
  ls.inverted = stars.inverted;
  ls.flat = stars.flat;
  ls.stars = stars.stars.size();
  ls.tets_in_stars = stars.tets_in_stars;
  for (const Star& star : stars.stars) ls.star_tets_max = std::max(ls.star_tets_max, star.tets.size());
  ls.star_tets_mean = stars.stars.empty() ? 0 : double(stars.tets_in_stars) / double(stars.stars.size());
  ls.share = input_tets ? double(stars.tets_in_stars) / double(input_tets) : 0;
}

// Tets of `tets` not positive in the doubles `at` (signs exact for those doubles).
std::size_t folded_in_doubles(const std::vector<Tet>& tets, const std::vector<std::array<double, 3>>& at) {
  std::size_t folded = 0;
  // A check of doubles: exact whatever --filter says, not counted.
  for (const Tet& t : tets)
    folded += orient3d(at[t[0]].data(), at[t[1]].data(), at[t[2]].data(), at[t[3]].data(),
                       PredicateContext::certain()) != Sign::positive;
  return folded;
}

// Why the map `at` (named `what`) is given up: more than `share` of the tets not positive in
// doubles. "" when it is kept.
std::string too_folded(const std::vector<Tet>& tets, const std::vector<std::array<double, 3>>& at, double share,
                       const char* what) {
  const std::size_t folded = folded_in_doubles(tets, at);
  if (double(folded) <= share * double(tets.size())) return {};
  return std::to_string(folded) + " of " + std::to_string(tets.size()) + " tets of " + what +
         " are inverted or flat in doubles, more than " + std::to_string(int(100 * share + 0.5)) + " %";
}

// The initial map, or nullopt with the reason in `why`. automatic: also nullopt when the Tutte
// map folds more than star_max_defect_share of the tets in doubles. That decision needs no exact
// signs and no rationals (the exact classification of a map that folds everywhere costs as much
// as solving it), so the map is taken exactly only once it is kept.
std::optional<std::vector<HPoint>> initial_target(const MapProblem& problem, const MapOptions& options,
                                                  LocalRepairStatistics& ls, std::string& why) {
  const bool automatic = options.init == InitialMapKind::automatic;
  const double limit = options.time_limit_seconds;
  const double max_flops = automatic && limit > 0 && std::isfinite(limit)
                               ? tuning::tutte_multiply_adds_per_second * limit / 2
                               : std::numeric_limits<double>::infinity();
  // auto: a map that an approximate solve already shows folding far too much is given up before
  // the factorisation (tuning::tutte_screen_multiply_adds).
  TutteScreen screen;
  screen.above_flops = options.tutte_screen_multiply_adds;
  screen.reject = [&](const std::vector<std::array<double, 3>>& approximate) {
    return too_folded(problem.tets, approximate, tuning::tutte_screen_fold_factor * options.star_max_defect_share,
                      "the Tutte map solved approximately (conjugate gradients, before a factorisation predicted "
                      "to be costly)");
  };
  InitialMap m = options.init == InitialMapKind::given
                     ? given_map(problem, problem.initial_target)
                     : tutte_map(problem, !automatic, max_flops, automatic ? &screen : nullptr);
  ls.init = options.init == InitialMapKind::given ? "given" : "tutte";
  ls.seconds_init = m.seconds;
  if (!m.ok) {
    why = m.screened_out ? "" : "the initial map could not be made: ";
    why += m.message;
    return std::nullopt;
  }
  if (automatic) {
    why = too_folded(problem.tets, m.doubles, options.star_max_defect_share, "the initial map");
    if (!why.empty()) return std::nullopt;
    exact_target(problem, m);
  }
  std::vector<HPoint> target;
  target.reserve(m.target.size());
  for (const Point3& p : m.target) target.emplace_back(p[0], p[1], p[2]);
  return target;
}

// The stars' trace rows, star by star, as rows of the whole run: steps counted on from the
// previous star's, vertices by their ids in the stitched map.
void replay_trace(const std::function<void(const TraceRow&)>& trace, const std::vector<StarProblem>& problems,
                  const std::vector<StarRun>& runs, const std::vector<VertexId>& first_new) {
  std::size_t steps = 0;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const std::vector<VertexId>& global = problems[k].global;
    for (TraceRow row : runs[k].trace) {
      row.vertex = row.vertex < global.size() ? global[row.vertex] : first_new[k] + (row.vertex - VertexId(global.size()));
      row.step += steps;
      trace(row);
    }
    steps += runs[k].trace.size();
  }
}

// Mapped stars stitched into the map of the whole problem (into r, whose input statistics the
// caller has filled), its doubles checked, verified.
void assemble(const MapProblem& problem, const ValidatedProblem& v, const MapOptions& options, const StarSet& stars,
              const std::vector<StarProblem>& problems, std::vector<StarRun>& runs, const std::vector<HPoint>& target,
              MapResult& r) {
  MapStatistics& s = r.stats;
  auto phase = Clock::now();
  for (const StarRun& run : runs) add_counts(s, run.result->stats);
  Stitched m = stitch(v, stars, problems, runs, target);
  s.local.seconds_stitch = seconds_since(phase);
  phase = Clock::now();
  r.doubles.target = std::move(m.doubles);
  r.doubles.checked = options.snap != SnapPolicy::none;
  if (r.doubles.checked) r.doubles.check = check_doubles(m.tets, r.doubles.target);
  for (const StarRun& run : runs) r.doubles.stopped_at_deadline |= run.result->doubles.stopped_at_deadline;
  s.seconds_double = seconds_since(phase);
  output_statistics(m.tets.size(), m.target, s);
  phase = Clock::now();
  VerificationInput in{&problem.tets, &v.source, &problem.boundary_vertices, &v.boundary_positions};
  r.verification = verify_map(in, m.tets, m.source, m.target);
  s.seconds_verify = seconds_since(phase);
  if (!r.verification.ok())
    throw MapError(MapErrorKind::internal, "the stitched map failed verification: " + r.verification.first_failure);
  r.outcome = MapOutcome::success;
  r.tets = std::move(m.tets);
  r.source = std::move(m.source);
  r.target = std::move(m.target);
  if (options.trace) replay_trace(options.trace, problems, runs, m.first_new);
}

// Automatic gives up the local path for the global one, saying why; an explicit choice of
// initial map cannot, and reports it.
bool fall_back(const MapOptions& options, LocalRepairStatistics& ls, const std::string& why, MapErrorKind kind) {
  if (options.init != InitialMapKind::automatic) throw MapError(kind, why);
  ls.fallback = why;
  ls.init = "shrink";
  return false;
}

}  // namespace

bool map_locally(const MapProblem& problem, const ValidatedProblem& v, const MapOptions& options, RunControl& control,
                 MapResult& r) {
  LocalRepairStatistics& ls = r.stats.local;
  std::string why;
  control.report("initial map", 0);
  const std::optional<std::vector<HPoint>> target = initial_target(problem, options, ls, why);
  if (!target) return fall_back(options, ls, why, MapErrorKind::invalid_input);
  auto phase = Clock::now();
  StarOptions so;
  // The whole mesh is always a star (the problem's own boundary): an explicit choice never gives up.
  const bool automatic = options.init == InitialMapKind::automatic;
  so.max_share = automatic ? options.star_max_share : 1.0;
  so.max_defect_share = automatic ? options.star_max_defect_share : 1.0;
  so.placement = options.placement;
  so.control = &control;
  const StarSet stars = grow_stars(v.mesh, *target, v.boundary, so);
  ls.seconds_classify_grow = seconds_since(phase);
  star_statistics(stars, problem.tets.size(), ls);
  if (!stars.ok && control.stopped()) {
    r.outcome = MapOutcome::time_limit;
    r.message = "time limit reached while growing stars";
    return true;
  }
  if (!stars.ok) return fall_back(options, ls, stars.message, MapErrorKind::internal);
  phase = Clock::now();
  std::vector<StarProblem> problems;
  for (const Star& star : stars.stars) problems.push_back(star_problem(star, v, *target));
  ls.threads = topology::thread_count(options.threads, problems.size());
  std::vector<StarRun> runs = map_stars(problems, options, control, ls.threads);
  ls.seconds_map_stars = seconds_since(phase);
  if (std::optional<MapResult> failed = first_failure(runs)) {
    r.outcome = failed->outcome;
    r.message = failed->message;
    r.loss = failed->loss;
    return true;
  }
  assemble(problem, v, options, stars, problems, runs, *target, r);
  return true;
}

}  // namespace cmx::algorithm
