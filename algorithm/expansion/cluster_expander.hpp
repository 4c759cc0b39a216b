#pragma once
// The expansion loop of paper Alg. 1 as one object (internal to algorithm/, used through
// cluster_expansion.hpp). Alg. 1 itself, line by line: cluster_mesh_expansion.cpp (run, handle,
// refine_and_expand); the queue, classification and bookkeeping: cluster_expansion.cpp; the local
// refinement it falls back on (relaxation, pushes, bends, inflation):
// refinement/local_refinement.cpp.
#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "algorithm/expansion/candidate_queue.hpp"
#include "algorithm/expansion/cluster_expansion.hpp"
#include "algorithm/expansion/cone_base.hpp"
#include "algorithm/expansion/expansion_cone.hpp"
#include "algorithm/expansion/placement.hpp"
#include "topology/cluster_links.hpp"
#include "topology/shelling.hpp"

namespace cmx::algorithm::detail {

// The plans a replay can take, best first (ClusterExpander::rank_plans), found once and read by
// every attempt of expand_cluster, on any thread: each attempt starts from the same state.
struct ReplayPlans {
  std::vector<topology::ShellingExpansion> best_first;
  // Per plan: the expansions of its topological replay before greedy expansion could take over
  // (its steps + 1 when it never could; 0 when not asked, as for full).
  std::vector<std::size_t> handover_at;
  std::size_t shelling_attempts = 0;
  std::string why;  // why there is none, when there is none
};

// Depth of local refinement: a star-shapification or inflation expands the vertices it pushes
// right away, refining them in turn up to this depth; deeper, they go back to the queue.
constexpr int max_depth = 3;

// Sets the trace label for a scope and restores the previous one on exit.
class Relabel {
 public:
  Relabel(const char*& label, const char* now) : label_(label), saved_(label) { label_ = now; }
  ~Relabel() { label_ = saved_; }
  Relabel(const Relabel&) = delete;
  Relabel& operator=(const Relabel&) = delete;

 private:
  const char*& label_;
  const char* saved_;
};

// A copy of the loop's state for the runaway restarts (cluster_expansion.hpp).
struct Checkpoint {
  Embedding embedding;  // without per-vertex properties (a copy starts without them)
  MapStatistics stats;
  std::size_t cluster = 0;
  bool halved = false;  // taken because the cluster halved (not at the start of an attempt)
};

class ClusterExpander {
 public:
  ClusterExpander(Embedding& e, const ExpansionSettings& s, MapStatistics& stats, bool watch_runaway = false)
      : e_(e),
        s_(s),
        stats_(stats),
        watch_runaway_(watch_runaway),
        queue_(e, s.order, s.planned_vertices),
        cached_(e.properties.make<std::optional<Placement>>(e.num_vertices())),
        float_centre_(e.properties.make<std::optional<std::array<double, 3>>>(e.num_vertices())),
        guess_wrong_(e.properties.make<char>(e.num_vertices(), 0)) {}

  ExpansionOutcome run();
  // Paper Sec. 4.3: the replay of a shelling (MapOptions::replay), once, before run(); success
  // with the cluster left to the greedy loop when it handed over (shelling_replay.cpp).
  // `replans`: how often a plan that meets a step it cannot make is planned again from there.
  ExpansionOutcome replay(std::size_t plan_rank, const ReplayPlans& plans, std::size_t replans);
  // The plans replay() takes, ranked from this state once its chords are split (every attempt
  // from the same state splits the same ones), so that the attempts need not rank them.
  void rank_plans(ReplayPlans& plans);
  bool refine_by(VertexId v, RefinementStep step);  // cluster_expansion.hpp
  // After run() returned a runaway: the state to go back to.
  std::optional<Checkpoint> take_checkpoint() { return std::move(checkpoint_); }

 private:
  // --- bookkeeping -------------------------------------------------------------------------

