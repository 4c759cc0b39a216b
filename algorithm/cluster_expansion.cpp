#include "algorithm/cluster_expansion.hpp"

#include <algorithm>
#include <array>
#include <deque>
#include <queue>
#include <tuple>
#include <unordered_map>

#include "algorithm/collapse_pass.hpp"
#include "algorithm/cone_base.hpp"
#include "algorithm/expansion_cone.hpp"
#include "algorithm/invariants.hpp"
#include "algorithm/map_error.hpp"
#include "algorithm/placement.hpp"
#include "algorithm/smoothing.hpp"
#include "algorithm/subcluster.hpp"
#include "algorithm/trace_row.hpp"
#include "topology/cluster_links.hpp"
#include "topology/complex_queries.hpp"
#include "topology/mesh_edits.hpp"

namespace cmx::algorithm {

namespace {

enum class Kind : std::uint8_t { automatic = 0, simple = 1, star_shapify = 2, inflate = 3 };

struct Entry {
  std::array<std::int64_t, 4> key;
  std::uint32_t version;
  VertexId v;
  Kind kind;
  std::uint8_t k;  // k-manifold expandability (0: other)
  bool operator>(const Entry& o) const { return key > o.key; }
};

std::uint64_t splitmix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

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

class ClusterExpander {
 public:
  ClusterExpander(Embedding& e, const ExpansionSettings& s, MapStatistics& stats) : e_(e), s_(s), stats_(stats) {}

