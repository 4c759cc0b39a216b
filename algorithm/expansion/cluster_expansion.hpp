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
  std::size_t subcluster_size = 4;        // largest subcluster tried (< 2: off; MapOptions::subclusters)
};

struct ExpansionOutcome {
  MapOutcome outcome = MapOutcome::success;
  std::string message;
  bool nobuenoss = false;  // stuck because no cluster vertex satisfies Eq. (1)
};

ExpansionOutcome expand_cluster(Embedding& e, const ExpansionSettings& settings, MapStatistics& stats);

}  // namespace cmx::algorithm
