// Paper Alg. 1, the Cluster Mesh Expansion loop, as cmx runs it: the three functions of this file
// are its control flow, and every step they call is named below by the paper's line or section.
//
//   before the loop   problem/preprocess.cpp shrinks every interior vertex to p_c: the cluster
//                     mesh M* is simply connected (chord splits) and every tet outside it positive.
//   while M* is not empty                                        run()
//     line 5          select an expandable candidate (Eq. 1) by the priority of Sec. 4.1.2:
//                     simple before star-shapification before inflation, then lower k, then
//                     expanded neighbours                        queue_.pop(), evaluate()
//                                                                (candidate_queue.hpp)
//                     none left: one more round with heavier refinement, then stuck (a NOBUENOSS
//                     or a refinement that failed)               stuck()
//                     (map.cpp then searches a shelling: refinement/shelling_fallback.hpp)
//                                                                handle()
//     line 11         simply expandable: place at the (precision-reduced) Chebyshev centre of its
//                     cone's kernel (Sec. 4.2.3)                 place() -> place_in_cone()
//     Sec. 4.2.5      else first try a subcluster of up to four  expand_subcluster()
//                                                                refine_and_expand()
//     (relaxation)    re-centre the expanded base vertices       relax_base()
//     line 9          inflation, when the base has dangling edges or cut vertices
//                                                                inflate(), paper_inflate()
//     line 10         star-shapification, when the cone has no kernel: bends, then pushes; in a
//                     last round before stuck, pushes along a shelling of the base (the fallback)
//                                                                bend_and_expand(), star_shapify(),
//                                                                shelled_star_shapify()
//     line 11         then place as above                        try_simple(), expand_to()
//     Sec. 4.2.2      collapse what the refinement added         collapse_added_since()
//     Sec. 4.2.4      smooth the recently expanded vertices      smooth_recent()
//
// The refinement steps are in refinement/local_refinement.cpp, the queue and the set of vertices
// to classify again in candidate_queue.cpp, classification and bookkeeping (limits, trace) in
// cluster_expansion.cpp; docs/algorithm/expansion.md explains each step.
#include "algorithm/expansion/cluster_expander.hpp"
#include "algorithm/map_error.hpp"

