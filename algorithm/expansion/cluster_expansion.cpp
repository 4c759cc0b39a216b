#include "algorithm/expansion/cluster_expansion.hpp"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <optional>
#include <string_view>

#include "algorithm/collapse/collapse_pass.hpp"
#include "algorithm/expansion/cluster_expander.hpp"
#include "algorithm/expansion/smoothing.hpp"
#include "algorithm/expansion/subcluster.hpp"
#include "algorithm/expansion/trace_row.hpp"
#include "algorithm/map_error.hpp"
#include "algorithm/tuning.hpp"
#include "algorithm/verify/invariants.hpp"
#include "topology/complex_queries.hpp"
#include "topology/indexed_tasks.hpp"
#include "topology/mesh_edits.hpp"
#include "topology/topological_expansion.hpp"

namespace cmx::algorithm {

namespace detail {

void ClusterExpander::classify_marked() {
  while (const std::optional<VertexId> v = queue_.take_marked()) evaluate(*v);
}

// Expansions without a new smallest cluster after which an attempt counts as stalled: the
// refinement then only expands the vertices it pushed itself (Furch's knotted hole on a tet:
// from 1,960 cluster vertices on, 7,000 expansions of pushed vertices, none of an input vertex,
// while the bits grow from 71 to 2,800 and the run meets the time limit). Traps are mostly found
// earlier by the NOBUENOSS-ahead check (stall_check_due), so the bound can leave room for long
// detours that do finish: at 512 + L/8 the one star re-mapped from gargoyle_star's doubles stalls
// twice and ends with invalid doubles, at 1,024 + L/4 it finishes in its first order and they are
// valid (bench/results/issue21-thin-combinatorial.md).
static std::size_t stall_bound(std::size_t least_cluster) { return 1024 + least_cluster / 4; }

void ClusterExpander::note_progress() {
  if (cluster_ >= least_cluster_) return;
  least_cluster_ = cluster_;
  expanded_at_least_ = expanded_;
}

bool ClusterExpander::stalled() const { return expanded_ - expanded_at_least_ > stall_bound(least_cluster_); }

// Before the stall bound, at 64, 128, 256, ... expansions without a new smallest cluster: the
// NOBUENOSS-ahead check costs four topological expansions of the cluster mesh, a stalled step
// up to 0.15 s (Furch's knotted hole), so a trap is better recognised early. Where the check
// finds no trap nothing changes (the longest stall on the shared cases is 67 expansions, P07).
bool ClusterExpander::stall_check_due() const {
  const std::size_t stalled_for = expanded_ - expanded_at_least_;
  return stalled_for >= 64 && (stalled_for & (stalled_for - 1)) == 0;
}

ExpansionOutcome ClusterExpander::stall() const {
  return {MapOutcome::stuck, "stalled: " + std::to_string(cluster_) + " cluster vertices left; the last " +
                                 std::to_string(expanded_ - expanded_at_least_) +
                                 " expansions never left fewer than " + std::to_string(least_cluster_) +
                                 " (after " + std::to_string(stats_.expansion_restarts) +
                                 " restarts in other orders)"};
}

// A stall, or a state where every candidate's refinement failed, where greedy expansion cannot
// finish whatever the geometry: topological expansion (Eq. (1) alone,
// topology/topological_expansion.hpp) from the cluster mesh left stops at a NOBUENOSS in the
// default order and in random:1..3. Then no restart in another order is tried (the input's own
// cluster mesh is a trap for every order on Furch's knotted hole) and the run ends as a NOBUENOSS,
// which the shelling search of the fallback then examines (map.cpp).
std::optional<ExpansionOutcome> ClusterExpander::nobuenoss_ahead(ExpansionOutcome end) const {
  std::size_t fewest = SIZE_MAX;
  for (std::uint64_t k = 0; k < 4; ++k) {
    const topology::ExpansionOrder order =
        k == 0 ? topology::ExpansionOrder{} : topology::ExpansionOrder{topology::ExpansionOrderKind::random, k};
    const topology::TopologicalExpansionResult t = topology::topological_expansion(e_.mesh, order, e_.unexpanded);
    if (!t.stuck) return std::nullopt;
    fewest = std::min(fewest, t.remaining.size());
  }
  // Nothing expandable even topologically: the cluster mesh left is itself a NOBUENOSS (the
  // refinement of the last candidates can leave one behind).
  if (fewest == cluster_) return nobuenoss_now();
  ExpansionOutcome out = std::move(end);
  out.message += "; NOBUENOSS ahead: topological expansion from the cluster mesh left stops at one in the default "
                 "order and random:1..3 (" + std::to_string(fewest) + " or more cluster vertices left)";
  out.nobuenoss = true;
  return out;
}

ExpansionOutcome ClusterExpander::refinement_failed(ExpansionOutcome end) {
  end.message +=
      "; not a NOBUENOSS: topological expansion from the cluster mesh left completes in the default order or "
      "one of random:1..3, so the refinement failed where the topology allows progress (docs/algorithm/"
      "expansion.md)";
  return end;
}

bool ClusterExpander::runaway() {
  if (!watch_runaway_) return false;
  if (!checkpoint_ || 2 * cluster_ <= checkpoint_->cluster) {
    const bool halved = checkpoint_.has_value();
    checkpoint_ = Checkpoint{e_, stats_, cluster_, halved};
    return false;
  }
  const std::size_t added = e_.num_vertices() - checkpoint_->embedding.num_vertices();
  return cluster_ > 2 * checkpoint_->cluster + 64 || added > 16 * checkpoint_->cluster + 1024;
}

ExpansionOutcome ClusterExpander::ran_away() {
  ExpansionOutcome out{MapOutcome::stuck, "the cluster ran away", false};
  out.runaway = true;
  return out;
}

std::optional<ExpansionOutcome> ClusterExpander::check_limits() const {
  if (s_.control && s_.control->should_stop("expansion"))
    return ExpansionOutcome{MapOutcome::time_limit,
                            "time limit reached with " + std::to_string(cluster_) + " cluster vertices left"};
  if (s_.vertex_budget && e_.num_vertices() > s_.vertex_budget)
    return ExpansionOutcome{MapOutcome::stuck, "refinement budget exhausted (" +
                                                   std::to_string(e_.num_vertices()) + " vertices) with " +
                                                   std::to_string(cluster_) + " cluster vertices left"};
  return std::nullopt;
}

ExpansionOutcome ClusterExpander::nobuenoss_now() const {
  return {MapOutcome::stuck,
          "NOBUENOSS: " + std::to_string(cluster_) +
              " cluster vertices left and none satisfies Eq. (1) (b0 = chi = 1 of its unexpanded link)",
          true};
}

ExpansionOutcome ClusterExpander::stuck() const {
  if (failures_ == 0) return nobuenoss_now();
  return {MapOutcome::stuck, std::to_string(cluster_) +
                                 " cluster vertices left; star-shapification (bends, pushes" +
                                 (s_.shelled == ShelledMode::when_stuck ? ", and by shelling in a last round" : "") +
                                 ") or inflation failed for every remaining candidate"};
}

void ClusterExpander::report_progress(bool final) {
  if (!s_.progress) return;
  const auto now = std::chrono::steady_clock::now();
  if (!final && now - last_report_ < std::chrono::milliseconds(200)) return;
  last_report_ = now;
  MapProgress p;
  p.expanded = expanded_;
  p.remaining = cluster_;
  p.splits = e_.num_vertices() - s_.input_vertices;
  p.max_bits = max_bits_;
  p.seconds = std::chrono::duration<double>(now - s_.start).count();
  s_.progress(p);
}

void ClusterExpander::evaluate(VertexId v) {
  queue_.invalidate(v);
  cached_[v].reset();
  float_centre_[v].reset();
  if (!e_.unexpanded[v]) return;
  const topology::ClusterVertexStatus st = topology::classify_cluster_vertex(e_.mesh, v, e_.unexpanded, ws_);
  Kind kind;
  if (st.unexpanded_link.vertices == 0) {
    kind = Kind::automatic;
  } else {
    if (!st.expandable) return;
    const FloatCone guess = float_expansion_cone(e_, v);
    const FloatConeVerdict g =
        guess.base_tets == 0 || guess_wrong_[v] ? FloatConeVerdict{} : guess_cone(guess, s_.placement);
    if (guess.base_tets == 0) {
      kind = Kind::inflate;
    } else if (g.guess == ConeGuess::closed && certified_closed(e_, v, guess, g.lp)) {
      // The exact class, proved on at most four rows instead of the whole cone.
      kind = refinement_kind(v);
      ++stats_.closed_by_support;
    } else if (g.guess == ConeGuess::open) {
      // The exact cone, the certified LP and the precision reduction run when v is popped,
      // once, instead of at every re-evaluation (about five per expansion): the same position,
      // a fraction of the cost. Should the guess be wrong there, v is classified exactly from
      // then on. The float centre is kept for the quick placement (placement.hpp).
      kind = Kind::simple;
      ++stats_.lp_float_guesses;
      float_centre_[v] = float_centre(guess, g.lp, s_.placement);
    } else {
      const ExpansionCone cone = gather_expansion_cone(e_, v);
      Placement p = place(cone, nullptr);
      if (p.ok()) {
        kind = Kind::simple;
        cached_[v] = std::move(p);
      } else {
        // Bases that are not discs (pinched, dangling edges) come after every disc: their
        // refinement is heavier (paper Sec. 4.1.2: star-shapification before inflation).
        kind = refinement_kind(v);
      }
    }
  }
  queue_.push(v, kind, st.manifold_k, st.expanded_neighbors);
}

Kind ClusterExpander::refinement_kind(VertexId v) {
  return topology::expanded_link_cut_vertices(e_.mesh, v, e_.unexpanded).empty() ? Kind::star_shapify
                                                                                 : Kind::inflate;
}

Placement ClusterExpander::place(const ExpansionCone& cone, const VertexId* witness) {
  Placement p = witness ? place_in_cone(cone, s_.placement, &e_.center, &e_.target[*witness])
                        : place_in_cone(cone, s_.placement);
  ++stats_.lps;
  if (p.info.certified) ++stats_.lps_certified;
  if (p.info.fell_back) ++stats_.lps_fell_back;
  return p;
}

void ClusterExpander::expand_to(VertexId v, const HPoint& position, int k, const Placement* placement) {
  e_.target[v] = position;
  e_.unexpanded[v] = 0;
  after_expansion(v, k, placement);
}

// Bookkeeping of v having left the cluster (position and flag already set).
void ClusterExpander::after_expansion(VertexId v, int k, const Placement* placement) {
  const HPoint& position = e_.target[v];
  --cluster_;
  ++expanded_;
  ++stats_.k_manifold[k >= 1 && k <= 3 ? k : 0];
  max_bits_ = std::max(max_bits_, position.bit_size());
  queue_.invalidate(v);
  require_valid(v, "expansion", placement);
  if (s_.check) check_all("after expanding vertex " + std::to_string(v));
  queue_.mark_star(v);
  if (s_.trace) trace_row(v, position, placement);
  if (s_.smooth_every) recent_.push_back(v);
}

void ClusterExpander::trace_row(VertexId v, const HPoint& position, const Placement* placement) const {
  TraceRow row = state_row(e_, s_.input_vertices);
  row.step = expanded_;
  row.kind = label_;
  row.vertex = v;
  row.bits = position.bit_size();
  row.cone_rows = placement ? placement->rows : 0;
  row.lp = !placement                   ? "none"
           : placement->at_float_centre ? "float-centre"
           : placement->info.certified  ? "certified"
           : placement->info.fell_back  ? "exact-fallback"
                                        : "exact";
  row.cluster_left = cluster_;
  row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - s_.start).count();
  s_.trace(row);
}

// Invariant 2 around v after v moved or appeared. In an exact run a failure is a bug; in a
// non-exact one (--arith) the rounding of v's position lost validity here: the run stops with
// the loss (step, operation, vertex, tet, bits the exact position had).
void ClusterExpander::require_valid(VertexId v, const char* action, const Placement* placement) const {
  if (e_.arith.exact()) {
    if (std::string why = check_local_invariant(e_, v); !why.empty())
      throw MapError(MapErrorKind::internal, std::string(action) + " broke an invariant: " + why,
                     "vertex " + std::to_string(v));
    return;
  }
  const std::optional<InvalidTet> bad = first_invalid_tet_around(e_, v);
  if (!bad) return;
  std::string what = std::string(action) + " of vertex " + std::to_string(v) + " to a rounded position";
  if (placement && placement->rounded_outside) what += " outside its cone";
  PrecisionLoss loss = precision_loss_at(e_, v, *bad, label_, std::move(what));
  loss.step = expanded_ - (std::string_view(action) == "expansion" ? 1 : 0);
  loss.exact_bits = placement ? placement->unrounded_bits : 0;
  throw PrecisionLost(std::move(loss));
}

void ClusterExpander::check_all(const std::string& when) const {
  if (std::string why = check_invariants(e_, *s_.prescribed); !why.empty())
    throw MapError(MapErrorKind::internal, "invariant violated " + when + ": " + why);
}

// Splits edge (c, b) from cluster vertex c to expanded vertex b at a new cluster vertex at p_c.
// Keeps every invariant: the tets with the new vertex in place of c are copies of old ones
// (same positions, same number of cluster vertices), the others have two cluster vertices; and
// the cluster stays simply connected (the new vertex's unexpanded link is the cone from c).
VertexId ClusterExpander::push(VertexId c, VertexId b) {
  for (TetId t : topology::tets_around_edge(e_.mesh, c, b))
    for (VertexId w : e_.mesh.tet(t))
      if (e_.unexpanded[w]) queue_.mark(w);
  const VertexId m = e_.split_edge(c, b, e_.center, true);
  ++cluster_;
  queue_.mark(m);
  if (s_.check) check_all("after pushing edge (" + std::to_string(c) + ", " + std::to_string(b) + ")");
  return m;
}

// Collapses a pushed vertex x (still at p_c, in the cluster) back into cluster vertex c: the mesh
// is exactly as before the push.
void ClusterExpander::undo_push(VertexId c, VertexId x) {
  const topology::CollapseResult r = e_.collapse_edge(c, x);
  if (!r.ok) throw MapError(MapErrorKind::internal, "could not undo a push: " + r.message);
  e_.unexpanded[x] = 0;
  --cluster_;
  queue_.invalidate(x);
  queue_.mark_star(c);
}

// Tried before refining v, that is only when no single vertex is simply expandable (the class
// comes first in the key). A plan is found without changing anything; committing it sets every
// position first, since each was chosen with the rest of the set at its common point, then
// checks invariant 2 around each vertex.
bool ClusterExpander::expand_subcluster(VertexId v) {
  if (s_.subcluster_size < 2) return false;
  SubclusterCounters counters;
  const auto began = std::chrono::steady_clock::now();
  std::optional<std::vector<SubclusterMove>> plan =
      plan_subcluster(e_, v, s_.subcluster_size, s_.placement, ws_, counters, s_.order);
  stats_.seconds_subcluster_search +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  stats_.subcluster_candidates += counters.candidates;
  stats_.lps += counters.exact_lps;
  if (!plan) return false;
  const Relabel relabel(label_, "subcluster");
  for (const SubclusterMove& m : *plan) {
    e_.target[m.v] = m.placement.position;
    e_.unexpanded[m.v] = 0;
  }
  for (const SubclusterMove& m : *plan) after_expansion(m.v, m.manifold_k, &m.placement);
  // Each was placed with the rest of the set at one point: crowded. Re-centring each in its
  // star's kernel gives the next cones room.
  for (const SubclusterMove& m : *plan) recentre(m.v);
  ++stats_.subcluster_expansions;
  stats_.expansions_subcluster += plan->size();
  return true;
}

// The refinement that expanded a vertex is conservative: of the vertices it added, those now
// expanded are collapsed into an expanded neighbour wherever every invariant survives, so that
// the next cones do not inherit them.
void ClusterExpander::collapse_added_since(std::size_t first) {
  for (std::size_t g = e_.num_vertices(); g-- > first;) {
    if (e_.mesh.tets_of(VertexId(g)).empty()) continue;
    const std::optional<VertexId> keep = try_collapse(e_, VertexId(g));
    if (!keep) continue;
    ++stats_.refinement_collapses;
    queue_.invalidate(VertexId(g));
    queue_.mark_star(*keep);
    if (s_.check) check_all("after collapsing vertex " + std::to_string(g));
  }
}

// Every `smooth_every` expansions, the expanded non-boundary neighbours of the vertices expanded
// since the last time, if they still touch the cluster, move to their laplacian_position
// (smoothing.hpp), which keeps every tet's state.
void ClusterExpander::smooth_recent() {
  const std::vector<VertexId> movers = smoothing_candidates(e_, recent_);
  recent_.clear();
  for (VertexId b : movers) smooth_vertex(b);
  if (s_.check) check_all("after smoothing");
}

void ClusterExpander::smooth_vertex(VertexId b) {
  const std::optional<HPoint> q = laplacian_position(e_, b);
  if (!q) return;
  e_.target[b] = *q;
  ++stats_.smoothing_moves;
  max_bits_ = std::max(max_bits_, q->bit_size());
  queue_.mark_star(b);
}

}  // namespace detail

