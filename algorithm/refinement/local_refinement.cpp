// Local refinement of the expansion loop (ClusterExpander, cluster_expander.hpp): what runs when a
// popped vertex is not simply expandable (docs/algorithm/expansion.md: relaxation, star-shapification by
// pushes and bends, inflation with cluster isolation).
#include <algorithm>
#include <tuple>
#include <unordered_map>

#include "algorithm/expansion/cluster_expander.hpp"
#include "algorithm/tuning.hpp"
#include "topology/complex_queries.hpp"

namespace cmx::algorithm::detail {
namespace {

// Distance of b from the witness in base edges; a vertex the witness does not reach counts as
// farther than any reached one (a base has far fewer than 2^20 vertices).
int witness_distance(const std::unordered_map<VertexId, int>& dist, VertexId b) {
  const auto it = dist.find(b);
  return it == dist.end() ? 1 << 20 : it->second;
}

}  // namespace

bool ClusterExpander::try_simple(VertexId v, int k) {
  const ExpansionCone cone = gather_expansion_cone(e_, v);
  if (cone.base_tets == 0) return false;
  const Placement p = place(cone, nullptr);
  if (!p.ok()) return false;
  expand_to(v, p.position, k, &p);
  ++stats_.expansions_simple;
  return true;
}

// The expanded non-boundary vertices of v's base move to the (precision-reduced) Chebyshev
// centres of their own stars' kernels. Such a move keeps every invariant (the kernel is exactly
// where every tet around the vertex keeps its state) and adds nothing; a cone that was only
// squeezed by neighbours crowding near p_c often opens. Bounded: each vertex moves at most
// twice (moves dirty their neighbours, which must not become an endless exchange).
bool ClusterExpander::relax_base(VertexId v) {
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
bool ClusterExpander::recentre(VertexId b) {
  const Placement p = place(gather_expansion_cone(e_, b), nullptr);  // counted with the loop's LPs
  if (!move_to_placement(e_, b, p)) return false;
  ++stats_.relaxations;
  max_bits_ = std::max(max_bits_, p.position.bit_size());
  queue_.mark_star(b);
  require_valid(b, "re-centring", &p);
  return true;
}

bool ClusterExpander::star_shapify(VertexId v, int k, int depth, bool leaves) {
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

bool ClusterExpander::bend_and_expand(VertexId v, int k) {
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
  const std::size_t cap = tuning::bends_per_base_vertex * base.verts.size() + tuning::bends_beyond_base;
  Placement p;
  for (;;) {
    p = place(gather_expansion_cone(e_, v), &w);
    if (p.ok()) break;
    if (bends.size() >= cap) {
      undo_virtual();
      return false;
    }
    std::optional<HPoint> q;
    VertexId b{0};
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
std::vector<std::pair<int, VertexId>> ClusterExpander::blockers(VertexId v, const HPoint& aim) const {
  std::vector<std::pair<int, VertexId>> out;
  for (const auto& [x, count] : blocking_endpoints(e_, v, aim)) out.emplace_back(-count, x);
  std::sort(out.begin(), out.end());
  return out;
}

// Ears first (the base stays a disc), then vertices blocking the direction toward the kept
// triangle most often, then the farthest from the witness in base edges, then the fewest base
// triangles. Only vertices on a base triangle: a pushed vertex then has a base of two fans over
// an arc of at least two vertices rather than a bare path, which would need inflation in turn.
std::optional<VertexId> ClusterExpander::choose_push(VertexId v, VertexId w,
                                                     const std::array<VertexId, 3>& keep, ConeBase& base,
                                                     bool leaves) const {
  std::unordered_map<VertexId, int> dist = base_distances(base, w);
  std::unordered_map<VertexId, int> blocks = blocking_endpoints(e_, v, centroid(e_, keep));
  std::optional<VertexId> best;
  std::tuple<int, int, int, int, VertexId> best_key{};
  for (VertexId b : base.verts) {
    if (std::find(keep.begin(), keep.end(), b) != keep.end() || (base.tets[b] == 0 && !leaves) ||
        !is_pushable(e_, v, b))
      continue;
    const std::tuple<int, int, int, int, VertexId> key{is_ear(e_, v, b) ? 0 : 1, -blocks[b],
                                                       -witness_distance(dist, b), base.tets[b], b};
    if (!best || key < best_key) {
      best = b;
      best_key = key;
    }
  }
  return best;
}

bool ClusterExpander::inflate(VertexId v, int depth) {
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
  queue_.mark(v);
  if (progress) ++stats_.expansions_inflated;
  return progress;
}

bool ClusterExpander::inflate_isolated(VertexId v, const ConeBase& base, int depth) {
  if (depth + 1 >= max_depth || ++inflations_[v] > 4) return false;
  for (VertexId b : base.verts) {
    std::vector<VertexId> ring;  // the cluster vertices around spoke (v, b), each tried once
    for (const auto& [p, q] : spoke_ring(e_, v, b))
      for (VertexId u : {p, q})
        if (e_.unexpanded[u] && std::find(ring.begin(), ring.end(), u) == ring.end()) ring.push_back(u);
    for (VertexId u : ring) {
      if (!e_.unexpanded[v]) return true;  // expanded after all, by a deeper refinement
      if (!e_.unexpanded[u] || topology::tets_around_edge(e_.mesh, u, b).empty()) continue;
      const VertexId x = push(u, b);
      if (refine_and_expand(x, depth + 1)) {
        ++stats_.inflation_splits;
        ++stats_.isolated_inflations;
        queue_.mark(v);
        return true;
      }
      if (!e_.unexpanded[x]) return true;
      undo_push(u, x);
    }
  }
  return !e_.unexpanded[v];
}

// The last round's pushes for inflation's new vertices: real pushes one at a time, farthest from
// the witness first, kept even when the cone does not open: on inputs without interior vertices
// this partial progress is what lets the last round finish.
bool ClusterExpander::push_until_star_shaped(VertexId v, int k) {
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
      if (std::find(keep.begin(), keep.end(), b) != keep.end() || base.tets[b] == 0 || !is_pushable(e_, v, b))
        continue;
      const std::tuple<int, int, VertexId> key{-witness_distance(dist, b), base.tets[b], b};
      if (!best || key < best_key) best = b, best_key = key;
    }
    if (!best) return false;
    push(v, *best);
    ++stats_.pushes;
    if (check_limits()) return false;
  }
}

bool ClusterExpander::paper_inflate(VertexId v, int depth) {
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
  queue_.mark(v);
  if (added.empty()) ++stats_.expansions_inflated;
  return added.empty();
}

bool ClusterExpander::isolate(VertexId x) {
  const Relabel relabel(label_, "refinement");
  const topology::ClusterVertexStatus st = topology::classify_cluster_vertex(e_.mesh, x, e_.unexpanded, ws_);
  if (!st.expandable) return false;
  if (try_simple(x, st.manifold_k)) return true;
  if (!topology::expanded_link_cut_vertices(e_.mesh, x, e_.unexpanded).empty()) return false;
  return push_until_star_shaped(x, st.manifold_k);
}

}  // namespace cmx::algorithm::detail
