// The fallback star-shapification of the expansion loop (ClusterExpander::shelled_star_shapify,
// cluster_expander.hpp): it pushes v's base away until only one fan of its witness is left, so
// that it does not depend on where the base vertices are. docs/algorithm/expansion.md
// ("Star-shapification by shelling") has the argument and what it does not prove.
#include <algorithm>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "algorithm/expansion/cluster_expander.hpp"
#include "algorithm/map_error.hpp"
#include "topology/complex_queries.hpp"
#include "topology/disc_shelling.hpp"

namespace cmx::algorithm::detail {
namespace {

// Base edges in no base triangle with both ends in `within`, each counted once.
int dangling_count(const ConeBase& base, const std::unordered_set<VertexId>& within) {
  std::unordered_set<std::uint64_t> in_triangle, dangling;
  auto key = [](VertexId a, VertexId b) {
    return (std::uint64_t{std::min(a, b)} << 32) | std::uint64_t{std::max(a, b)};
  };
  for (const auto& t : base.triangles)
    for (int i = 0; i < 3; ++i) in_triangle.insert(key(t[i], t[(i + 1) % 3]));
  for (const auto& [a, nbrs] : base.adj)
    for (VertexId b : nbrs)
      if (!in_triangle.count(key(a, b)) && within.count(a) && within.count(b)) dangling.insert(key(a, b));
  return static_cast<int>(dangling.size());
}

// Edge (a, b) lies on the mesh boundary: some face through it is in one tet only. A split there
// would make a boundary vertex that the boundary does not prescribe, so such edges are not split.
bool on_mesh_boundary(const Embedding& e, VertexId a, VertexId b) {
  return e.boundary[a] && e.boundary[b] && topology::edge_on_boundary(e.mesh, a, b);
}

// The fan of w that refinement keeps: the base triangles through w whose other edges form the
// largest connected piece of w's link in the base (a cut vertex w has several; two fans seen from
// p_c around one point leave no kernel). Its vertices, w included.
std::unordered_set<VertexId> kept_fan(const ConeBase& base, VertexId w) {
  std::vector<std::array<VertexId, 2>> link;  // the edge opposite w of each triangle through w
  for (const auto& t : base.triangles)
    for (int i = 0; i < 3; ++i)
      if (t[i] == w) link.push_back({t[(i + 1) % 3], t[(i + 2) % 3]});
  std::unordered_set<VertexId> best;
  std::size_t best_edges = 0;
  std::vector<char> used(link.size(), 0);
  for (std::size_t seed = 0; seed < link.size(); ++seed) {
    if (used[seed]) continue;
    std::unordered_set<VertexId> piece{link[seed][0], link[seed][1]};
    std::size_t edges = 0;
    for (bool grew = true; grew;) {  // fans are short: a quadratic sweep is enough
      grew = false;
      for (std::size_t i = 0; i < link.size(); ++i)
        if (!used[i] && (piece.count(link[i][0]) || piece.count(link[i][1]))) {
          used[i] = 1;
          piece.insert(link[i].begin(), link[i].end());
          ++edges;
          grew = true;
        }
    }
    if (edges > best_edges) best = std::move(piece), best_edges = edges;
  }
  best.insert(w);
  return best;
}

bool in_fan(const std::array<VertexId, 3>& t, VertexId w, const std::unordered_set<VertexId>& fan) {
  return std::find(t.begin(), t.end(), w) != t.end() && fan.count(t[0]) && fan.count(t[1]) && fan.count(t[2]);
}

// Only the kept fan is left: every base triangle is one of its triangles, and no base edge lies
// outside the triangles.
bool only_fan_left(const ConeBase& base, VertexId w, const std::unordered_set<VertexId>& fan) {
  return std::all_of(base.triangles.begin(), base.triangles.end(),
                     [&](const auto& t) { return in_fan(t, w, fan); }) &&
         !has_dangling_edge(base);
}

// The witnesses a plan is tried with, best first: the three base vertices in the most base
// triangles, smallest id among equals (the first is choose_witness's choice). Another witness
// helps where the first one's fan has a triangle beside it with a free edge on the mesh boundary,
// which no split may remove.
std::vector<VertexId> witnesses(const ConeBase& base) {
  std::vector<std::pair<int, VertexId>> order;
  for (const auto& [x, triangles] : base.tets) order.emplace_back(-triangles, x);
  std::sort(order.begin(), order.end());
  std::vector<VertexId> out;
  for (std::size_t i = 0; i < order.size() && i < 3; ++i) out.push_back(order[i].second);
  return out;
}

}  // namespace

// Splits base edge (a, b) at its target and source midpoints, as an expanded vertex. Every tet
// around the edge becomes two tets of its own sign, so every invariant holds after it. Like the
// pushes below it leaves the queue alone: a failed attempt is undone exactly and must not make
// v a candidate again (it waits until its star changes), a kept one marks what it changed.
VertexId ClusterExpander::split_base_edge(VertexId a, VertexId b) {
  const VertexId s = e_.split_edge(a, b, midpoint(e_.target[a], e_.target[b]), false);
  max_bits_ = std::max(max_bits_, e_.target[s].bit_size());
  require_valid(s, "a base edge split", nullptr);
  return s;
}

// Collapses the edit's new vertex back: the mesh is exactly as before the edit.
void ClusterExpander::undo_edit(VertexId v, const ShellingEdit& edit) {
  const topology::CollapseResult r = e_.collapse_edge(edit.split ? edit.vertex : v, edit.added);
  if (!r.ok) throw MapError(MapErrorKind::internal, "could not undo a shelling edit: " + r.message);
  if (!edit.split) {
    e_.unexpanded[edit.added] = 0;
    --cluster_;
  }
}

void ClusterExpander::undo_shelling(VertexId v, std::vector<ShellingEdit>& edits) {
  for (auto it = edits.rbegin(); it != edits.rend(); ++it) undo_edit(v, *it);
  edits.clear();
}

// Pushes x if v still satisfies Eq. (1) after it (is_pushable's count alone does not ensure that
// once the base has dangling edges) and no dangling base edge is left between two vertices of the
// kept fan (one with an end outside the fan goes when that end is pushed).
bool ClusterExpander::try_push(VertexId v, VertexId x, const std::unordered_set<VertexId>& fan,
                               std::vector<ShellingEdit>& edits) {
  if (!is_pushable(e_, v, x)) return false;
  const VertexId c = e_.split_edge(v, x, e_.center, true);
  ++cluster_;
  const ShellingEdit edit{false, x, c};
  if (dangling_count(cone_base(e_, v), fan) > 0 ||
      !topology::classify_cluster_vertex(e_.mesh, v, e_.unexpanded, ws_).expandable) {
    undo_edit(v, edit);
    return false;
  }
  edits.push_back(edit);
  return true;
}

// The disc case: one push per step of a shelling of the base onto star(w). False when the base
// is not a disc or a step cannot be made; the pushes made so far are valid and stay.
bool ClusterExpander::push_along_shelling(VertexId v, VertexId w, std::vector<ShellingEdit>& edits) {
  const ConeBase base = cone_base(e_, v);
  if (has_dangling_edge(base) || !topology::is_disc(base.triangles)) return false;
  const topology::DiscShelling shelling = topology::shell_disc_onto_star(base.triangles, w);
  if (!shelling.complete) return false;
  const std::unordered_set<VertexId> fan = kept_fan(base, w);
  for (const topology::DiscShellingStep& step : shelling.steps) {
    if (step.kind == topology::DiscShellingKind::ear) {
      if (!try_push(v, step.apex, fan, edits)) return false;
      continue;
    }
    if (on_mesh_boundary(e_, step.free_edge[0], step.free_edge[1])) return false;
    const VertexId s = split_base_edge(step.free_edge[0], step.free_edge[1]);
    edits.push_back({true, step.free_edge[0], s});
    if (!try_push(v, s, fan, edits)) return false;
  }
  return true;
}

// Any simply connected base: repeatedly push the base vertex outside the kept fan farthest from w
// that can go; when none can, remove a base triangle outside the fan through a free edge (split at
// its midpoint, which is then pushed). Each edit removes base triangles or dangling edges; it may
// leave dangling edges with an end outside the fan, which pushing that end removes later. A bound
// on the rounds ends a search that does not get there.
bool ClusterExpander::push_greedily_onto_star(VertexId v, VertexId w, std::vector<ShellingEdit>& edits) {
  const ConeBase first = cone_base(e_, v);
  const std::unordered_set<VertexId> keep = kept_fan(first, w);
  if (dangling_count(first, keep) > 0) return false;  // a chord of the fan: no push removes it
  const std::size_t bound = 2 * (first.triangles.size() + first.verts.size()) + 16;
  for (std::size_t round = 0;; ++round) {
    const ConeBase base = cone_base(e_, v);
    if (only_fan_left(base, w, keep)) return true;
    if (round >= bound) return false;
    const std::unordered_map<VertexId, int> dist = base_distances(base, w);
    std::vector<std::tuple<int, int, VertexId>> order;  // farthest first, then fewest triangles
    for (VertexId x : base.verts) {
      if (keep.count(x) || !base.adj.count(x)) continue;  // isolated vertices constrain nothing
      const auto d = dist.find(x);
      const auto t = base.tets.find(x);
      order.emplace_back(d == dist.end() ? -(1 << 20) : -d->second, t == base.tets.end() ? 0 : t->second, x);
    }
    std::sort(order.begin(), order.end());
    bool done = false;
    for (const auto& [negative_distance, triangles, x] : order)
      if ((done = try_push(v, x, keep, edits))) break;
    if (done) continue;
    for (const auto& t : base.triangles) {
      if (in_fan(t, w, keep)) continue;
      for (int i = 0; i < 3 && !done; ++i) {
        const VertexId a = t[i], b = t[(i + 1) % 3];
        const auto shared = std::count_if(base.triangles.begin(), base.triangles.end(), [&](const auto& u) {
          return std::find(u.begin(), u.end(), a) != u.end() && std::find(u.begin(), u.end(), b) != u.end();
        });
        if (shared != 1 || on_mesh_boundary(e_, a, b)) continue;
        edits.push_back({true, a, split_base_edge(a, b)});
        if ((done = try_push(v, edits.back().added, keep, edits))) break;
        undo_edit(v, edits.back());
        edits.pop_back();
      }
      if (done) break;
    }
    if (!done) return false;
  }
}

bool ClusterExpander::shelled_star_shapify(VertexId v, int k, int depth) {
  // The refinement tried before (inflation above all) may have changed v's link since v was
  // classified; every plan starts from a v that satisfies Eq. (1).
  if (!topology::classify_cluster_vertex(e_.mesh, v, e_.unexpanded, ws_).expandable) return false;
  const ConeBase base = cone_base(e_, v);
  if (base.triangles.empty()) return false;
  const Relabel relabel(label_, "shelled");
  std::vector<ShellingEdit> edits;
  Placement p;
  VertexId w{0};
  for (VertexId candidate : witnesses(base)) {
    w = candidate;
    if (only_fan_left(base, w, kept_fan(base, w))) return false;  // nothing to push: the cone is what it is
    if ((push_along_shelling(v, w, edits) || push_greedily_onto_star(v, w, edits)) &&
        (p = place(gather_expansion_cone(e_, v), &w)).ok())
      break;
    undo_shelling(v, edits);
  }
  if (edits.empty()) return false;
  std::vector<VertexId> pushed;
  for (const ShellingEdit& edit : edits) {
    queue_.mark_star(edit.added);
    if (edit.split)
      ++stats_.base_edge_splits;
    else
      pushed.push_back(edit.added);
  }
  if (s_.check) check_all("after the shelling star-shapification's edits of vertex " + std::to_string(v));
  stats_.pushes += pushed.size();
  stats_.shelled_pushes += pushed.size();
  const topology::ClusterVertexStatus now = topology::classify_cluster_vertex(e_.mesh, v, e_.unexpanded, ws_);
  expand_to(v, p.position, now.manifold_k > 0 ? now.manifold_k : k, &p);
  ++stats_.expansions_star_shapified;
  ++stats_.shelled_star_shapifications;
  if (depth + 1 < max_depth)
    for (auto it = pushed.rbegin(); it != pushed.rend(); ++it)
      if (e_.unexpanded[*it]) refine_and_expand(*it, depth + 1);
  for (VertexId c : pushed) stats_.shelled_pushes_left += e_.unexpanded[c] ? 1 : 0;
  return true;
}

}  // namespace cmx::algorithm::detail
