#include "algorithm/map.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "algorithm/expansion/cluster_expansion.hpp"
#include "algorithm/collapse/collapse_pass.hpp"
#include "algorithm/embedding.hpp"
#include "algorithm/verify/invariants.hpp"
#include "algorithm/local/local_repair.hpp"
#include "algorithm/local/remap_doubles.hpp"
#include "algorithm/collapse/merge_pass.hpp"
#include "algorithm/verify/output_statistics.hpp"
#include "algorithm/problem/preprocess.hpp"
#include "algorithm/refinement/shelling_fallback.hpp"
#include "algorithm/run_control.hpp"
#include "algorithm/problem/validate_problem.hpp"
#include "algorithm/verify/verify_map.hpp"
#include "algorithm/tuning.hpp"
#include "arith/rational.hpp"
#include "arith/rounding.hpp"
#include "topology/complex_queries.hpp"
#include "topology/cluster_links.hpp"

namespace cmx::algorithm {

const char* to_string(MapOutcome o) {
  switch (o) {
    case MapOutcome::success: return "success";
    case MapOutcome::time_limit: return "time_limit";
    case MapOutcome::stuck: return "stuck";
    case MapOutcome::precision_lost: return "precision_lost";
  }
  return "?";
}

// A non-exact run's coordinates are its output: the doubles are their plain rounding, checked.
SnapPolicy applied_snap_policy(const MapOptions& options) {
  return options.placement.arith.exact() ? options.snap : SnapPolicy::nearest;
}

namespace {

using Clock = std::chrono::steady_clock;

double boundary_extent(const std::vector<HPoint>& points) {
  if (points.empty()) return 0;
  std::array<double, 3> lo = points[0].approx(), hi = lo;
  for (const HPoint& p : points) {
    const auto a = p.approx();
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], a[i]), hi[i] = std::max(hi[i], a[i]);
  }
  return std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
}

// A non-exact run reads its input as a program in that arithmetic would: every coordinate
// rounded to nearest. The rounded problem is what it maps and what its result is verified against;
// the report counts the coordinates that moved. Returns that count.
std::size_t round_problem(MapProblem& p, const CoordinateArith& arith) {
  std::size_t moved = 0;
  auto round = [&](Point3& q) {
    for (Rational& c : q) {
      Rational r = arith.round(c);
      if (r != c) ++moved, c = std::move(r);
    }
  };
  for (Point3& q : p.source) round(q);
  for (Point3& q : p.boundary_positions) round(q);
  return moved;
}

void fill_output(const Embedding& e, MapResult& r) {
  r.tets.reserve(e.mesh.num_tets());
  for (TetId t : e.mesh.live_tets()) r.tets.push_back(e.mesh.tet(t));
  r.source = e.source;
  r.target = e.target;
  r.parents = e.parents;
  r.origin = e.origin;
  output_statistics(e.mesh.num_tets(), e.target, r.stats);
}

}  // namespace