namespace cmx::algorithm::detail {

void ClusterExpander::count_cluster() {
  cluster_ = 0;
  for (VertexId v{0}; v < e_.num_vertices(); ++v) cluster_ += e_.unexpanded[v] ? 1 : 0;
}

ExpansionOutcome ClusterExpander::run() {
  count_cluster();
  for (VertexId v{0}; v < e_.num_vertices(); ++v)
    if (e_.unexpanded[v]) queue_.mark(v);
  classify_marked();
  if (watch_runaway_) checkpoint_ = Checkpoint{e_, stats_, cluster_};
  while (cluster_ > 0) {
    if (auto stop = check_limits()) return *stop;
    report_progress(false);
    const std::optional<Entry> next = queue_.pop();  // line 5
    if (!next) {
      // Every candidate failed: one more round in which refinement may also push dangling
      // leaves and inflate around cut vertices (heavier, and prone to chains of refinement, so
      // only when nothing else is left).
      if (failures_ == 0) return stuck();
      if (aggressive_) {
        if (auto doomed = nobuenoss_ahead(stuck())) return *doomed;
        if (s_.shelled != ShelledMode::when_stuck || shelling_round_) return refinement_failed(stuck());
        shelling_round_ = true;  // the last round: the shelling star-shapification as well
        for (VertexId v{0}; v < e_.num_vertices(); ++v)
          if (e_.unexpanded[v]) queue_.mark(v);
        classify_marked();
        continue;
      }
      aggressive_ = true;
      for (VertexId v{0}; v < e_.num_vertices(); ++v)
        if (e_.unexpanded[v]) queue_.mark(v);
      classify_marked();
      continue;
    }
    const std::size_t before = cluster_;
    try {
      handle(*next);
    } catch (PrecisionLost& lost) {
      if (lost.loss().phase == "split") {  // a split's loss knows neither the step nor the operation
        lost.loss().step = expanded_;
        lost.loss().phase = std::string(label_) + " (split)";
      }
      throw;
    }
    if (cluster_ < before) aggressive_ = shelling_round_ = false;
    if (s_.smooth_every && expanded_ >= next_smooth_) {
      smooth_recent();
      next_smooth_ = expanded_ + s_.smooth_every;
    }
    classify_marked();
    note_progress();
    // A stall ahead of a NOBUENOSS ends the run; any other stall restarts like a runaway, or
    // ends the last attempt (no restart left): going on only expands what the refinement pushes
    // while the bits grow.
    if (s_.max_restarts > 0 && stalled()) {
      if (auto doomed = nobuenoss_ahead(stall())) return *doomed;
      return watch_runaway_ ? ran_away() : refinement_failed(stall());
    }
    if (s_.max_restarts > 0 && stall_check_due())
      if (auto doomed = nobuenoss_ahead(stall())) return *doomed;
    if (runaway()) return ran_away();
  }
  report_progress(true);
  return {MapOutcome::success, {}};
}

ExpansionOutcome ClusterExpander::replay(std::size_t plan_rank, const ReplayPlans& plans,
                                         std::size_t replans) {
  count_cluster();
  ExpansionOutcome planned = replay_shelling(plan_rank, plans, replans);
  report_progress(planned.outcome != MapOutcome::success || cluster_ == 0);
  return planned;
}

void ClusterExpander::rank_plans(ReplayPlans& plans) {
  count_cluster();
  replay_split_chords();
  rank_replay_plans(plans, false);
}

// One popped candidate (Alg. 1 lines 9-11 for it).
void ClusterExpander::handle(const Entry& entry) {
  const VertexId v = entry.v;
  switch (entry.kind) {
    case Kind::automatic:
      label_ = "automatic";
      expand_to(v, e_.center, entry.k);
      ++stats_.expansions_automatic;
      return;
    case Kind::simple: {  // line 11
      const bool guessed = !cached_[v];
      std::optional<Placement> p = std::move(cached_[v]);
      if (!p) {
        if (float_centre_[v]) p = place_at_point(e_, v, *float_centre_[v]);
        if (p)
          ++stats_.placements_float_centre;
        else
          p = place(gather_expansion_cone(e_, v), nullptr);
      }
      if (!p->ok()) {
        if (!guessed)
          throw MapError(MapErrorKind::internal, "a simple cone lost its interior",
                         "vertex " + std::to_string(v));
        guess_wrong_[v] = 1;
        queue_.mark(v);
        return;
      }
      label_ = "simple";
      expand_to(v, p->position, entry.k, &*p);
      ++stats_.expansions_simple;
      return;
    }
    case Kind::star_shapify:  // lines 10 and 11
    case Kind::inflate:       // lines 9 to 11
      // A failure changes nothing that matters for v: it waits until its star changes.
      if (expand_subcluster(v)) return;
      label_ = entry.kind == Kind::inflate ? "inflation" : "star-shapified";
      if (const std::size_t before = e_.num_vertices(); !refine_and_expand(v, 0))
        ++failures_;
      else if (s_.collapse_after_refinement)
        collapse_added_since(before);
      return;
  }
}

// Expands cluster vertex v now if it can be done: simply; after re-centring its base; by
// inflation of dangling base edges; by star-shapification. Each step keeps every invariant.
bool ClusterExpander::refine_and_expand(VertexId v, int depth) {
  const Relabel relabel(label_, depth > 0 ? "refinement" : label_);
  const topology::ClusterVertexStatus st = topology::classify_cluster_vertex(e_.mesh, v, e_.unexpanded, ws_);
  if (!st.expandable) return false;
  if (try_simple(v, st.manifold_k)) return true;
  if (depth == 0 && relax_base(v) && try_simple(v, st.manifold_k)) return true;
  // Inflation changes v's unexpanded link (the split vertices it expands were cluster vertices
  // around v): the steps after it need Eq. (1) again, or v's expansion could leave the cluster
  // mesh not simply connected (found with --check on a replay, docs/algorithm/expansion.md).
  const auto still_eq1 = [&] {
    return topology::classify_cluster_vertex(e_.mesh, v, e_.unexpanded, ws_).expandable;
  };
  ConeBase base = cone_base(e_, v);
  if (base.adj.empty() && !base.verts.empty()) {  // line 9, a base without edges
    if (inflate_isolated(v, base, depth) && !e_.unexpanded[v]) return true;
    if (!still_eq1()) return false;
    base = cone_base(e_, v);  // the attempts' refinement may have kept edits
  }
  if (has_dangling_edge(base)) {  // line 9
    if (!inflate(v, depth) || !e_.unexpanded[v]) return !e_.unexpanded[v];
    if (!still_eq1()) return false;
    if (try_simple(v, st.manifold_k)) return true;
  }
  if (s_.shelled == ShelledMode::first && shelled_star_shapify(v, st.manifold_k, depth)) return true;
  if (bend_and_expand(v, st.manifold_k)) return true;  // line 10, then 11
  if (star_shapify(v, st.manifold_k, depth, false)) return true;
  if (s_.shelled == ShelledMode::after_pushes && fallback(v, st.manifold_k, depth)) return true;
  if (!aggressive_ || depth > 0) return false;
  if (star_shapify(v, st.manifold_k, depth, true)) return true;
  // Line 9 as the paper does it (Sec. 4.2.1: split around the base's cut vertices).
  if (paper_inflate(v, depth) && (!e_.unexpanded[v] || (still_eq1() && try_simple(v, st.manifold_k))))
    return true;
  if (!e_.unexpanded[v]) return true;
  return shelling_round_ && fallback(v, st.manifold_k, depth);
}

// A step at the last depth, so that what it pushes is left in the cluster.
bool ClusterExpander::refine_by(VertexId v, RefinementStep step) {
  count_cluster();
  const topology::ClusterVertexStatus st = topology::classify_cluster_vertex(e_.mesh, v, e_.unexpanded, ws_);
  if (!e_.unexpanded[v] || !st.expandable) return false;
  switch (step) {
    case RefinementStep::bends:
      return bend_and_expand(v, st.manifold_k);
    case RefinementStep::pushes:
      return star_shapify(v, st.manifold_k, max_depth - 1, false);
    case RefinementStep::shelling:
      return shelled_star_shapify(v, st.manifold_k, max_depth - 1);
    case RefinementStep::all:
      return refine_and_expand(v, 0);
  }
  return false;
}

// The fallback after bends and pushes failed, announced to ExpansionSettings::before_fallback.
bool ClusterExpander::fallback(VertexId v, int k, int depth) {
  if (s_.before_fallback) s_.before_fallback(e_, v);
  return shelled_star_shapify(v, k, depth);
}

}  // namespace cmx::algorithm::detail