bool refine_by(Embedding& e, VertexId v, RefinementStep step, const ExpansionSettings& settings, MapStatistics& stats) {
  detail::ClusterExpander x(e, settings, stats);
  return x.refine_by(v, step);
}

namespace {

// The greedy loop (Alg. 1) with its runaway restarts, from the state `e` is in.
ExpansionOutcome expand_greedily(Embedding& e, ExpansionSettings s, MapStatistics& stats) {
  std::optional<detail::Checkpoint> first;  // the state before any greedy expansion
  if (s.max_restarts > 0) first = detail::Checkpoint{e, stats, 0};
  for (std::size_t restart = 0;; ++restart) {
    const bool watch = restart < s.max_restarts;
    ExpansionOutcome out;
    std::optional<detail::Checkpoint> back;
    {
      detail::ClusterExpander x(e, s, stats, watch);
      out = x.run();
      if (out.runaway) back = x.take_checkpoint();
    }  // the expander's per-vertex properties are released before the embedding is replaced
    if (!out.runaway) return out;
    // Back to the last copy when the cluster halved in this attempt; a copy that one attempt
    // could not halve again may be a trap (on Rudin's ball most failures end at the same 15
    // vertices), so an attempt that did not halve goes back to the very start.
    if (!back->halved) back = first;
    e = std::move(back->embedding);
    stats = std::move(back->stats);
    stats.expansion_restarts = restart + 1;
    // Another order, the same deferral: a deferred range is the experiment's, not the order's.
    s.order = topology::ExpansionOrder{topology::ExpansionOrderKind::random, restart + 1, s.order.defer_first,
                                       s.order.defer_end};
    // A restart means the refinement churned; smoothing (paper Sec. 4.2.4) re-centres the
    // expanded vertices whose placement makes later cones empty.
    if (s.smooth_every == 0) s.smooth_every = tuning::restart_smooth_every;
  }
}

// One attempt of the schedule after a NOBUENOSS: a plan of rank `rank`, in one --shelled mode,
// planned again up to `replans` times where it fails.
struct ReplayAttempt {
  std::size_t rank;
  ShelledMode mode;
  std::size_t replans;
};

// One attempt from the state `e` and `stats` are in; `raised` counts the attempts in a raised
// mode up to this one (the report's shelled_retries).
ExpansionOutcome run_attempt(Embedding& e, MapStatistics& stats, const ExpansionSettings& s,
                             const detail::ReplayPlans& plans, const ReplayAttempt& a, std::size_t raised) {
  ExpansionSettings replay = s;
  replay.shelled = a.mode;
  ExpansionOutcome out;
  {
    detail::ClusterExpander x(e, replay, stats);
    out = x.replay(a.rank, plans, a.replans);
  }
  stats.replay.plans_tried = a.rank + 1;
  stats.replay.shelled = a.mode;
  stats.replay.shelled_retries = raised;
  if (out.outcome == MapOutcome::success && stats.replay.handed_over) {
    // A deferral is an experiment's way to meet a NOBUENOSS; the replay has led the cluster
    // mesh past it, and the greedy loop goes on in the order without it (greedy_can_take_over
    // checked that this order completes topologically too). Kept, it makes the loop expand the
    // deferred vertices last, each among expanded neighbours only, where it churns.
    ExpansionSettings greedy = replay;
    greedy.replay = ReplayMode::off;
    greedy.order.defer_first = greedy.order.defer_end = 0;
    out = expand_greedily(e, greedy, stats);
  }
  return out;
}

// What one attempt run on a thread left: its end, its state (kept only where it can be the
// result) and its trace rows, replayed in schedule order.
struct AttemptRun {
  ExpansionOutcome out;
  std::optional<Embedding> state;
  MapStatistics stats;
  std::vector<TraceRow> trace;
};

// The attempts of `schedule` from the same start, `threads` at once: the result is the first one
// in schedule order that does not end stuck (or the last one), exactly as one after the other,
// whatever the thread count. An attempt above one that has not ended stuck is stopped, as
// its result cannot be the run's. Each has its own stop control, which asks the run's own under
// a lock (a stop hook need not be thread-safe); no progress of its own; its trace rows are kept.
std::size_t run_attempts_on_threads(std::vector<AttemptRun>& runs, const std::vector<ReplayAttempt>& schedule,
                                    const std::vector<std::size_t>& raised, const Embedding& start,
                                    const MapStatistics& stats_start, const ExpansionSettings& s,
                                    const detail::ReplayPlans& plans, std::size_t threads) {
  std::mutex lock;
  std::atomic<std::size_t> ended{schedule.size()};  // lowest attempt not ended stuck
  std::size_t finished = 0;
  const std::size_t count = schedule.size();
  const std::size_t lowest = topology::run_indexed(count, threads, [&](std::size_t k) {
    AttemptRun& run = runs[k];
    MapOptions stop_only;
    stop_only.stop = [&, k](std::string_view) {
      if (k > ended.load()) return true;
      const std::lock_guard<std::mutex> hold(lock);
      return s.control != nullptr && s.control->should_stop("expansion");
    };
    RunControl control(stop_only, s.start);
    ExpansionSettings mine = s;
    mine.control = &control;
    mine.threads = 1;  // the attempts are what runs on the threads (a plan made again is ranked on this one)
    mine.progress = nullptr;
    mine.trace = nullptr;
    if (s.trace) mine.trace = [&run](const TraceRow& row) { run.trace.push_back(row); };
    run.state = start;
    run.stats = stats_start;
    if (start.stats) run.state->stats = &run.stats.filter;  // the predicate counters, its own too
    run.out = run_attempt(*run.state, run.stats, mine, plans, schedule[k], raised[k]);
    const bool done = run.out.outcome != MapOutcome::stuck;
    for (std::size_t low = ended.load(); done && k < low && !ended.compare_exchange_weak(low, k);) {
    }
    if (!done && k + 1 < count) run.state.reset();  // only the last stuck one can be the result
    const std::lock_guard<std::mutex> hold(lock);
    if (s.control) s.control->report("replay attempts", ++finished, count);
    return done;
  });
  return std::min(lowest, count - 1);
}

}  // namespace