namespace {

// Preprocessing and shrink (invariants asserted once): the state expansion starts from.
void preprocess(Embedding& e, const ValidatedProblem& v, const MapOptions& options, std::vector<HPoint>& prescribed,
                MapResult& r) {
  MapStatistics& s = r.stats;
  const PreprocessResult pre = preprocess_and_shrink(e, v, options.placement);
  s.split_topology = pre.split_topology;
  s.split_fallback = pre.split_fallback;
  s.split_all_boundary_tet = pre.split_all_boundary_tet;
  s.split_no_shrink_point = pre.split_no_shrink_point;
  s.lps += pre.lps;
  s.vertices_after_preprocess = e.num_vertices();
  s.tets_after_preprocess = e.mesh.num_tets();
  prescribed = v.prescribed;
  prescribed.resize(e.num_vertices());
  if (std::string why = check_invariants(e, prescribed); !why.empty())
    throw MapError(MapErrorKind::internal, "the shrunk state breaks an invariant: " + why);
  s.degenerate_after_shrink = topology::count_degenerate_tets(e.mesh, e.unexpanded);
  s.shrink_radius = pre.shrink_radius;
  s.boundary_extent = boundary_extent(v.boundary_positions);
  r.center = e.center;
}

ExpansionSettings expansion_settings(const MapOptions& options, Clock::time_point start, RunControl& control,
                                     const std::vector<HPoint>& prescribed, std::size_t input_vertices) {
  ExpansionSettings settings;
  settings.placement = options.placement;
  settings.order = options.order;
  settings.check = options.check;
  settings.start = start;
  settings.control = &control;
  settings.progress = options.progress;
  settings.trace = options.trace;
  settings.smooth_every = options.smooth_every;
  settings.collapse_after_refinement = options.collapse_refinement;
  settings.shelled = options.shelled;
  settings.replay = options.replay;
  settings.subcluster_size = options.subclusters;
  settings.before_fallback = options.before_fallback;
  settings.threads = options.threads;
  settings.prescribed = &prescribed;  // read for boundary vertices only; new vertices are interior
  settings.input_vertices = input_vertices;
  settings.vertex_budget = std::max(tuning::vertex_budget_floor, tuning::vertex_budget_per_input_vertex * input_vertices);
  return settings;
}

void make_doubles(Embedding& e, const MapOptions& options, RunControl& control, MapResult& r) {
  MapStatistics& s = r.stats;
  control.report("doubles", 0);
  r.doubles = make_double_map(e, applied_snap_policy(options), options.placement, &control);
  s.chebyshev_moves = r.doubles.chebyshev_moves;
  s.snap_exact_rounds = r.doubles.exact_rounds;
  s.snap_crowd_scalings = r.doubles.crowd_scalings;
  s.snap_crowd_sweeps = r.doubles.crowd_sweeps;
  s.snap_repaired = r.doubles.repaired;
  s.snap_boundary_rerounded = r.doubles.boundary_rerounded;
  s.snap_rounds = r.doubles.rounds;
  s.lps += r.doubles.lps;
}

// Merges (merge_pass.hpp), exact runs only: a merge may pick a midpoint, which a non-exact
// arithmetic may not hold. Cut short by the time limit they are all undone, so that the result
// does not depend on where the time ran out.
void merge(Embedding& e, const MapOptions& options, RunControl& control, MapStatistics& s) {
  std::optional<Embedding> before;
  if (control.can_stop()) before = e;
  MergeSettings settings;
  settings.control = &control;
  settings.flip_collapses = options.flip_collapse;
  // --check: the tets a merge, relocating or flip collapse changed all lie around these vertices.
  if (options.check)
    settings.after_step = [&e](const std::vector<VertexId>& changed) {
      for (VertexId v : changed)
        if (std::string why = check_local_invariant(e, v); !why.empty())
          throw MapError(MapErrorKind::internal, "the merge pass broke an invariant: " + why);
    };
  const MergeResult m = merge_added_vertices(e, s.input_vertices, options.placement, settings);
  if (m.stopped) {
    e = std::move(*before);
    s.merge_stopped_at_time_limit = true;
    return;
  }
  s.merged = m.removed;
  s.relocating_collapses = m.relocating;
  s.flip_collapses = m.flipping;
  s.collapsed += m.removed;
}

void record_shelling_verdict(const ShellingVerdict& v, MapStatistics& s) {
  s.nobuenoss = true;
  s.shelling_found = v.found;
  s.shelling_attempts = v.attempts;
  s.shelling_best_removed = v.best_removed;
  s.shelling_tets = v.tets;
  s.shelling_split_chords = v.split_chords;
  s.shelling_replay_completed = v.replay_completed;
  s.shelling_replay_expansions = v.replay_expansions;
  s.shelling_replay_empty_cone_steps = v.replay_empty_cone_steps;
}

// After a NOBUENOSS: the shelling search that the fallback of paper Sec. 4.3 starts with
// (shelling_fallback.hpp). Its verdict completes the stuck message.
ShellingVerdict search_fallback(const MapProblem& problem, std::size_t threads, RunControl& control,
                                MapResult& r) {
  const auto phase = Clock::now();
  control.report("shelling search", 0);
  ShellingVerdict v = search_input_shelling(problem.tets, problem.source.size(), 1, &control, 8, threads);
  r.stats.seconds_shelling_search = seconds_since(phase);
  record_shelling_verdict(v, r.stats);
  r.message += "; " + v.message;
  return v;
}

// Paper Sec. 4.3 after a NOBUENOSS with a shelling found (ReplayMode::after_nobuenoss): the run
// again from the shrunk state, replaying the shelling until greedy expansion can take over. The
// report keeps the greedy run's NOBUENOSS and shelling verdicts; its other counts are the
// replayed run's. A plan that fails in the run's own --shelled mode is made again with the
// shelling star-shapification wherever bends and pushes fail before the next plan is tried
// (ExpansionSettings::raise_shelled): on the subdivided dunce-hat balls (docs/algorithm/expansion.md)
// each mode mapped cases the other stalled or ran away on. The caller words a failure.
ExpansionOutcome replay_after_nobuenoss(const ValidatedProblem& v, const MapOptions& options,
                                        Clock::time_point start, RunControl& control,
                                        const MapStatistics& before, const ShellingVerdict& verdict,
                                        Embedding& e, std::vector<HPoint>& prescribed, MapResult& r) {
  MapStatistics greedy = std::move(r.stats);
  r.stats = before;
  MapStatistics& s = r.stats;
  record_shelling_verdict(verdict, s);
  s.seconds_shelling_search = greedy.seconds_shelling_search;
  e = initial_embedding(v, options.filter, options.placement.arith, &s.filter);
  auto phase = Clock::now();
  preprocess(e, v, options, prescribed, r);
  s.seconds_preprocess = greedy.seconds_preprocess + seconds_since(phase);
  phase = Clock::now();
  ExpansionSettings settings = expansion_settings(options, start, control, prescribed, s.input_vertices);
  settings.replay = ReplayMode::until_greedy;
  settings.raise_shelled = true;
  ExpansionOutcome out = expand_cluster(e, settings, s);
  s.seconds_expand = greedy.seconds_expand + seconds_since(phase);
  s.replay.after_nobuenoss = true;
  return out;
}

void run_method(const MapProblem& problem, const ValidatedProblem& v, const MapOptions& options, Clock::time_point start,
                RunControl& control, Embedding& e, MapResult& r) {
  const MapStatistics before = r.stats;
  MapStatistics& s = r.stats;
  auto phase = Clock::now();
  std::vector<HPoint> prescribed;
  preprocess(e, v, options, prescribed, r);
  s.seconds_preprocess = seconds_since(phase);

  phase = Clock::now();
  ExpansionOutcome out =
      expand_cluster(e, expansion_settings(options, start, control, prescribed, s.input_vertices), s);
  s.seconds_expand = seconds_since(phase);
  r.outcome = out.outcome;
  r.message = out.message;
  if (out.nobuenoss) {
    const ShellingVerdict verdict = search_fallback(problem, options.threads, control, r);
    const bool replay = options.replay == ReplayMode::after_nobuenoss && verdict.replay_completed;
    if (replay && !control.stopped()) {
      // A failure ends the run as stuck (or stopped) with the NOBUENOSS and the replay's reasons.
      out = replay_after_nobuenoss(v, options, start, control, before, verdict, e, prescribed, r);
      r.outcome = out.outcome;
      if (out.outcome == MapOutcome::success)
        r.message = out.message;
      else
        r.message += "; replayed from the start (--replay-shelling after-nobuenoss), it " +
                     std::string(out.outcome == MapOutcome::stuck ? "ended: " : "stopped: ") + out.message;
    } else if (replay) {
      r.message += "; not replayed: the run was stopped";
    } else if (verdict.replay_completed) {
      r.message += "; not replayed (--replay-shelling " + std::string(to_string(options.replay)) + ")";
    }
  }
  if (out.outcome == MapOutcome::success && options.collapse) {
    phase = Clock::now();
    control.report("collapse", 0);
    s.collapsed = collapse_added_vertices(e, s.input_vertices);
    if (options.merge && options.placement.arith.exact()) merge(e, options, control, s);
    s.seconds_collapse = seconds_since(phase);
    if (options.check)
      if (std::string why = check_invariants(e, prescribed); !why.empty())
        throw MapError(MapErrorKind::internal, "the final collapse pass broke an invariant: " + why);
  }
  e.compact_vertices(s.input_vertices);  // vertices collapsed away, or inflation splits undone
  if (out.outcome == MapOutcome::success) {
    phase = Clock::now();
    make_doubles(e, options, control, r);
    s.seconds_double = seconds_since(phase);
  }
  fill_output(e, r);
  if (r.outcome != MapOutcome::success) return;
  phase = Clock::now();
  control.report("verification", 0);
  VerificationInput in{&problem.tets, &v.source, &problem.boundary_vertices, &v.boundary_positions};
  if (v.combinatorial) {
    in.parents = &r.parents;
    in.origin = &r.origin;
  }
  r.verification = verify_map(in, r.tets, r.source, r.target);
  s.seconds_verify = seconds_since(phase);
  if (r.verification.ok()) return;
  if (options.placement.arith.exact())
    throw MapError(MapErrorKind::internal, "the computed map failed verification: " + r.verification.first_failure);
  PrecisionLoss loss;  // every step checks what it rounds; this is the last line of defence
  loss.phase = "verification";
  loss.what = "the final map failed exact verification: " + r.verification.first_failure;
  throw PrecisionLost(std::move(loss));
}

// The local repair of an initial map (local/local_repair.hpp) when options.init asks for one:
// true when it produced the result. It runs on exact coordinates only: the stars' boundaries are
// the initial map's positions, which a rounded arithmetic would move.
bool try_local(const MapProblem& problem, const ValidatedProblem& v, const MapOptions& options, RunControl& control,
               MapResult& r) {
  if (options.init == InitialMapKind::shrink) return false;
  LocalRepairStatistics& ls = r.stats.local;
  if (!options.placement.arith.exact()) {
    if (options.init != InitialMapKind::automatic)
      throw MapError(MapErrorKind::invalid_input, "an initial map (--init) needs exact coordinates (--arith rational)");
    ls.fallback = "coordinates in " + to_string(options.placement.arith) + " (local repair needs exact ones)";
    return false;
  }
  if (map_locally(problem, v, options, control, r)) return true;
  ls.init = "shrink";
  return false;
}

}  // namespace

