#include "algorithm/cluster_expansion.hpp"

#include <algorithm>
#include <array>
#include <deque>
#include <queue>
#include <unordered_map>

#include "algorithm/expansion_cone.hpp"
#include "algorithm/invariants.hpp"
#include "algorithm/map_error.hpp"
#include "algorithm/placement.hpp"
#include "topology/cluster_links.hpp"
#include "topology/complex_queries.hpp"

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
      if (!next) return stuck();
      handle(*next);
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

  std::array<std::int64_t, 4> key(Kind kind, int k, std::uint32_t expanded_neighbors, VertexId v) const {
    switch (s_.order.kind) {
      case topology::ExpansionOrderKind::index: return {kind == Kind::automatic ? 0 : 1, 0, 0, v};
      case topology::ExpansionOrderKind::random:
        return {kind == Kind::automatic ? 0 : 1, 0, 0, std::int64_t(splitmix(s_.order.seed ^ splitmix(v)) >> 1)};
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
      const ExpansionCone cone = gather_expansion_cone(e_, v);
      if (cone.base_tets == 0) {
        kind = Kind::inflate;
      } else {
        Placement p = place(cone, nullptr);
        kind = p.ok() ? Kind::simple : Kind::star_shapify;
        if (p.ok()) cached_[v] = std::move(p);
      }
    }
    queue_.push({key(kind, st.manifold_k, st.expanded_neighbors, v), version_[v], v, kind,
                 std::uint8_t(st.manifold_k)});
  }

  Placement place(const ExpansionCone& cone, const VertexId* witness) {
    Placement p = witness ? place_in_cone(cone, s_.placement, &e_.center, &e_.target[*witness])
                          : place_in_cone(cone, s_.placement);
    ++stats_.lps;
    if (p.info.certified) ++stats_.lps_certified;
    if (p.info.fell_back) ++stats_.lps_fell_back;
    return p;
  }

  // --- operations --------------------------------------------------------------------------

  void handle(const Entry& entry) {
    const VertexId v = entry.v;
    switch (entry.kind) {
      case Kind::automatic:
        expand_to(v, e_.center, entry.k);
        ++stats_.expansions_automatic;
        return;
      case Kind::simple: {
        std::optional<Placement> p = std::move(cached_[v]);
        if (!p) p = place(gather_expansion_cone(e_, v), nullptr);
        if (!p->ok()) throw MapError(MapErrorKind::internal, "a simple cone lost its interior", "vertex " + std::to_string(v));
        expand_to(v, p->position, entry.k);
        ++stats_.expansions_simple;
        return;
      }
      case Kind::star_shapify:
        if (star_shapify(v, entry.k)) {
          ++stats_.expansions_star_shapified;
        } else {
          ++failures_;
          dirty_star(v);  // pushes may have changed neighbours; v itself waits for a change
          is_dirty_[v] = 0;
          dirty_.erase(std::remove(dirty_.begin(), dirty_.end(), v), dirty_.end());
        }
        return;
      case Kind::inflate:
        if (!inflate(v)) ++failures_;
        return;
    }
  }

  void expand_to(VertexId v, const HPoint& position, int k) {
    e_.target[v] = position;
    e_.unexpanded[v] = 0;
    --cluster_;
    ++expanded_;
    ++stats_.k_manifold[k >= 1 && k <= 3 ? k : 0];
    max_bits_ = std::max(max_bits_, position.bit_size());
    ++version_[v];
    if (std::string why = check_local_invariant(e_, v); !why.empty())
      throw MapError(MapErrorKind::internal, "expansion broke an invariant: " + why, "vertex " + std::to_string(v));
    if (s_.check) check_all("after expanding vertex " + std::to_string(v));
    dirty_star(v);
  }

  void check_all(const std::string& when) const {
    if (std::string why = check_invariants(e_, *s_.prescribed); !why.empty())
      throw MapError(MapErrorKind::internal, "invariant violated " + when + ": " + why);
  }

  // Splits edge (c, b) from cluster vertex c to expanded vertex b at a new cluster vertex at p_c.
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

  // --- star-shapification by pushes ---------------------------------------------------------

  struct Base {
    std::vector<VertexId> verts;                       // expanded neighbours of v
    std::unordered_map<VertexId, std::vector<VertexId>> adj;  // base edges
    std::unordered_map<VertexId, int> tets;            // base tets containing each vertex
    std::vector<std::array<VertexId, 3>> triangles;
  };

  Base base_of(VertexId v) const {
    Base b;
    for (TetId t : e_.mesh.tets_of(v)) {
      std::array<VertexId, 3> ex{};
      int n = 0;
      for (VertexId w : e_.mesh.tet(t))
        if (w != v && !e_.unexpanded[w]) ex[n++] = w;
      for (int i = 0; i < n; ++i) {
        b.verts.push_back(ex[i]);
        for (int j = 0; j < n; ++j)
          if (i != j) b.adj[ex[i]].push_back(ex[j]);
      }
      if (n == 3) {
        b.triangles.push_back(ex);
        for (VertexId w : ex) ++b.tets[w];
      }
    }
    std::sort(b.verts.begin(), b.verts.end());
    b.verts.erase(std::unique(b.verts.begin(), b.verts.end()), b.verts.end());
    return b;
  }

  // b's neighbours in Lk(v) (the link of edge vb) are one run of cluster vertices and one run of
  // expanded vertices: pushing b keeps Eq. (1) for v.
  bool pushable(VertexId v, VertexId b) const {
    std::unordered_map<VertexId, int> seen;
    int cluster_edges = 0;
    for (TetId t : topology::tets_around_edge(e_.mesh, v, b)) {
      VertexId xy[2];
      int n = 0;
      for (VertexId w : e_.mesh.tet(t))
        if (w != v && w != b) xy[n++] = w;
      seen[xy[0]] = 1;
      seen[xy[1]] = 1;
      if (e_.unexpanded[xy[0]] && e_.unexpanded[xy[1]]) ++cluster_edges;
    }
    int in_cluster = 0, expanded = 0;
    for (const auto& [w, one] : seen) (e_.unexpanded[w] ? in_cluster : expanded) += one;
    return in_cluster >= 1 && expanded >= 1 && in_cluster - cluster_edges == 1;
  }

  bool star_shapify(VertexId v, int k) {
    Base base = base_of(v);
    if (base.triangles.empty()) return false;
    // Witness: the base vertex in most base tets; kept: one base triangle through it.
    VertexId w = base.verts.front();
    for (VertexId x : base.verts)
      if (base.tets[x] > base.tets[w]) w = x;
    std::array<VertexId, 3> keep{};
    for (const auto& tri : base.triangles)
      if (std::find(tri.begin(), tri.end(), w) != tri.end()) {
        keep = tri;
        break;
      }
    for (;;) {
      const Placement p = place(gather_expansion_cone(e_, v), &w);
      if (p.ok()) {
        expand_to(v, p.position, k);
        return true;
      }
      base = base_of(v);
      const std::optional<VertexId> b = choose_push(v, w, keep, base);
      if (!b) return false;
      push(v, *b);
      ++stats_.pushes;
      if (auto stop = check_limits()) return false;
    }
  }

  // The pushable base vertex farthest from the witness (in base edges), fewest base tets first.
  std::optional<VertexId> choose_push(VertexId v, VertexId w, const std::array<VertexId, 3>& keep, Base& base) const {
    std::unordered_map<VertexId, int> dist;
    std::deque<VertexId> q{w};
    dist[w] = 0;
    while (!q.empty()) {
      const VertexId x = q.front();
      q.pop_front();
      for (VertexId y : base.adj[x])
        if (!dist.count(y)) {
          dist[y] = dist[x] + 1;
          q.push_back(y);
        }
    }
    std::optional<VertexId> best;
    std::tuple<int, int, VertexId> best_key{};
    for (VertexId b : base.verts) {
      if (std::find(keep.begin(), keep.end(), b) != keep.end() || !pushable(v, b)) continue;
      const std::tuple<int, int, VertexId> key{-(dist.count(b) ? dist[b] : 1 << 20), base.tets[b], b};
      if (!best || key < best_key) {
        best = b;
        best_key = key;
      }
    }
    return best;
  }

  // --- inflation -----------------------------------------------------------------------------

  bool inflate(VertexId v) {
    if (++inflations_[v] > 2) return false;
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
    // Cluster isolation: expand the new vertices one by one, in passes while any succeeds.
    for (bool progress = true; progress && !added.empty();) {
      progress = false;
      for (auto it = added.begin(); it != added.end();) {
        if (expand_isolated(*it)) {
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

  bool expand_isolated(VertexId x) {
    const topology::ClusterVertexStatus st = topology::classify_cluster_vertex(e_.mesh, x, e_.unexpanded, ws_);
    if (!st.expandable) return false;
    const ExpansionCone cone = gather_expansion_cone(e_, x);
    if (cone.base_tets == 0) return false;
    const Placement p = place(cone, nullptr);
    if (p.ok()) {
      expand_to(x, p.position, st.manifold_k);
      ++stats_.expansions_simple;
      return true;
    }
    if (!star_shapify(x, st.manifold_k)) return false;
    ++stats_.expansions_star_shapified;
    return true;
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
  std::unordered_map<VertexId, int> inflations_;
  std::size_t cluster_ = 0, expanded_ = 0, failures_ = 0, max_bits_ = 0;
  std::chrono::steady_clock::time_point last_report_{};
};

}  // namespace

ExpansionOutcome expand_cluster(Embedding& e, const ExpansionSettings& settings, MapStatistics& stats) {
  return ClusterExpander(e, settings, stats).run();
}

}  // namespace cmx::algorithm