  void count_cluster();    // cluster_ from the flags
  void classify_marked();  // evaluate() every vertex the queue has marked
  bool runaway();          // keeps the checkpoint; true when the cluster passed the runaway bound
  static ExpansionOutcome ran_away();  // the outcome that makes expand_cluster restart
  void note_progress();    // a new smallest cluster of this attempt
  bool stalled() const;    // too many expansions since the smallest cluster (stall_bound)
  bool stall_check_due() const;  // a stall long enough to look for a NOBUENOSS ahead already
  ExpansionOutcome stall() const;
  // `end` (a stall, or every candidate failed) when no other order escapes it.
  std::optional<ExpansionOutcome> nobuenoss_ahead(ExpansionOutcome end) const;
  // `end` once nobuenoss_ahead found that some order escapes it: says the failure is geometric.
  static ExpansionOutcome refinement_failed(ExpansionOutcome end);
  std::optional<ExpansionOutcome> check_limits() const;
  ExpansionOutcome stuck() const;
  ExpansionOutcome nobuenoss_now() const;  // no cluster vertex satisfies Eq. (1)
  void report_progress(bool final);

  // --- classification ----------------------------------------------------------------------

  void evaluate(VertexId v);
  Kind refinement_kind(VertexId v);
  Placement place(const ExpansionCone& cone, const VertexId* witness);

  // --- the loop's operations ---------------------------------------------------------------

  void handle(const Entry& entry);
  void expand_to(VertexId v, const HPoint& position, int k, const Placement* placement = nullptr);
  void after_expansion(VertexId v, int k, const Placement* placement);
  void trace_row(VertexId v, const HPoint& position, const Placement* placement) const;
  void require_valid(VertexId v, const char* action, const Placement* placement) const;
  void check_all(const std::string& when) const;
  VertexId push(VertexId c, VertexId b);
  void undo_push(VertexId c, VertexId x);

  // --- subcluster expansion (paper Sec. 4.2.5, subcluster.hpp) ------------------------------
  bool expand_subcluster(VertexId v);

  // --- post-star-shapification collapses (paper Sec. 4.2.2) ---------------------------------
  void collapse_added_since(std::size_t first);

  // --- smoothing (paper Sec. 4.2.4) -------------------------------------------------------------
  void smooth_recent();
  void smooth_vertex(VertexId b);

  // --- local refinement ----------------------------------------------------------------------

  bool refine_and_expand(VertexId v, int depth);
  bool try_simple(VertexId v, int k);

  // --- relaxation: re-centring the cone base ---------------------------------------------------
  bool relax_base(VertexId v);
  bool recentre(VertexId b);

  // --- star-shapification by pushes ------------------------------------------------------------
  // A push moves a base vertex b of v out of v's base: the spoke (v, b) is split at a new cluster
  // vertex at p_c. Base vertices are pushed away from a kept triangle T until v's cone has
  // interior; it has when the base is T alone (a triangle's cone always has interior), so at most
  // |base| - 3 pushes are needed. Pushes are chosen on a virtual state first (the chosen vertices
  // flagged as cluster vertices at p_c, which is exactly v's star after the real pushes) and made
  // only when they succeed, then v is expanded, then the pushed vertices, last first, each now
  // between v and its base vertex.

  bool star_shapify(VertexId v, int k, int depth, bool leaves);

  // --- star-shapification by bends ------------------------------------------------------------
  // A bend of base vertex b of v splits the spoke (v, b) at a new vertex b' and places b' at once
  // as an expanded vertex, v still at p_c. Its star is the spoke's tets: those with b' in place of
  // v (b' inside the fan of b) and those with b' in place of b (v at p_c). With v in the cluster
  // the new vertex's cone is a fan around b, which always has interior; so every bend is possible
  // and keeps every invariant, and the cluster never grows. For v, b' replaces b in its link with
  // another direction from p_c: bending the endpoints of the base boundary edges that hide the
  // aim point (the centroid of a base triangle) from p_c, with the extra linear constraints that
  // the two new boundary edges at b' show it, straightens the cone until it has interior.
  // Bends are computed on a virtual state (b moved to b's position, which is exactly v's star
  // after the real split) and made only when v's cone has interior.