std::optional<InitialMapKind> parse_initial_map_kind(std::string_view name) {
  if (name == "shrink") return InitialMapKind::shrink;
  if (name == "tutte") return InitialMapKind::tutte;
  if (name == "given") return InitialMapKind::given;
  if (name == "auto") return InitialMapKind::automatic;
  return std::nullopt;
}

const char* to_string(InitialMapKind kind) {
  switch (kind) {
    case InitialMapKind::shrink: return "shrink";
    case InitialMapKind::tutte: return "tutte";
    case InitialMapKind::given: return "given";
    case InitialMapKind::automatic: return "auto";
  }
  return "?";
}

// automatic: the local repair succeeded but its stitched doubles are not a valid map, where the
// global method's often are: stars that hold a large share of the tets crowd their vertices like a
// global run does, without its crowd-opening passes (cases: bench/RESULTS.md, issue 20 sections).
bool retry_globally(const MapOptions& options, const RunControl& control, const MapResult& local) {
  return options.init == InitialMapKind::automatic && local.outcome == MapOutcome::success &&
         local.doubles.checked && !local.doubles.check.valid() && !local.doubles.stopped_at_deadline &&
         !control.stopped();
}

// A result holding only what `from` knew before any method ran: the input statistics, and the
// local repair's, with `why` as its fallback reason.
MapResult inputs_of(const MapResult& from, std::string why) {
  MapResult r;
  MapStatistics& s = r.stats;
  const MapStatistics& f = from.stats;
  s.input_vertices = f.input_vertices, s.input_tets = f.input_tets;
  s.input_boundary_vertices = f.input_boundary_vertices, s.input_interior_vertices = f.input_interior_vertices;
  s.input_rounded = f.input_rounded;
  s.combinatorial = f.combinatorial;
  s.seconds_validate = f.seconds_validate;
  s.local = f.local;
  s.local.init = "shrink";
  s.local.fallback = std::move(why);
  return r;
}

