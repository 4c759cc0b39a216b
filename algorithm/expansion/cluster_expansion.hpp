#pragma once
// The expansion loop (paper Alg. 1 with the priority queue of Sec. 4.2.6).
//
// Every cluster vertex satisfying Eq. (1) is a candidate, classified as
//   simple        : its expansion cone has interior (Chebyshev LP, r > 0);
//   star-shapify  : its cone base has a triangle but the cone has no interior;
//   inflate       : its cone base has no triangle;
// and ordered by class, then lower k-manifold-expandability, then (simple) more or (star-shapify)
// fewer expanded neighbours, then vertex id (paper Sec. 4.1.2); `index` and `random:SEED` orders
// replace the whole key. Only vertices whose star changed are re-classified.
//
// Star-shapification by pushes (docs/DESIGN.md, "Star-shapification by pushes", has the proof):
// a push splits a spoke (v, b) from v to an expanded base vertex b at a new vertex placed at p_c
// and put into the cluster. It keeps every invariant exactly (the new tets are either copies of
// old ones with one cluster vertex renamed, or have two cluster vertices) and keeps the cluster
// simply connected; when b's neighbours in Lk(v) are one run of cluster vertices and one run of
// expanded ones, v still satisfies Eq. (1) and its base loses b's star. Pushing base vertices
// away from a witness w, keeping one base triangle T at w, ends with a star-shaped cone (a
// single triangle's cone always has interior), after at most |base| - 3 pushes.
//
// Inflation (paper Sec. 4.2.1): for each cut vertex b of Lk°(v), the edges (b, c) to cluster
// vertices c of Lk(v) are split by pushes and the new vertices expanded one by one (cluster
// isolation); v is then re-classified.
//
// Every operation keeps the invariants, so a failed star-shapification or inflation leaves a
// valid state and the loop goes on with other candidates; the loop reports `stuck` when no
// candidate is left (a NOBUENOSS when no cluster vertex satisfies Eq. (1)), and stops at the
// refinement budget or the time limit.
#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "algorithm/embedding.hpp"
#include "algorithm/map.hpp"
#include "algorithm/run_control.hpp"

namespace cmx::algorithm {

struct ExpansionSettings {
  PlacementOptions placement;
  topology::ExpansionOrder order;
  // `strict-index` (CandidateQueue): the vertices below this count come by id before the class;
  // expand_cluster sets it to the vertex count at the start (0: no planned order).
  std::size_t planned_vertices = 0;
  bool check = false;
  RunControl* control = nullptr;  // polled before every step: the time limit and the stop hook
  std::chrono::steady_clock::time_point start;
  std::function<void(const MapProgress&)> progress;
  std::function<void(const TraceRow&)> trace;
  const std::vector<HPoint>* prescribed = nullptr;  // per vertex, for the check mode
  std::size_t input_vertices = 0;
  std::size_t vertex_budget = 0;  // refinement stops (stuck) beyond this many vertices in total
  std::size_t smooth_every = 0;   // smoothing period in expansions (0: off)
  bool collapse_after_refinement = true;  // paper Sec. 4.2.2 (MapOptions::collapse_refinement)
  ShelledMode shelled = ShelledMode::when_stuck;  // MapOptions::shelled
  ReplayMode replay = ReplayMode::off;            // MapOptions::replay
  // A replayed plan that fails, or after whose handover the greedy loop ends stuck, is made once
  // more with `shelled` raised to after_pushes before the next plan (the replay after a NOBUENOSS).
  bool raise_shelled = false;
  std::size_t subcluster_size = 4;        // largest subcluster tried (< 2: off; MapOptions::subclusters)
  // Runaway restarts (below): how many, at most; 0 turns the detection off.
  std::size_t max_restarts = 8;
  // The replay's plans are ranked, and its attempts (expand_cluster) run, this many at once (0:
  // the machine's cores); the result is the same for every count.
  std::size_t threads = 1;
  // MapOptions::before_fallback: called with the state and v just before the shelling
  // star-shapification tries v after bends and pushes failed on it.
  std::function<void(const Embedding&, VertexId)> before_fallback;
};

struct ExpansionOutcome {
  MapOutcome outcome = MapOutcome::success;
  std::string message;
  bool nobuenoss = false;  // stuck because no cluster vertex satisfies Eq. (1)
  bool runaway = false;    // internal: the cluster grew past the runaway bound (see below)
};

// Runaway restarts. Refinement can feed itself: a star-shapification's pushes put new vertices
// into the cluster, whose own expansion pushes again, and the cluster grows without end (Rudin's
// ball mapped combinatorially: from 30 cluster vertices to 2,000 in five minutes). Whether it does
// depends on the order of the candidates (on Rudin's ball about half of the random tie-breaks
// finish in under a second). So the loop keeps a copy of the state (embedding and statistics)
// each time the cluster has halved since the last copy, and when the cluster exceeds twice the
// size it had at the copy plus 64, or refinement has added more than 16 vertices per cluster vertex
// of the copy plus 1,024 without halving it (a churn that does not grow the cluster, seen on the
// same ball), or 1,024 + L / 4 expansions have not made the cluster smaller than its smallest
// size L in this attempt (a stall: on Furch's knotted hole the refinement expands only the
// vertices it pushed itself while the bits grow, up to the time limit), it goes back to the copy
// and continues with the tie-breaks of random:K (K = 1, 2, ...) and, unless the run smooths
// already, smoothing every tuning::restart_smooth_every expansions, at most max_restarts times;
// after that it runs on without the bounds, except that a stall then ends the run as `stuck`
// with the figures. A stall where topological expansion from the cluster mesh left meets a
// NOBUENOSS in four orders ends the run at once, as a NOBUENOSS (nobuenoss_ahead). An attempt
// that did not halve the cluster goes back to the state before the first expansion instead (a
// copy that no order could halve again may be a trap).
// A heuristic: it does not make the expansion's success certain (issue 21 point 1 asks for a
// star-shapification that is), and the output stays deterministic (the restarts are too).

ExpansionOutcome expand_cluster(Embedding& e, const ExpansionSettings& settings, MapStatistics& stats);

// One step of the loop's refinement, on its own, for cluster vertex v of a valid state (every
// invariant of verify/invariants.hpp holds): the bends (bend_and_expand), the pushes of
// star-shapification (star_shapify, without dangling leaves), the fallback star-shapification
// by shelling (shelled_star_shapify), or the whole refinement (refine_and_expand: relaxation,
// inflation, then the others), each as the loop calls it, except that the vertices that the
// pushes and the fallback push stay in the cluster instead of being refined in turn. True when v was
// expanded. Either way every invariant still holds after it (what the step changed is valid;
// a failed step may keep valid edits, as in the loop). For tests on given states: the loop
// itself never calls this.
enum class RefinementStep : std::uint8_t { bends, pushes, shelling, all };
bool refine_by(Embedding& e, VertexId v, RefinementStep step, const ExpansionSettings& settings,
               MapStatistics& stats);

}  // namespace cmx::algorithm
