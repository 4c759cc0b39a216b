#include "algorithm/expansion/cone_base.hpp"

#include <algorithm>
#include <deque>

#include "kernel/plane.hpp"
#include "topology/complex_queries.hpp"

namespace cmx::algorithm {

ConeBase cone_base(const Embedding& e, VertexId v) {
  ConeBase b;
  for (TetId t : e.mesh.tets_of(v)) {
    std::array<VertexId, 3> ex{};
    int n = 0;
    for (VertexId w : e.mesh.tet(t))
      if (w != v && !e.unexpanded[w]) ex[n++] = w;
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

std::unordered_map<VertexId, int> base_distances(const ConeBase& base, VertexId from) {
  std::unordered_map<VertexId, int> dist{{from, 0}};
  std::deque<VertexId> queue{from};
  while (!queue.empty()) {
    const VertexId x = queue.front();
    queue.pop_front();
    const auto it = base.adj.find(x);
    if (it == base.adj.end()) continue;
    for (VertexId y : it->second)
      if (dist.emplace(y, dist[x] + 1).second) queue.push_back(y);
  }
  return dist;
}

Witness choose_witness(const ConeBase& base) {
  auto triangles_at = [&](VertexId x) {
    const auto it = base.tets.find(x);
    return it == base.tets.end() ? 0 : it->second;
  };
  Witness w{base.verts.front(), {}};
  for (VertexId x : base.verts)
    if (triangles_at(x) > triangles_at(w.vertex)) w.vertex = x;
  for (const auto& tri : base.triangles)
    if (std::find(tri.begin(), tri.end(), w.vertex) != tri.end()) {
      w.keep = tri;
      break;
    }
  return w;
}

HPoint centroid(const Embedding& e, const std::array<VertexId, 3>& t) {
  const HPoint corners[3] = {e.target[t[0]], e.target[t[1]], e.target[t[2]]};
  const Rational third(1, 3), thirds[3] = {third, third, third};
  return convex_combination(corners, thirds, 3);
}

bool has_dangling_edge(const ConeBase& base) {
  std::vector<std::pair<VertexId, VertexId>> in_triangle;
  for (const auto& t : base.triangles)
    for (int i = 0; i < 3; ++i) in_triangle.emplace_back(std::min(t[i], t[(i + 1) % 3]), std::max(t[i], t[(i + 1) % 3]));
  std::sort(in_triangle.begin(), in_triangle.end());
  for (const auto& [a, nbrs] : base.adj)
    for (VertexId b : nbrs)
      if (!std::binary_search(in_triangle.begin(), in_triangle.end(), std::make_pair(std::min(a, b), std::max(a, b))))
        return true;
  return false;
}

std::vector<std::array<VertexId, 4>> dangling_edges(const Embedding& e, VertexId v) {
  const ConeBase base = cone_base(e, v);
  std::vector<std::array<VertexId, 4>> out;
  for (const auto& [a, nbrs] : base.adj)
    for (VertexId b : nbrs) {
      if (a > b) continue;
      std::vector<VertexId> sides;
      bool in_triangle = false;
      for (TetId t : topology::tets_around_edge(e.mesh, v, a))
        if (topology::contains(e.mesh.tet(t), b))
          for (VertexId z : e.mesh.tet(t))
            if (z != v && z != a && z != b) {
              if (e.unexpanded[z]) sides.push_back(z);
              else in_triangle = true;
            }
      if (!in_triangle && !sides.empty()) out.push_back({a, b, sides[0], sides.size() > 1 ? sides[1] : sides[0]});
    }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::pair<VertexId, VertexId>> spoke_ring(const Embedding& e, VertexId v, VertexId b) {
  std::vector<std::pair<VertexId, VertexId>> ring;
  for (TetId t : topology::tets_around_edge(e.mesh, v, b)) {
    VertexId xy[2];
    int n = 0;
    for (VertexId w : e.mesh.tet(t))
      if (w != v && w != b) xy[n++] = w;
    ring.emplace_back(xy[0], xy[1]);
  }
  return ring;
}

bool is_pushable(const Embedding& e, VertexId v, VertexId b) {
  std::vector<VertexId> seen;
  int cluster_edges = 0;
  for (const auto& [x, y] : spoke_ring(e, v, b)) {
    seen.push_back(x);
    seen.push_back(y);
    if (e.unexpanded[x] && e.unexpanded[y]) ++cluster_edges;
  }
  std::sort(seen.begin(), seen.end());
  seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
  int in_cluster = 0, expanded = 0;
  for (VertexId w : seen) (e.unexpanded[w] ? in_cluster : expanded) += 1;
  return in_cluster >= 1 && expanded >= 1 && in_cluster - cluster_edges == 1;
}

bool is_ear(const Embedding& e, VertexId v, VertexId b) {
  const auto ring = spoke_ring(e, v, b);
  std::vector<VertexId> expanded;
  for (const auto& [x, y] : ring)
    for (VertexId z : {x, y})
      if (!e.unexpanded[z]) expanded.push_back(z);
  std::sort(expanded.begin(), expanded.end());
  std::vector<VertexId> inner;  // arc vertices met twice and without a cluster ring neighbour
  for (std::size_t i = 0; i < expanded.size(); ++i) {
    if (i > 0 && expanded[i] == expanded[i - 1]) continue;
    const bool twice = i + 1 < expanded.size() && expanded[i + 1] == expanded[i];
    bool next_to_cluster = false;
    for (const auto& [x, y] : ring)
      if ((x == expanded[i] && e.unexpanded[y]) || (y == expanded[i] && e.unexpanded[x])) next_to_cluster = true;
    if (twice && !next_to_cluster) inner.push_back(expanded[i]);
  }
  expanded.erase(std::unique(expanded.begin(), expanded.end()), expanded.end());
  if (expanded.size() < 2) return false;
  for (VertexId c : inner)
    for (TetId t : e.mesh.tets_of(c))
      if (topology::contains(e.mesh.tet(t), v))
        for (VertexId z : e.mesh.tet(t))
          if (z != v && e.unexpanded[z]) return false;
  if (expanded.size() == 2) {
    int base_triangles = 0;
    for (TetId t : topology::tets_around_edge(e.mesh, expanded[0], expanded[1]))
      if (topology::contains(e.mesh.tet(t), v) && e.unexpanded_count(e.mesh.tet(t)) == 1) ++base_triangles;
    return base_triangles == 2;
  }
  return true;
}

namespace {

void add_face(ExpansionCone& cone, const Embedding& e, const topology::Tet& tet, int i, bool base) {
  const topology::Triangle f = topology::tet_face(tet, i);
  InnerHalfSpace h = inner_halfspace(e.target[f[0]], e.target[f[1]], e.target[f[2]]);
  if (h.is_degenerate()) cone.degenerate = true;
  (base ? cone.base_tets : cone.side_tets) += 1;
  cone.halfspaces.push_back(std::move(h));
}

}  // namespace

ExpansionCone bend_cone(const Embedding& e, VertexId v, VertexId b) {
  ExpansionCone cone;
  for (TetId t : topology::tets_around_edge(e.mesh, v, b)) {
    const topology::Tet& tet = e.mesh.tet(t);
    const int cluster = e.unexpanded_count(tet);  // v included
    if (cluster - 1 <= 1) add_face(cone, e, tet, topology::local_index(tet, v), cluster - 1 == 0);
    if (cluster == 1) add_face(cone, e, tet, topology::local_index(tet, b), false);
  }
  return cone;
}

void add_aim_constraints(ExpansionCone& cone, const Embedding& e, VertexId v, VertexId b, const HPoint& aim,
                         bool only_violated) {
  for (TetId t : topology::tets_around_edge(e.mesh, v, b)) {
    const topology::Tet& tet = e.mesh.tet(t);
    if (e.unexpanded_count(tet) != 2) continue;
    const topology::Triangle f = topology::tet_face(tet, topology::local_index(tet, v));
    if (only_violated) {
      const InnerHalfSpace now = inner_halfspace(e.target[f[0]], e.target[f[1]], e.target[f[2]]);
      if (!now.is_degenerate() && side_of(now, aim) == Sign::negative) continue;
    }
    // orient(f with q) < 0 at aim  <=>  orient(f with aim in q's slot, q) > 0 (one transposition)
    HPoint g[3] = {e.target[f[0]], e.target[f[1]], e.target[f[2]]};
    for (int i = 0; i < 3; ++i)
      if (f[i] == b) g[i] = aim;
    InnerHalfSpace h = inner_halfspace(g[0], g[2], g[1]);
    if (h.is_degenerate()) cone.degenerate = true;
    cone.halfspaces.push_back(std::move(h));
    if (only_violated) return;
  }
}

std::unordered_map<VertexId, int> blocking_endpoints(const Embedding& e, VertexId v, const HPoint& aim) {
  std::unordered_map<VertexId, int> count;
  for (TetId t : e.mesh.tets_of(v)) {
    const topology::Tet& tet = e.mesh.tet(t);
    if (e.unexpanded_count(tet) != 2) continue;
    const topology::Triangle f = topology::tet_face(tet, topology::local_index(tet, v));
    const InnerHalfSpace h = inner_halfspace(e.target[f[0]], e.target[f[1]], e.target[f[2]]);
    if (!h.is_degenerate() && side_of(h, aim) == Sign::negative) continue;
    for (VertexId x : f)
      if (!e.unexpanded[x]) ++count[x];
  }
  return count;
}

}  // namespace cmx::algorithm