ExpansionOutcome expand_cluster(Embedding& e, const ExpansionSettings& settings, MapStatistics& stats) {
  ExpansionSettings s = settings;
  if (s.order.kind == topology::ExpansionOrderKind::strict_index) s.planned_vertices = e.num_vertices();
  if (s.replay != ReplayMode::until_greedy && s.replay != ReplayMode::full)
    return expand_greedily(e, s, stats);
  // The plans once, best first. A plan whose replay fails (runs away, or meets a step it cannot
  // make), or after whose handover the greedy loop ends stuck, is made again from the same start:
  // with the shelling star-shapification wherever bends and pushes fail (raise_shelled), then
  // with the next plan (up to tuning::replay_plan_attempts). When every one has failed, the same
  // again, each plan planned again where it fails (up to tuning::replay_replans times). On the
  // subdivided dunce-hat balls each --shelled mode mapped cases the other stalled on, the loop
  // stalled after one plan's handover and mapped after another's, and two cases map only when
  // planned again; planned again first, the collared ball with 32 collars mapped with four times
  // the splits where the next plan had needed 13 (docs/algorithm/expansion.md).
  detail::ReplayPlans plans;
  const Embedding before_replay = e;
  const MapStatistics stats_before = stats;
  const ShelledMode raised_mode = std::max(s.shelled, ShelledMode::after_pushes);
  std::vector<ShelledMode> modes{s.shelled};
  if (s.raise_shelled && raised_mode != s.shelled) modes.push_back(raised_mode);
  // The plans first, on a copy (every attempt splits the same chords before it replays), so that
  // every attempt can run on a thread; the schedule follows from how many plans there are.
  {
    Embedding copy = e;
    MapStatistics scratch = stats;
    if (copy.stats) copy.stats = &scratch.filter;
    detail::ClusterExpander x(copy, s, scratch);
    x.rank_plans(plans);
  }
  // Without a plan, one attempt says why.
  std::vector<ReplayAttempt> schedule{{0, modes.front(), 0}};
  const std::size_t ranks = std::min(tuning::replay_plan_attempts, plans.best_first.size());
  for (std::size_t rank = 0; rank < ranks; ++rank)
    for (const ShelledMode mode : modes)
      if (rank > 0 || mode != modes.front()) schedule.push_back({rank, mode, 0});
  for (std::size_t rank = 0; rank < ranks; ++rank)
    for (const ShelledMode mode : modes) schedule.push_back({rank, mode, tuning::replay_replans});
  std::vector<std::size_t> raised(schedule.size(), 0);
  for (std::size_t k = 0; k < schedule.size(); ++k)
    raised[k] = (k > 0 ? raised[k - 1] : 0) + (schedule[k].mode != s.shelled);
  // The first attempt's failure, should an attempt in a raised mode end the run.
  std::string first_failure;
  ExpansionOutcome out;
  // One after the other, attempts report progress and trace rows as they go; a hook that looks at
  // the state as it goes (before_fallback) sees them so whatever the thread count.
  const std::size_t threads = s.before_fallback ? 1 : topology::thread_count(s.threads, schedule.size());
  if (threads <= 1) {
    for (std::size_t k = 0; k < schedule.size(); ++k) {
      if (k > 0) {
        e = before_replay;
        stats = stats_before;
      }
      out = run_attempt(e, stats, s, plans, schedule[k], raised[k]);
      if (out.outcome != MapOutcome::stuck) break;
      if (k == 0) first_failure = out.message;
    }
  } else {
    std::vector<AttemptRun> runs(schedule.size());
    const std::size_t chosen =
        run_attempts_on_threads(runs, schedule, raised, before_replay, stats_before, s, plans, threads);
    if (s.trace)
      for (std::size_t k = 0; k <= chosen; ++k)
        for (const TraceRow& row : runs[k].trace) s.trace(row);
    first_failure = runs[0].out.message;
    e = std::move(*runs[chosen].state);
    e.stats = before_replay.stats;
    stats = std::move(runs[chosen].stats);
    out = std::move(runs[chosen].out);
  }
  if (out.outcome != MapOutcome::success && stats.replay.shelled != s.shelled && !first_failure.empty())
    out.message +=
        "; with --shelled " + std::string(to_string(s.shelled)) + " it had ended: " + first_failure;
  return out;
}

}  // namespace cmx::algorithm