  ExpansionOutcome run() {
    for (VertexId v = 0; v < e_.num_vertices(); ++v)
      if (e_.unexpanded[v]) {
        ++cluster_;
        dirty(v);
      }
    flush_dirty();
    while (cluster_ > 0) {
      if (auto stop = check_limits()) return *stop;
      report_progress(false);
      const std::optional<Entry> next = pop();
      if (!next) {
        // Every candidate failed: one more round in which refinement may also push dangling
        // leaves and inflate around cut vertices (heavier, and prone to chains of refinement, so
        // only when nothing else is left).
        if (aggressive_ || failures_ == 0) return stuck();
        aggressive_ = true;
        for (VertexId v = 0; v < e_.num_vertices(); ++v)
          if (e_.unexpanded[v]) dirty(v);
        flush_dirty();
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
      if (cluster_ < before) aggressive_ = false;
      if (s_.smooth_every && expanded_ >= next_smooth_) {
        smooth_recent();
        next_smooth_ = expanded_ + s_.smooth_every;
      }
      flush_dirty();
    }
    report_progress(true);
    return {MapOutcome::success, {}};
  }

 private:
  // --- bookkeeping -------------------------------------------------------------------------

  void grow() {
    version_.resize(e_.num_vertices(), 0);
    cached_.resize(e_.num_vertices());
    guess_wrong_.resize(e_.num_vertices(), 0);
    is_dirty_.resize(e_.num_vertices(), 0);
  }

  void dirty(VertexId v) {
    grow();
    if (!is_dirty_[v]) {
      is_dirty_[v] = 1;
      dirty_.push_back(v);
    }
  }

  // Every cluster vertex of every tet around v (v included).
  void dirty_star(VertexId v) {
    for (TetId t : e_.mesh.tets_of(v))
      for (VertexId w : e_.mesh.tet(t))
        if (e_.unexpanded[w]) dirty(w);
  }

  void flush_dirty() {
    while (!dirty_.empty()) {
      const VertexId v = dirty_.back();
      dirty_.pop_back();
      is_dirty_[v] = 0;
      evaluate(v);
    }
  }

  std::optional<Entry> pop() {
    while (!queue_.empty()) {
      const Entry top = queue_.top();
      queue_.pop();
      if (top.version == version_[top.v] && e_.unexpanded[top.v]) return top;
    }
    return std::nullopt;
  }

  std::optional<ExpansionOutcome> check_limits() const {
    if (s_.deadline && std::chrono::steady_clock::now() > *s_.deadline)
      return ExpansionOutcome{MapOutcome::time_limit,
                              "time limit reached with " + std::to_string(cluster_) + " cluster vertices left"};
    if (s_.vertex_budget && e_.num_vertices() > s_.vertex_budget)
      return ExpansionOutcome{MapOutcome::stuck, "refinement budget exhausted (" + std::to_string(e_.num_vertices()) +
                                                     " vertices) with " + std::to_string(cluster_) +
                                                     " cluster vertices left"};
    return std::nullopt;
  }

  ExpansionOutcome stuck() const {
    if (failures_ == 0)
      return {MapOutcome::stuck, "NOBUENOSS: " + std::to_string(cluster_) +
                                     " cluster vertices left and none satisfies Eq. (1) (b0 = chi = 1 of its "
                                     "unexpanded link)"};
    return {MapOutcome::stuck, std::to_string(cluster_) + " cluster vertices left; star-shapification or inflation "
                                                          "failed for every remaining candidate"};
  }

  void report_progress(bool final) {
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

  // --- classification ----------------------------------------------------------------------

  // The class always comes first: refinement only when no simple expansion is left, whatever the
  // order among equals (paper Sec. 4.1.2 for `priority`).
  std::array<std::int64_t, 4> key(Kind kind, int k, std::uint32_t expanded_neighbors, VertexId v) const {
    switch (s_.order.kind) {
      case topology::ExpansionOrderKind::index: return {std::int64_t(kind), 0, 0, v};
      case topology::ExpansionOrderKind::random:
        return {std::int64_t(kind), 0, 0, std::int64_t(splitmix(s_.order.seed ^ splitmix(v)) >> 1)};
      case topology::ExpansionOrderKind::priority: break;
    }
    const std::int64_t kk = k == 0 ? 4 : k;
    const std::int64_t n = kind == Kind::simple ? -std::int64_t(expanded_neighbors) : std::int64_t(expanded_neighbors);
    return {std::int64_t(kind), kk, n, v};
  }

  void evaluate(VertexId v) {
    grow();
    ++version_[v];
    cached_[v].reset();
    if (!e_.unexpanded[v]) return;
    const topology::ClusterVertexStatus st = topology::classify_cluster_vertex(e_.mesh, v, e_.unexpanded, ws_);
    Kind kind;
    if (st.unexpanded_link.vertices == 0) {
      kind = Kind::automatic;
    } else {
      if (!st.expandable) return;
      const FloatCone guess = float_expansion_cone(e_, v);
      const FloatConeVerdict g = guess.base_tets == 0 || guess_wrong_[v] ? FloatConeVerdict{} : guess_cone(guess, s_.placement);
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
        // then on.
        kind = Kind::simple;
        ++stats_.lp_float_guesses;
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
    queue_.push({key(kind, st.manifold_k, st.expanded_neighbors, v), version_[v], v, kind,
                 std::uint8_t(st.manifold_k)});
  }

  Kind refinement_kind(VertexId v) {
    return topology::expanded_link_cut_vertices(e_.mesh, v, e_.unexpanded).empty() ? Kind::star_shapify : Kind::inflate;
  }

  Placement place(const ExpansionCone& cone, const VertexId* witness) {
    Placement p = witness ? place_in_cone(cone, s_.placement, &e_.center, &e_.target[*witness])
                          : place_in_cone(cone, s_.placement);
    ++stats_.lps;
    if (p.info.certified) ++stats_.lps_certified;
    if (p.info.fell_back) ++stats_.lps_fell_back;
    return p;
  }

  // --- the loop's operations ---------------------------------------------------------------

  void handle(const Entry& entry) {
    const VertexId v = entry.v;
    switch (entry.kind) {
      case Kind::automatic:
        label_ = "automatic";
        expand_to(v, e_.center, entry.k);
        ++stats_.expansions_automatic;
        return;
      case Kind::simple: {
        const bool guessed = !cached_[v];
        std::optional<Placement> p = std::move(cached_[v]);
        if (!p) p = place_at_float_centre(e_, v, float_expansion_cone(e_, v), s_.placement);
        if (p) ++stats_.placements_float_centre;
        else p = place(gather_expansion_cone(e_, v), nullptr);
        if (!p->ok()) {
          if (!guessed) throw MapError(MapErrorKind::internal, "a simple cone lost its interior", "vertex " + std::to_string(v));
          guess_wrong_[v] = 1;
          dirty(v);
          return;
        }
        label_ = "simple";
        expand_to(v, p->position, entry.k, &*p);
        ++stats_.expansions_simple;
        return;
      }
      case Kind::star_shapify:
      case Kind::inflate:
        // A failure changes nothing that matters for v: it waits until its star changes.
        if (expand_subcluster(v)) return;
        label_ = entry.kind == Kind::inflate ? "inflation" : "star-shapified";
        if (const std::size_t before = e_.num_vertices(); !refine_and_expand(v, 0)) ++failures_;
        else if (s_.collapse_after_refinement) collapse_added_since(before);
        return;
    }
  }

  void expand_to(VertexId v, const HPoint& position, int k, const Placement* placement = nullptr) {
    e_.target[v] = position;
    e_.unexpanded[v] = 0;
    after_expansion(v, k, placement);
  }

  // Bookkeeping of v having left the cluster (position and flag already set).
  void after_expansion(VertexId v, int k, const Placement* placement) {
    const HPoint& position = e_.target[v];
    --cluster_;
    ++expanded_;
    ++stats_.k_manifold[k >= 1 && k <= 3 ? k : 0];
    max_bits_ = std::max(max_bits_, position.bit_size());
    ++version_[v];
    require_valid(v, "expansion", placement);
    if (s_.check) check_all("after expanding vertex " + std::to_string(v));
    dirty_star(v);
    if (s_.trace) trace_row(v, position, placement);
    if (s_.smooth_every) recent_.push_back(v);
  }

  void trace_row(VertexId v, const HPoint& position, const Placement* placement) const {
    TraceRow row = state_row(e_, s_.input_vertices);
    row.step = expanded_;
    row.kind = label_;
    row.vertex = v;
    row.bits = position.bit_size();
    row.cone_rows = placement ? placement->rows : 0;
    row.lp = !placement                                 ? "none"
             : placement->info.backend == "float-centre" ? "float-centre"
             : placement->info.certified                 ? "certified"
             : placement->info.fell_back                 ? "exact-fallback"
                                                         : "exact";
    row.cluster_left = cluster_;
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - s_.start).count();
    s_.trace(row);
  }

  // Invariant 2 around v after v moved or appeared. In an exact run a failure is a bug; in a
  // non-exact one (--arith) the rounding of v's position lost validity here: the run stops with
  // the loss (step, operation, vertex, tet, bits the exact position had).
  void require_valid(VertexId v, const char* action, const Placement* placement) const {
    if (e_.arith.exact()) {
      if (std::string why = check_local_invariant(e_, v); !why.empty())
        throw MapError(MapErrorKind::internal, std::string(action) + " broke an invariant: " + why, "vertex " + std::to_string(v));
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

  void check_all(const std::string& when) const {
    if (std::string why = check_invariants(e_, *s_.prescribed); !why.empty())
      throw MapError(MapErrorKind::internal, "invariant violated " + when + ": " + why);
  }

  // Splits edge (c, b) from cluster vertex c to expanded vertex b at a new cluster vertex at p_c.
  // Keeps every invariant: the tets with the new vertex in place of c are copies of old ones
  // (same positions, same number of cluster vertices), the others have two cluster vertices; and
  // the cluster stays simply connected (the new vertex's unexpanded link is the cone from c).
  VertexId push(VertexId c, VertexId b) {
    for (TetId t : topology::tets_around_edge(e_.mesh, c, b))
      for (VertexId w : e_.mesh.tet(t))
        if (e_.unexpanded[w]) dirty(w);
    const VertexId m = e_.split_edge(c, b, e_.center, true);
    ++cluster_;
    grow();
    dirty(m);
    if (s_.check) check_all("after pushing edge (" + std::to_string(c) + ", " + std::to_string(b) + ")");
    return m;
  }

  // Collapses a pushed vertex x (still at p_c, in the cluster) back into cluster vertex c: the mesh
  // is exactly as before the push.
  void undo_push(VertexId c, VertexId x) {
    const topology::CollapseResult r = topology::collapse_edge(e_.mesh, c, x);
    if (!r.ok) throw MapError(MapErrorKind::internal, "could not undo a push: " + r.message);
    e_.unexpanded[x] = 0;
    --cluster_;
    ++version_[x];
    dirty_star(c);
  }

  // --- subcluster expansion (paper Sec. 4.2.5, subcluster.hpp) ------------------------------
  // Tried before refining v, that is only when no single vertex is simply expandable (the class
  // comes first in the key). A plan is found without changing anything; committing it sets every
  // position first, since each was chosen with the rest of the set at its common point, then
  // checks invariant 2 around each vertex.
  bool expand_subcluster(VertexId v) {
    if (s_.subcluster_size < 2) return false;
    SubclusterCounters counters;
    const auto began = std::chrono::steady_clock::now();
    std::optional<std::vector<SubclusterMove>> plan =
        plan_subcluster(e_, v, s_.subcluster_size, s_.placement, ws_, counters);
    stats_.seconds_subcluster_search += std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
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

  // --- post-star-shapification collapses (paper Sec. 4.2.2) ---------------------------------
  // The refinement that expanded a vertex is conservative: of the vertices it added, those now
  // expanded are collapsed into an expanded neighbour wherever every invariant survives, so that
  // the next cones do not inherit them.
  void collapse_added_since(std::size_t first) {
    grow();
    for (std::size_t g = e_.num_vertices(); g-- > first;) {
      if (e_.mesh.tets_of(VertexId(g)).empty()) continue;
      const std::optional<VertexId> keep = try_collapse(e_, VertexId(g));
      if (!keep) continue;
      ++stats_.refinement_collapses;
      ++version_[g];
      dirty_star(*keep);
      if (s_.check) check_all("after collapsing vertex " + std::to_string(g));
    }
  }

  // --- smoothing (paper Sec. 4.2.4) -------------------------------------------------------------
  // Every `smooth_every` expansions, the expanded non-boundary neighbours of the vertices expanded
  // since the last time, if they still touch the cluster, move to their laplacian_position
  // (smoothing.hpp), which keeps every tet's state.
  void smooth_recent() {
    std::vector<VertexId> movers;
    for (VertexId v : recent_)
      for (TetId t : e_.mesh.tets_of(v))
        for (VertexId b : e_.mesh.tet(t))
          if (!e_.unexpanded[b] && !e_.boundary[b] && touches_cluster(b)) movers.push_back(b);
    recent_.clear();
    std::sort(movers.begin(), movers.end());
    movers.erase(std::unique(movers.begin(), movers.end()), movers.end());
    for (VertexId b : movers) smooth_vertex(b);
    if (s_.check) check_all("after smoothing");
  }

  bool touches_cluster(VertexId b) const {
    for (TetId t : e_.mesh.tets_of(b))
      for (VertexId w : e_.mesh.tet(t))
        if (e_.unexpanded[w]) return true;
    return false;
  }

  void smooth_vertex(VertexId b) {
    const std::optional<HPoint> q = laplacian_position(e_, b);
    if (!q) return;
    e_.target[b] = *q;
    ++stats_.smoothing_moves;
    max_bits_ = std::max(max_bits_, q->bit_size());
    dirty_star(b);
  }

  // --- local refinement ----------------------------------------------------------------------

  // Expands cluster vertex v now if it can be done: simply; after re-centring its base; by
  // inflation of dangling base edges; by star-shapification. Each step keeps every invariant.
  bool refine_and_expand(VertexId v, int depth) {
    const Relabel relabel(label_, depth > 0 ? "refinement" : label_);
    const topology::ClusterVertexStatus st = topology::classify_cluster_vertex(e_.mesh, v, e_.unexpanded, ws_);
    if (!st.expandable) return false;
    if (try_simple(v, st.manifold_k)) return true;
    if (depth == 0 && relax_base(v) && try_simple(v, st.manifold_k)) return true;
    if (has_dangling_edge(cone_base(e_, v))) {
      if (!inflate(v, depth) || !e_.unexpanded[v]) return !e_.unexpanded[v];
      if (try_simple(v, st.manifold_k)) return true;
    }
    if (bend_and_expand(v, st.manifold_k)) return true;
    if (star_shapify(v, st.manifold_k, depth, false)) return true;
    if (!aggressive_ || depth > 0) return false;
    if (star_shapify(v, st.manifold_k, depth, true)) return true;
    return paper_inflate(v, depth) && (!e_.unexpanded[v] || try_simple(v, st.manifold_k));
  }

  bool try_simple(VertexId v, int k) {
    const ExpansionCone cone = gather_expansion_cone(e_, v);
    if (cone.base_tets == 0) return false;
    const Placement p = place(cone, nullptr);
    if (!p.ok()) return false;
    expand_to(v, p.position, k, &p);
    ++stats_.expansions_simple;
    return true;
  }

  // --- relaxation: re-centring the cone base ---------------------------------------------------
  // The expanded non-boundary vertices of v's base move to the (precision-reduced) Chebyshev
  // centres of their own stars' kernels. Such a move keeps every invariant (the kernel is exactly
  // where every tet around the vertex keeps its state) and adds nothing; a cone that was only
  // squeezed by neighbours crowding near p_c often opens. Bounded: each vertex moves at most
  // twice (moves dirty their neighbours, which must not become an endless exchange).
  bool relax_base(VertexId v) {
    bool moved = false;
    for (VertexId b : cone_base(e_, v).verts) {
      if (e_.boundary[b] || relaxed_moves_[b] >= 2) continue;
      ++relaxed_moves_[b];
      moved = recentre(b) || moved;
    }
    return moved;
  }

  // Moves expanded vertex b to the Chebyshev centre of its star's kernel; true if it moved. The
  // move is optional: a non-exact run skips it when rounding would leave the kernel.
  bool recentre(VertexId b) {
    const Placement p = place(gather_expansion_cone(e_, b), nullptr);
    if (!p.ok() || p.rounded_outside || p.position == e_.target[b]) return false;
    e_.target[b] = p.position;
    ++stats_.relaxations;
    max_bits_ = std::max(max_bits_, p.position.bit_size());
    dirty_star(b);
    require_valid(b, "re-centring", &p);
    return true;
  }

  // --- star-shapification by pushes ------------------------------------------------------------
  // A push moves a base vertex b of v out of v's base: the spoke (v, b) is split at a new cluster
  // vertex at p_c. Base vertices are pushed away from a kept triangle T until v's cone has
  // interior; it has when the base is T alone (a triangle's cone always has interior), so at most
  // |base| - 3 pushes are needed. Pushes are chosen on a virtual state first (the chosen vertices
  // flagged as cluster vertices at p_c, which is exactly v's star after the real pushes) and made
  // only when they succeed, then v is expanded, then the pushed vertices, last first, each now
  // between v and its base vertex.

  bool star_shapify(VertexId v, int k, int depth, bool leaves) {
    ConeBase base = cone_base(e_, v);
    if (base.triangles.empty()) return false;
    const auto [w, keep] = choose_witness(base);
    std::vector<std::pair<VertexId, HPoint>> virtual_pushes;
    auto undo_virtual = [&] {
      for (auto it = virtual_pushes.rbegin(); it != virtual_pushes.rend(); ++it) {
        e_.unexpanded[it->first] = 0;
        e_.target[it->first] = it->second;
      }
    };
    Placement p;
    for (;;) {
      p = place(gather_expansion_cone(e_, v), &w);
      if (p.ok()) break;
      base = cone_base(e_, v);
      const std::optional<VertexId> b = choose_push(v, w, keep, base, leaves);
      if (!b) {
        undo_virtual();
        return false;
      }
      virtual_pushes.emplace_back(*b, e_.target[*b]);
      e_.unexpanded[*b] = 1;
      e_.target[*b] = e_.center;
    }
    undo_virtual();
    std::vector<VertexId> pushed;
    for (const auto& [b, position] : virtual_pushes) {
      pushed.push_back(push(v, b));
      ++stats_.pushes;
    }
    expand_to(v, p.position, k, &p);
    ++stats_.expansions_star_shapified;
    if (depth + 1 < max_depth)
      for (auto it = pushed.rbegin(); it != pushed.rend(); ++it)
        if (e_.unexpanded[*it]) refine_and_expand(*it, depth + 1);
    return true;
  }

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

  bool bend_and_expand(VertexId v, int k) {
    ConeBase base = cone_base(e_, v);
    if (base.triangles.empty() || has_dangling_edge(base)) return false;
    const auto [w, keep] = choose_witness(base);
    const HPoint aim = centroid(e_, keep);

    struct Bend {
      VertexId b;
      HPoint original, q;
    };
    std::vector<Bend> bends;
    std::unordered_map<VertexId, int> bent;
    auto undo_virtual = [&] {
      for (auto it = bends.rbegin(); it != bends.rend(); ++it) e_.target[it->b] = it->original;
    };
    const std::size_t cap = 2 * base.verts.size() + 8;
    Placement p;
    for (;;) {
      p = place(gather_expansion_cone(e_, v), &w);
      if (p.ok()) break;
      if (bends.size() >= cap) {
        undo_virtual();
        return false;
      }
      std::optional<HPoint> q;
      VertexId b = 0;
      const auto bl = blockers(v, aim);
      // Fix both boundary edges at a blocker if possible, else one, else move it inward.
      for (int level = 0; level < 3 && !q; ++level)
        for (const auto& [count, x] : bl) {
          if (bent[x] >= 2) continue;
          ExpansionCone cone = bend_cone(e_, v, x);
          if (level < 2) add_aim_constraints(cone, e_, v, x, aim, level == 1);
          const Placement r = place(cone, nullptr);
          if (!r.ok()) continue;
          q = r.position;
          b = x;
          break;
        }
      if (!q) {
        undo_virtual();
        return false;
      }
      ++bent[b];
      bends.push_back({b, e_.target[b], *q});
      e_.target[b] = *q;
    }
    undo_virtual();
    // Make the bends: each split's new vertex replaces the previous one of its chain in v's link.
    std::unordered_map<VertexId, VertexId> current;
    for (const Bend& bend : bends) {
      const VertexId from = current.count(bend.b) ? current[bend.b] : bend.b;
      const VertexId m = e_.split_edge(v, from, bend.q, false);
      grow();
      current[bend.b] = m;
      ++stats_.bends;
      max_bits_ = std::max(max_bits_, bend.q.bit_size());
      require_valid(m, "a bend", nullptr);
    }
    expand_to(v, p.position, k, &p);
    ++stats_.expansions_star_shapified;
    return true;
  }

  // Expanded endpoints of v's side constraints that hide `aim`, most often first.
  std::vector<std::pair<int, VertexId>> blockers(VertexId v, const HPoint& aim) const {
    std::vector<std::pair<int, VertexId>> out;
    for (const auto& [x, count] : blocking_endpoints(e_, v, aim)) out.emplace_back(-count, x);
    std::sort(out.begin(), out.end());
    return out;
  }

  // Ears first (the base stays a disc), then vertices blocking the direction toward the kept
  // triangle most often, then the farthest from the witness in base edges, then the fewest base
  // triangles. Only vertices on a base triangle: a pushed vertex then has a base of two fans over
  // an arc of at least two vertices rather than a bare path, which would need inflation in turn.
  std::optional<VertexId> choose_push(VertexId v, VertexId w, const std::array<VertexId, 3>& keep, ConeBase& base,
                                      bool leaves) const {
    std::unordered_map<VertexId, int> dist = base_distances(base, w);
    std::unordered_map<VertexId, int> blocks = blocking_endpoints(e_, v, centroid(e_, keep));
    std::optional<VertexId> best;
    std::tuple<int, int, int, int, VertexId> best_key{};
    for (VertexId b : base.verts) {
      if (std::find(keep.begin(), keep.end(), b) != keep.end() || (base.tets[b] == 0 && !leaves) || !is_pushable(e_, v, b))
        continue;
      const std::tuple<int, int, int, int, VertexId> key{is_ear(e_, v, b) ? 0 : 1, -blocks[b],
                                                         -(dist.count(b) ? dist[b] : 1 << 20), base.tets[b], b};
      if (!best || key < best_key) {
        best = b;
        best_key = key;
      }
    }
    return best;
  }

  // --- inflation -----------------------------------------------------------------------------
  // A base edge (a, b) in no base triangle has cluster vertices u, u' on both sides in Lk(v): the
  // side planes through p_c, a, b face each other and flatten the kernel (paper Sec. 3.1, Fig. 4).
  // Inflation splits the edge (b, u) (or (a, u), (b, u'), (a, u')) at a new vertex x, pushed to
  // p_c and expanded at once (its unexpanded link is the cone from u, so Eq. (1) holds); (a, b, x)
  // is then a base triangle of v. An x that cannot be expanded is collapsed back into u, which
  // restores the mesh exactly: inflation never leaves refinement behind without progress.
  // Attempts per vertex are bounded; the refinement budget bounds the total.

  bool inflate(VertexId v, int depth) {
    if (depth + 1 >= max_depth || ++inflations_[v] > 4) return false;
    bool progress = false;
    for (const auto& [a, b, u1, u2] : dangling_edges(e_, v)) {
      if (!e_.unexpanded[v]) break;
      if (!e_.unexpanded[u1] || !e_.unexpanded[u2]) continue;  // changed by an earlier inflation
      for (const auto& [end, u] : {std::pair{b, u1}, std::pair{a, u1}, std::pair{b, u2}, std::pair{a, u2}}) {
        if (topology::tets_around_edge(e_.mesh, end, u).empty()) continue;
        const VertexId x = push(u, end);
        if (refine_and_expand(x, depth + 1)) {
          ++stats_.inflation_splits;
          progress = true;
          break;
        }
        if (!e_.unexpanded[x]) break;  // expanded after all, by a deeper refinement
        undo_push(u, x);
      }
    }
    dirty(v);
    if (progress) ++stats_.expansions_inflated;
    return progress;
  }

  // The last round's pushes for inflation's new vertices: real pushes one at a time, farthest from
  // the witness first, kept even when the cone does not open (measured, on the case without
  // interior vertices (P07) this partial progress is what lets the last round finish).
  bool push_until_star_shaped(VertexId v, int k) {
    ConeBase base = cone_base(e_, v);
    if (base.triangles.empty()) return false;
    const auto [w, keep] = choose_witness(base);
    for (;;) {
      const Placement p = place(gather_expansion_cone(e_, v), &w);
      if (p.ok()) {
        expand_to(v, p.position, k, &p);
        ++stats_.expansions_star_shapified;
        return true;
      }
      base = cone_base(e_, v);
      std::unordered_map<VertexId, int> dist = base_distances(base, w);
      std::optional<VertexId> best;
      std::tuple<int, int, VertexId> best_key{};
      for (VertexId b : base.verts) {
        if (std::find(keep.begin(), keep.end(), b) != keep.end() || base.tets[b] == 0 || !is_pushable(e_, v, b)) continue;
        const std::tuple<int, int, VertexId> key{-(dist.count(b) ? dist[b] : 1 << 20), base.tets[b], b};
        if (!best || key < best_key) best = b, best_key = key;
      }
      if (!best) return false;
      push(v, *best);
      ++stats_.pushes;
      if (check_limits()) return false;
    }
  }

  bool paper_inflate(VertexId v, int depth) {
    if (depth + 1 >= max_depth || ++inflations_[v] > 4) return false;
    std::vector<VertexId> added;
    for (VertexId b : topology::expanded_link_cut_vertices(e_.mesh, v, e_.unexpanded)) {
      std::vector<VertexId> cs;
      for (TetId t : topology::tets_around_edge(e_.mesh, v, b))
        for (VertexId c : e_.mesh.tet(t))
          if (c != v && e_.unexpanded[c]) cs.push_back(c);
      std::sort(cs.begin(), cs.end());
      cs.erase(std::unique(cs.begin(), cs.end()), cs.end());
      for (VertexId c : cs) {
        added.push_back(push(c, b));
        ++stats_.inflation_splits;
      }
    }
    if (added.empty()) return false;
    for (bool progress = true; progress && !added.empty();) {
      progress = false;
      for (auto it = added.begin(); it != added.end();) {
        if (!e_.unexpanded[*it] || isolate(*it)) {
          it = added.erase(it);
          progress = true;
        } else {
          ++it;
        }
      }
    }
    dirty(v);
    if (added.empty()) ++stats_.expansions_inflated;
    return added.empty();
  }

  bool isolate(VertexId x) {
    const Relabel relabel(label_, "refinement");
    const topology::ClusterVertexStatus st = topology::classify_cluster_vertex(e_.mesh, x, e_.unexpanded, ws_);
    if (!st.expandable) return false;
    if (try_simple(x, st.manifold_k)) return true;
    if (!topology::expanded_link_cut_vertices(e_.mesh, x, e_.unexpanded).empty()) return false;
    return push_until_star_shaped(x, st.manifold_k);
  }

  Embedding& e_;
  const ExpansionSettings& s_;
  MapStatistics& stats_;
  topology::ClusterLinkWorkspace ws_;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue_;
  std::vector<std::uint32_t> version_;
  std::vector<std::optional<Placement>> cached_;
  std::vector<char> is_dirty_;
  std::vector<VertexId> dirty_;
  std::unordered_map<VertexId, int> inflations_, relaxed_moves_;
  std::size_t cluster_ = 0, expanded_ = 0, failures_ = 0, max_bits_ = 0;
  bool aggressive_ = false;
  std::vector<VertexId> recent_;  // expanded since the last smoothing
  std::size_t next_smooth_ = 0;
  std::vector<char> guess_wrong_;  // 1: the float guess of v's cone was wrong once; decide exactly
  const char* label_ = "";  // the kind of expansion under way, for the trace
  std::chrono::steady_clock::time_point last_report_{};
};

}  // namespace

ExpansionOutcome expand_cluster(Embedding& e, const ExpansionSettings& settings, MapStatistics& stats) {
  return ClusterExpander(e, settings, stats).run();
}

}  // namespace cmx::algorithm