  bool bend_and_expand(VertexId v, int k);
  std::vector<std::pair<int, VertexId>> blockers(VertexId v, const HPoint& aim) const;
  std::optional<VertexId> choose_push(VertexId v, VertexId w, const std::array<VertexId, 3>& keep,
                                      ConeBase& base, bool leaves) const;

  // --- star-shapification by shelling (the fallback) ------------------------------------------
  // The fallback when bends and pushes fail (MapOptions::shelled says when it runs): v's base is
  // pushed away until one fan of its witness w is left. A disc base is shelled onto star(w) one
  // triangle at a time (topology/disc_shelling.hpp): each triangle leaves by a push of the vertex
  // that leaves with it (an ear), or of the midpoint of its free edge (split first, a free split).
  // Any other base (discs and edges joined at cut vertices) keeps w's largest fan and is pushed
  // greedily, farthest from w first, splitting a free base edge when no vertex can go. Every push
  // keeps Eq. (1) for v and leaves no dangling edge inside the fan. Such a cone always has
  // interior: near p_c + t (w - p_c) for small t > 0 (each constraint is a base tet, positive at
  // p_c, or a side tet whose sign there is that of the base tet through the same edge and w). The
  // pushed vertices are then expanded last first, each now between v and the vertex it left with
  // (the predecessor's contraction, Nigolian et al. 2023, Sec. 5.3). A plan that does not complete
  // or place v is undone exactly and tried with the next of up to three witnesses;
  // docs/algorithm/expansion.md says what is and is not proved.

  // One edit of the shelling's pushes, kept so that a failure can undo them in reverse order: a
  // push of spoke (v, vertex) at the new cluster vertex `added`, or a split of a base edge from
  // `vertex` at `added`.
  struct ShellingEdit {
    bool split = false;
    VertexId vertex{0}, added{0};
  };
  bool shelled_star_shapify(VertexId v, int k, int depth);
  bool fallback(VertexId v, int k, int depth);  // shelled_star_shapify after bends and pushes
  bool push_along_shelling(VertexId v, VertexId w, std::vector<ShellingEdit>& edits);
  bool push_greedily_onto_star(VertexId v, VertexId w, std::vector<ShellingEdit>& edits);
  bool try_push(VertexId v, VertexId x, const std::unordered_set<VertexId>& fan, std::vector<ShellingEdit>& edits);
  void undo_edit(VertexId v, const ShellingEdit& edit);
  void undo_shelling(VertexId v, std::vector<ShellingEdit>& edits);
  VertexId split_base_edge(VertexId a, VertexId b);

  // --- inflation -----------------------------------------------------------------------------
  // A base edge (a, b) in no base triangle has cluster vertices u, u' on both sides in Lk(v): the
  // side planes through p_c, a, b face each other and flatten the kernel (paper Sec. 3.1, Fig. 4).
  // Inflation splits the edge (b, u) (or (a, u), (b, u'), (a, u')) at a new vertex x, pushed to
  // p_c and expanded at once (its unexpanded link is the cone from u, so Eq. (1) holds); (a, b, x)
  // is then a base triangle of v. An x that cannot be expanded is collapsed back into u, which
  // restores the mesh exactly: inflation never leaves refinement behind without progress.
  // Attempts per vertex are bounded; the refinement budget bounds the total.

  bool inflate(VertexId v, int depth);
  // A base without edges (isolated vertices: Eq. (1) allows a base that is one vertex b, and then
  // none of the steps above applies, the paper's inflation included, which splits at cut
  // vertices): the edge (b, u) to a cluster vertex u of the ring around spoke (v, b) is split at a
  // new cluster vertex x, refined and expanded at once, after which (b, x) is a base edge of v
  // that the inflation of dangling edges takes further. As there, an x that cannot be expanded
  // is collapsed back into u. Precondition: `base` is v's cone base, with vertices and no edge.
  bool inflate_isolated(VertexId v, const ConeBase& base, int depth);
  bool push_until_star_shaped(VertexId v, int k);
  bool paper_inflate(VertexId v, int depth);
  bool isolate(VertexId x);

