// Paper Sec. 4.3, Alg. 2 replayed geometrically: a shelling of the shrunk mesh is converted to an
// expansion sequence and each of its steps is made with the loop's own refinement
// (ClusterExpander::replay_shelling, docs/algorithm/expansion.md "Replaying a shelling").
#include <algorithm>
#include <functional>
#include <limits>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_set>

#include "algorithm/expansion/cluster_expander.hpp"
#include "algorithm/map_error.hpp"
#include "algorithm/tuning.hpp"
#include "topology/chords.hpp"
#include "topology/complex_queries.hpp"
#include "topology/fixed_boundary_replay.hpp"
#include "topology/indexed_tasks.hpp"
#include "topology/shelling.hpp"
#include "topology/topological_expansion.hpp"

namespace cmx::algorithm::detail {
namespace {

// until_greedy asks whether greedy expansion can take over after every replayed expansion at
// first, then after every n/8 of them (n replayed so far): each question costs two topological
// expansions of the whole mesh, and the replay's refinement grows with every step it takes past
// the first moment it could hand over (on the dunce-hat ball, asking every 16 expansions handed
// over after 16 instead of 8, with three times the vertices; with 1 or 2 more collars, 32 instead
// of 22 and 48 instead of 46).
constexpr std::size_t handover_check_fraction = 8;

// After `asked` questions (or replayed expansions), how many before the next one.
std::size_t next_handover_check(std::size_t asked) {
  return asked + std::max<std::size_t>(1, asked / handover_check_fraction);
}

// Topological expansion of the cluster left completes in `order` and in it without its deferral.
bool can_take_over(const topology::TetMesh& m, const topology::ExpansionOrder& order,
                   const std::vector<char>& unexpanded) {
  topology::ExpansionOrder plain = order;
  plain.defer_first = plain.defer_end = 0;
  return !topology::topological_expansion(m, order, unexpanded).stuck &&
         !topology::topological_expansion(m, plain, unexpanded).stuck;
}

// One seed's plan for rank_replay_plans, or why it has none: the shelling the search finds with
// this seed, converted by Alg. 2, and (`simulate`) the expansions of its topological replay before
// greedy expansion could take over (its steps + 1 when it never could).
struct SeedPlan {
  bool skipped = false;  // the run was stopped before this seed
  std::size_t attempts = 0, handover = 0;
  std::optional<topology::ShellingExpansion> plan;
  std::string why;
};

SeedPlan plan_of_seed(const topology::TetMesh& mesh, const std::vector<char>& interior, std::uint64_t seed,
                      bool simulate, bool from_here, const topology::ExpansionOrder& order) {
  SeedPlan out;
  topology::ShellingOptions options;  // one seeded attempt series on this thread
  options.interior = &interior;
  options.seed = seed;
  const topology::ShellingResult shelling = topology::find_shelling(mesh, options);
  out.attempts = shelling.attempts;
  if (!shelling.found) {
    out.why = "found no shelling: " + shelling.message;
    return out;
  }
  topology::ShellingExpansion plan = topology::shelling_to_expansion_sequence(mesh, shelling.order);
  if (!plan.ok) {
    out.why = "could not convert the shelling: " + plan.message;
    return out;
  }
  if (simulate) {
    std::size_t asked = 0, next = 0;
    const topology::FixedBoundaryReplay sim = topology::replay_with_fixed_boundary(
        mesh, plan, 0,
        [&](const topology::TetMesh& m, const std::vector<char>& unexpanded) {
          if (++asked < next) return false;
          next = next_handover_check(asked);
          return can_take_over(m, order, unexpanded);
        },
        from_here ? &interior : nullptr);
    // Planned again part-way, a plan whose topological replay fails Eq. (1) is not kept.
    if (from_here && (sim.eq1_failures > 0 || !(sim.stopped || sim.ok))) {
      out.why = "the topological replay of a plan made there failed: " +
                (sim.first_failure.empty() ? std::to_string(sim.left) + " cluster vertices left"
                                           : sim.first_failure);
      return out;
    }
    out.handover = sim.stopped ? sim.expansions : plan.steps.size() + 1;
  }
  out.plan = std::move(plan);
  return out;
}

bool simplex_exists(const topology::TetMesh& m, const VertexId* s, int n) {
  return n == 2 ? !topology::tets_around_edge(m, s[0], s[1]).empty()
                : !topology::tets_around_face(m, s[0], s[1], s[2]).empty();
}

}  // namespace

// Every chord first: a chord inside the remaining ball is a hole in the cluster mesh
// (topology/fixed_boundary_replay.hpp). Each chord vertex sits at p_c, as preprocessing's do.
void ClusterExpander::replay_split_chords() {
  const std::size_t before = e_.num_vertices();
  topology::ChordContext chords{
      e_.mesh, e_.boundary, e_.unexpanded, [this](VertexId a, VertexId b, VertexId c) {
        ++cluster_;
        return c == topology::invalid_index ? e_.split_edge(a, b, e_.center, true)
                                            : e_.split_face(a, b, c, e_.center, true);
      }};
  stats_.replay.chord_splits += topology::split_all_chords(chords);
  for (std::size_t v = before; v < e_.num_vertices(); ++v)
    require_valid(VertexId(static_cast<std::uint32_t>(v)), "chord split", nullptr);
}

// One cluster vertex, expanded with all the loop's refinement, then what that refinement added
// collapsed where it can be (paper Sec. 4.2.2). The last cluster vertex goes automatically.
bool ClusterExpander::replay_expand(VertexId v) {
  const topology::ClusterVertexStatus st = topology::classify_cluster_vertex(e_.mesh, v, e_.unexpanded, ws_);
  if (cluster_ == 1) {
    label_ = "automatic";
    expand_to(v, e_.center, st.manifold_k);
    ++stats_.expansions_automatic;
    return true;
  }
  if (!st.expandable) return false;
  label_ = "replayed";
  const std::size_t before = e_.num_vertices();
  if (!refine_and_expand(v, 0)) return false;
  if (s_.collapse_after_refinement) collapse_added_since(before);
  return true;
}

// The refinement's own cluster vertices (those its pushes left), simple expansions first as the
// loop's priority has them, one refined expansion only when no simple one is left. Until none is
// left, none can be expanded, or tuning::replay_drain_patience rounds in a row have not left fewer
// than the fewest so far: a refined expansion can leave another such vertex behind, and on the
// compact house in a box that chase never ended. The plan then goes on with them in the cluster.
// Every vertex below `planned.first` is the plan's, so the scans start there.
void ClusterExpander::replay_drain(const PlannedVertices& planned) {
  const auto own = [&](VertexId u) { return e_.unexpanded[u] && !planned.contains(u); };
  std::size_t fewest = std::numeric_limits<std::size_t>::max(), stale = 0;
  while (cluster_ > 0 && !check_limits() && e_.num_vertices() <= planned.vertex_bound) {
    bool progress = false;
    std::size_t left = 0;
    for (VertexId u{planned.first}; u < e_.num_vertices(); ++u) {
      if (!own(u)) continue;
      const topology::ClusterVertexStatus st =
          topology::classify_cluster_vertex(e_.mesh, u, e_.unexpanded, ws_);
      if (st.expandable && try_simple(u, st.manifold_k)) {
        progress = true;
        ++stats_.replay.drained;
      } else {
        ++left;
      }
    }
    if (left < fewest) {
      fewest = left;
      stale = 0;
    } else if (++stale > tuning::replay_drain_patience) {
      ++stats_.replay.drains_left;
      return;
    }
    for (VertexId u{planned.first}; u < e_.num_vertices() && !progress; ++u)
      if (own(u) && replay_expand(u)) {
        progress = true;
        ++stats_.replay.drained;
      }
    if (!progress) return;
  }
}

// Greedy expansion can take over when topological expansion (Eq. (1) alone) of the cluster left
// completes in the run's order and in the same order without its deferral, which the loop then
// uses (cluster_expansion.cpp): the replay has led the cluster mesh past every NOBUENOSS that
// either order meets without refinement.
bool ClusterExpander::greedy_can_take_over() const {
  return can_take_over(e_.mesh, s_.order, e_.unexpanded);
}

// The plans to replay, best first: until_greedy compares the shellings of tuning::replay_plan_seeds
// seeds by how many expansions their topological replay (topology::replay_with_fixed_boundary,
// asking as the geometric replay does) takes before greedy expansion could take over, fewest
// first (seed order on a tie): each replayed step costs refinement. full takes the first seed's
// plan only.
//
// `from_here`: planned again part-way, from the cluster as it is (some interior vertices expanded,
// the refinement's own vertices in it); the topological replays start there, and a plan whose
// topological replay fails Eq. (1) before it could hand over is not kept.
void ClusterExpander::rank_replay_plans(ReplayPlans& plans, bool from_here) {
  // The cluster now: every interior vertex at the start, the shelling's cheapest steps first.
  const std::vector<char> interior = e_.unexpanded;
  const std::size_t seeds = s_.replay == ReplayMode::until_greedy ? tuning::replay_plan_seeds : 1;
  // Per seed, on `threads` threads (each reads the mesh and works on its own copy), merged in seed
  // order, so the ranking is the same for every thread count.
  std::vector<SeedPlan> per_seed(seeds);
  std::mutex lock;
  topology::run_indexed(seeds, topology::thread_count(s_.threads, seeds), [&](std::size_t i) {
    if (i > 0) {
      const std::lock_guard<std::mutex> hold(lock);
      per_seed[i].skipped = check_limits().has_value();
    }
    if (!per_seed[i].skipped)
      per_seed[i] = plan_of_seed(e_.mesh, interior, i + 1, seeds > 1, from_here, s_.order);
    return false;
  });
  std::vector<std::pair<std::size_t, topology::ShellingExpansion>> ranked;  // (hand-over, plan)
  for (SeedPlan& seed : per_seed) {
    if (seed.skipped) break;
    plans.shelling_attempts += seed.attempts;
    if (plans.why.empty()) plans.why = seed.why;
    if (seed.plan) ranked.emplace_back(seed.handover, std::move(*seed.plan));
  }
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (auto& [handover, plan] : ranked) {
    plans.best_first.push_back(std::move(plan));
    plans.handover_at.push_back(handover);
  }
}

ExpansionOutcome ClusterExpander::replay_failed(const std::string& why) const {
  return {MapOutcome::stuck,
          "the replay of a shelling (paper Alg. 2) " + why + " (" + std::to_string(stats_.replay.expansions) +
              " replayed expansions, " + std::to_string(stats_.replay.drained) +
              " of the refinement's own vertices, " + std::to_string(cluster_) + " cluster vertices left" +
              (stats_.replay.replans == 0 ? ""
               : stats_.replay.replans == 1
                   ? ", planned again once"
                   : ", planned again " + std::to_string(stats_.replay.replans) + " times") +
              ")"};
}

// Why a step's split is skipped unless its simplex is all cluster vertices: a split of a simplex
// with an expanded vertex at p_c, then the expansion of the new vertex, leaves the cluster mesh
// (the full subcomplex of the cluster vertices) exactly as it was, since every simplex of it
// either contains the new vertex or existed before. The same holds for boundary and free splits,
// which make an expanded vertex at once. And the refinement only ever splits edges with an
// expanded end, so the all-cluster simplices of the plan are never refined away.
//
// Splits are made lazily: a split step waits until the plan needs it, that is until a planned
// vertex fails Eq. (1) without it, or a later split refers to its vertex; then the waiting splits
// are made in plan order, each expanding its new vertex, only until that need is met. Why: the
// vertex of a split of an all-cluster edge has an empty cone (both ends sit at p_c) and needs
// inflation, whose vertices must be drained in turn. Made eagerly, in plan order, those splits
// ran away on the dunce-hat ball with 6 or more collars; lazily, about half of them are never
// needed (docs/algorithm/expansion.md, "Replaying a shelling"). Every expansion still checks
// Eq. (1) at its turn, and the hand-over still asks for topological completion.
std::optional<ExpansionOutcome> ClusterExpander::replay_split(const topology::ShellingExpansion& plan,
                                                              std::size_t j, ReplayState& r) {
  const topology::ExpansionStep& st = plan.steps[j];
  const int n = st.kind == topology::ExpansionStepKind::edge_split ? 2 : 3;
  VertexId s[3];
  bool all_cluster = true;
  for (int a = 0; a < n; ++a) {
    s[a] = r.geo[st.split[a].idx()];
    all_cluster =
        all_cluster && s[a] != topology::invalid_vertex && s[a] != waiting_vertex && e_.unexpanded[s[a]];
  }
  if (!all_cluster) {
    r.geo[st.vertex.idx()] = topology::invalid_vertex;
    return std::nullopt;
  }
  if (!simplex_exists(e_.mesh, s, n))
    return replay_failed("lost a simplex of its plan at step " + std::to_string(j));
  const VertexId v =
      n == 2 ? e_.split_edge(s[0], s[1], e_.center, true) : e_.split_face(s[0], s[1], s[2], e_.center, true);
  ++cluster_;
  ++stats_.replay.splits;
  require_valid(v, "replayed split", nullptr);
  r.geo[st.vertex.idx()] = v;
  r.planned.splits.insert(v);
  return replay_step(plan, j, v, r);
}

// Makes the waiting splits in plan order until `met` holds (before each one).
std::optional<ExpansionOutcome> ClusterExpander::replay_waiting_splits(
    const topology::ShellingExpansion& plan, ReplayState& r, const std::function<bool()>& met) {
  std::size_t k = 0;
  for (; k < r.waiting.size() && !met(); ++k)
    if (auto failed = replay_split(plan, r.waiting[k], r)) return failed;
  r.waiting.erase(r.waiting.begin(), r.waiting.begin() + static_cast<std::ptrdiff_t>(k));
  return std::nullopt;
}

// Expands planned vertex v (step j) with all the refinement, then drains.
std::optional<ExpansionOutcome> ClusterExpander::replay_step(const topology::ShellingExpansion& plan,
                                                             std::size_t j, VertexId v, ReplayState& r) {
  if (!replay_expand(v))
    return replay_failed("could not expand vertex " + std::to_string(v) + " at step " + std::to_string(j) +
                         " of " + std::to_string(plan.steps.size()));
  ++stats_.replay.expansions;
  if (v.idx() < s_.input_vertices) stats_.replay.input_vertices.push_back(v.idx());
  replay_drain(r.planned);
  report_progress(false);
  return std::nullopt;
}

// One plan from the state the replay is in: nullopt once it has handed over or expanded every
// cluster vertex, else why it stopped.
std::optional<ExpansionOutcome> ClusterExpander::replay_plan(const topology::ShellingExpansion& plan,
                                                             std::size_t vertex_bound) {
  ReplayState r{{}, {}, {static_cast<std::uint32_t>(e_.num_vertices()), vertex_bound, {}}};
  for (std::size_t i = 0; i < e_.num_vertices(); ++i)
    r.geo.push_back(VertexId(static_cast<std::uint32_t>(i)));
  const auto ran_away = [&] {
    ExpansionOutcome out =
        replay_failed("ran away: its refinement grew the mesh to " + std::to_string(e_.num_vertices()) +
                      " vertices, beyond " + std::to_string(r.planned.vertex_bound) + " (" +
                      std::to_string(tuning::replay_growth_per_step) + " per step of its plan and " +
                      std::to_string(tuning::replay_growth_floor) + ")");
    out.runaway = true;
    return out;
  };
  std::size_t next_check = 0;  // replayed expansions before the next handover check
  for (std::size_t i = 0; i < plan.steps.size() && cluster_ > 0; ++i) {
    if (auto stop = check_limits()) return *stop;
    if (e_.num_vertices() > r.planned.vertex_bound) return ran_away();
    if (s_.replay == ReplayMode::until_greedy && stats_.replay.expansions >= next_check) {
      if (greedy_can_take_over()) {
        stats_.replay.handed_over = true;
        return std::nullopt;
      }
      next_check = next_handover_check(stats_.replay.expansions);
    }
    const topology::ExpansionStep& st = plan.steps[i];
    if (st.kind != topology::ExpansionStepKind::plain_vertex) {
      if (st.vertex.idx() != r.geo.size())
        throw MapError(MapErrorKind::internal, "replay: plan numbering out of step");
      const int n = st.kind == topology::ExpansionStepKind::edge_split ? 2 : 3;
      const auto refers_to_waiting = [&] {
        for (int a = 0; a < n; ++a)
          if (r.geo[st.split[a].idx()] == waiting_vertex) return true;
        return false;
      };
      if (auto failed = replay_waiting_splits(plan, r, [&] { return !refers_to_waiting(); })) return *failed;
      r.geo.push_back(waiting_vertex);
      r.waiting.push_back(i);
      continue;
    }
    const auto ready = [&] {
      const VertexId v = r.geo[st.vertex.idx()];
      return v != waiting_vertex &&
             (v == topology::invalid_vertex || !e_.unexpanded[v] ||
              topology::classify_cluster_vertex(e_.mesh, v, e_.unexpanded, ws_).expandable);
    };
    if (auto failed = replay_waiting_splits(plan, r, ready)) return *failed;
    const VertexId v = r.geo[st.vertex.idx()];
    if (v == topology::invalid_vertex || v == waiting_vertex || !e_.unexpanded[v]) continue;
    if (auto failed = replay_step(plan, i, v, r)) return *failed;
  }
  if (auto failed = replay_waiting_splits(plan, r, [] { return false; })) return *failed;
  replay_drain(r.planned);
  if (auto stop = check_limits()) return *stop;
  if (e_.num_vertices() > r.planned.vertex_bound) return ran_away();
  if (cluster_ > 0) return replay_failed("ended with cluster vertices left");
  return std::nullopt;
}

// A plan that meets a step it cannot make is planned again from where it stopped, up to `replans`
// times (expand_cluster asks for it only once every plan has failed): a shelling of the mesh as it
// is, whose plan holds the refinement's own vertices left in the cluster and the splits made late.
// Why: a plan is exact only while the cluster mesh is the plan's, and two things make it differ,
// both seen on the subdivided dunce-hat balls (docs/algorithm/expansion.md): a vertex a push left
// at p_c whose unexpanded link became a cycle once the vertex it was pushed from expanded (so no
// drain can take it until a planned neighbour goes), and a split made later than its step, after
// an apex of its simplex expanded.
ExpansionOutcome ClusterExpander::replay_shelling(std::size_t plan_rank, const ReplayPlans& plans,
                                                  std::size_t replans) {
  stats_.replay = {};
  stats_.replay.ran = true;
  replay_split_chords();
  stats_.replay.shelling_attempts = plans.shelling_attempts;
  stats_.replay.plans = plans.best_first.size();
  if (plan_rank >= plans.best_first.size())
    return replay_failed(plans.why.empty() ? "has no plan of rank " + std::to_string(plan_rank + 1)
                                           : plans.why);
  const topology::ShellingExpansion* plan = &plans.best_first[plan_rank];
  stats_.replay.steps = plan->steps.size();
  stats_.replay.plan_handover = plans.handover_at[plan_rank];
  aggressive_ = shelling_round_ = true;  // every refinement the loop has, at once
  // The first plan's growth bound holds for the plans made part-way too: on the subdivided balls
  // plans made again and again otherwise grew the mesh to 20,000 vertices until the time limit.
  const std::size_t vertex_bound =
      e_.num_vertices() + tuning::replay_growth_per_step * plan->steps.size() + tuning::replay_growth_floor;
  ReplayPlans again;  // the last plan made part-way
  for (;;) {
    std::optional<ExpansionOutcome> failed = replay_plan(*plan, vertex_bound);
    if (!failed) break;
    if (failed->outcome != MapOutcome::stuck || failed->runaway || stats_.replay.replans >= replans)
      return *failed;
    again = {};
    rank_replay_plans(again, true);
    stats_.replay.shelling_attempts += again.shelling_attempts;
    if (again.best_first.empty()) {
      failed->message += "; planned again from there: " + (again.why.empty() ? "no plan" : again.why);
      return *failed;
    }
    ++stats_.replay.replans;
    plan = &again.best_first.front();
    stats_.replay.steps += plan->steps.size();
  }
  if (!stats_.replay.handed_over) report_progress(true);
  return {MapOutcome::success, {}};
}

}  // namespace cmx::algorithm::detail