namespace {

// What a combinatorial run (MapOptions::combinatorial) can do: nothing that needs the source.
MapOptions without_source_steps(MapOptions o) {
  if (!o.combinatorial) return o;
  o.init = InitialMapKind::shrink;
  o.collapse = o.merge = o.flip_collapse = false;
  o.collapse_refinement = false;
  o.remap_doubles = false;
  return o;
}

}  // namespace

MapResult map_to_domain(const MapProblem& given, const MapOptions& requested) {
  const auto start = Clock::now();
  const MapOptions options = without_source_steps(requested);
  MapResult r;
  MapStatistics& s = r.stats;
  const CoordinateArith& arith = options.placement.arith;
  ValidatedProblem v = validate_problem(given, options.filter, options.placement.lp, options.combinatorial);
  MapProblem rounded;
  if (!arith.exact()) {
    rounded = given;
    s.input_rounded = round_problem(rounded, arith);
  }
  const MapProblem& problem = arith.exact() ? given : rounded;
  s.input_vertices = problem.source.size();
  s.input_tets = problem.tets.size();
  s.combinatorial = options.combinatorial;
  s.input_boundary_vertices = problem.boundary_vertices.size();
  s.input_interior_vertices = s.input_vertices - s.input_boundary_vertices;
  try {
    if (s.input_rounded) {
      try {
        v = validate_problem(problem, options.filter, options.placement.lp, options.combinatorial);
      } catch (const MapError& e) {
        PrecisionLoss loss;
        loss.phase = "input";
        loss.what = "the input rounded to " + to_string(arith) + " is not a valid problem: " + e.what();
        throw PrecisionLost(std::move(loss));
      }
    }
    s.seconds_validate = seconds_since(start);
    RunControl control(options, start);
    const auto remap_if_wanted = [&] {
      if (!wants_remap_from_doubles(options, r) || control.stopped()) return;
      const double left = options.time_limit_seconds > 0 ? options.time_limit_seconds - seconds_since(start) : 0;
      if (options.time_limit_seconds > 0 && left <= 0) return;
      const VerificationInput in{&problem.tets, &v.source, &problem.boundary_vertices, &v.boundary_positions};
      remap_from_doubles(options, in, left, r);
    };
    std::optional<MapResult> local;
    if (try_local(problem, v, options, control, r)) {
      if (!retry_globally(options, control, r)) {
        remap_if_wanted();
        s.seconds_total = seconds_since(start);
        return r;
      }
      const std::size_t bad = r.doubles.check.inverted + r.doubles.check.degenerate;
      local = std::move(r);
      r = inputs_of(*local, "the stars' stitched doubles leave " + std::to_string(bad) +
                                " tets inverted or flat; the global method ran after them");
    }
    Embedding e = initial_embedding(v, options.filter, options.placement.arith, &s.filter);
    try {
      run_method(problem, v, options, start, control, e, r);
    } catch (const PrecisionLost&) {
      r.tets.clear();
      fill_output(e, r);  // the state where validity was lost
      throw;
    }
    // The global method's map only when its doubles are valid; else the local repair's stands,
    // its report saying that the global method was tried.
    if (local && !(r.outcome == MapOutcome::success && r.doubles.check.valid())) {
      local->stats.local.fallback = "kept the local repair: the global method, run because the stars' "
                                    "stitched doubles were not valid, gave no valid doubles either";
      r = std::move(*local);
    }
    remap_if_wanted();
  } catch (const PrecisionLost& lost) {
    r.outcome = MapOutcome::precision_lost;
    r.loss = lost.loss();
    r.message = lost.loss().message();
    r.verification = {};
    r.doubles = {};
  }
  s.seconds_total = seconds_since(start);
  return r;
}

}  // namespace cmx::algorithm