  // --- the replay of a shelling (paper Sec. 4.3, Alg. 2; shelling_replay.cpp) ----------------
  // From the shrunk state: every chord split, then the plan of rank `plan_rank` (a shelling found
  // with its cheapest steps first, topology::ShellingOptions::interior, converted by Alg. 2 and
  // ranked by rank_plans) and each step made: a split of an all-cluster simplex at p_c, an
  // expansion of the planned vertex with all the refinement, then the refinement's own cluster
  // vertices drained. `stats_.replay` counts.
  ExpansionOutcome replay_shelling(std::size_t plan_rank, const ReplayPlans& plans, std::size_t replans);
  void replay_split_chords();
  bool replay_expand(VertexId v);
  // The plan's vertices: every vertex below `first` (the mesh when the plan was made) and the
  // vertices of its splits; the others were added by the refinement.
  struct PlannedVertices {
    std::uint32_t first = 0;
    std::size_t vertex_bound = 0;  // beyond it the replay ran away (tuning::replay_growth_*)
    std::unordered_set<VertexId> splits;
    bool contains(VertexId v) const { return v.idx() < first || splits.count(v) > 0; }
  };
  // The replay's state: plan vertex -> vertex of the embedding (invalid: skipped; waiting_vertex:
  // a split not made yet), the split steps waiting, the plan's vertices.
  static constexpr VertexId waiting_vertex{0xfffffffeu};
  struct ReplayState {
    std::vector<VertexId> geo;
    std::vector<std::size_t> waiting;
    PlannedVertices planned;
  };
  std::optional<ExpansionOutcome> replay_split(const topology::ShellingExpansion& plan, std::size_t j,
                                               ReplayState& r);
  std::optional<ExpansionOutcome> replay_waiting_splits(const topology::ShellingExpansion& plan,
                                                        ReplayState& r, const std::function<bool()>& met);
  std::optional<ExpansionOutcome> replay_step(const topology::ShellingExpansion& plan, std::size_t j,
                                              VertexId v, ReplayState& r);
  void replay_drain(const PlannedVertices& planned);
  bool greedy_can_take_over() const;
  void rank_replay_plans(ReplayPlans& plans, bool from_here);
  std::optional<ExpansionOutcome> replay_plan(const topology::ShellingExpansion& plan,
                                              std::size_t vertex_bound);
  ExpansionOutcome replay_failed(const std::string& why) const;

  Embedding& e_;
  const ExpansionSettings& s_;
  MapStatistics& stats_;
  bool watch_runaway_;
  std::optional<Checkpoint> checkpoint_;
  topology::ClusterLinkWorkspace ws_;
  CandidateQueue queue_;  // line 5's candidates and the vertices to classify again
  // Per-vertex state, grown with the mesh (Embedding::properties).
  VertexProperty<std::optional<Placement>> cached_;                    // v's placement from classification
  VertexProperty<std::optional<std::array<double, 3>>> float_centre_;  // of a cone guessed open
  VertexProperty<char> guess_wrong_;  // 1: the float guess of v's cone was wrong once; decide exactly
  std::unordered_map<VertexId, int> inflations_, relaxed_moves_;
  std::size_t cluster_ = 0, expanded_ = 0, failures_ = 0, max_bits_ = 0;
  // The smallest cluster of this attempt and the expansion count when it was reached: an
  // attempt whose expansions stop making the cluster smaller is stalled (stalled()).
  std::size_t least_cluster_ = SIZE_MAX, expanded_at_least_ = 0;
  bool aggressive_ = false;
  bool shelling_round_ = false;  // the last round before stuck: the shelling star-shapification too
  std::vector<VertexId> recent_;  // expanded since the last smoothing
  std::size_t next_smooth_ = 0;
  const char* label_ = "";  // the kind of expansion under way, for the trace
  std::chrono::steady_clock::time_point last_report_{};
};

}  // namespace cmx::algorithm::detail
