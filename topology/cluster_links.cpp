#include "topology/cluster_links.hpp"

#include <algorithm>
#include <numeric>

namespace cmx::topology {
namespace {

bool in_side(std::span<const char> unexpanded, VertexId w, bool want_unexpanded) {
  const bool u = w < unexpanded.size() && unexpanded[w] != 0;
  return u == want_unexpanded;
}

std::uint32_t find(std::vector<std::uint32_t>& p, std::uint32_t x) {
  while (p[x] != x) x = p[x] = p[p[x]];
  return x;
}

// Fills ws.verts (sorted global ids), ws.edges (sorted unique, local index pairs packed),
// ws.tris (local indices) with the part of Lk(v) on the requested side, and returns its stats.
LinkStats gather(const TetMesh& m, VertexId v, std::span<const char> unexpanded, bool want_unexpanded,
                 ClusterLinkWorkspace& ws) {
  ws.verts.clear();
  ws.edges.clear();
  ws.tris.clear();
  for (TetId t : m.tets_of(v)) {
    for (VertexId w : m.tet(t))
      if (w != v) ws.verts.push_back(w);
  }
  std::sort(ws.verts.begin(), ws.verts.end());
  ws.verts.erase(std::unique(ws.verts.begin(), ws.verts.end()), ws.verts.end());
  ws.all_neighbors = static_cast<std::uint32_t>(ws.verts.size());
  ws.verts.erase(std::remove_if(ws.verts.begin(), ws.verts.end(),
                                [&](VertexId w) { return !in_side(unexpanded, w, want_unexpanded); }),
                 ws.verts.end());
  auto idx = [&](VertexId w) {
    return static_cast<std::uint32_t>(std::lower_bound(ws.verts.begin(), ws.verts.end(), w) - ws.verts.begin());
  };
  for (TetId t : m.tets_of(v)) {
    const Tet& x = m.tet(t);
    std::uint32_t loc[3];
    int n = 0;
    for (VertexId w : x)
      if (w != v && in_side(unexpanded, w, want_unexpanded)) loc[n++] = idx(w);
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        const std::uint32_t a = std::min(loc[i], loc[j]), b = std::max(loc[i], loc[j]);
        ws.edges.push_back((std::uint64_t{a} << 32) | b);
      }
    // Each tet around v contributes its own opposite triangle: no duplicates.
    if (n == 3) ws.tris.push_back({loc[0], loc[1], loc[2]});
  }
  std::sort(ws.edges.begin(), ws.edges.end());
  ws.edges.erase(std::unique(ws.edges.begin(), ws.edges.end()), ws.edges.end());
  LinkStats s;
  s.vertices = static_cast<std::uint32_t>(ws.verts.size());
  s.edges = static_cast<std::uint32_t>(ws.edges.size());
  s.triangles = static_cast<std::uint32_t>(ws.tris.size());
  s.euler = static_cast<std::int32_t>(s.vertices) - static_cast<std::int32_t>(s.edges) +
            static_cast<std::int32_t>(s.triangles);
  ws.parent.resize(s.vertices);
  std::iota(ws.parent.begin(), ws.parent.end(), 0u);
  std::uint32_t comps = s.vertices;
  for (std::uint64_t e : ws.edges) {
    const std::uint32_t a = find(ws.parent, static_cast<std::uint32_t>(e >> 32));
    const std::uint32_t b = find(ws.parent, static_cast<std::uint32_t>(e & 0xffffffffu));
    if (a != b) {
      ws.parent[a] = b;
      --comps;
    }
  }
  s.components = comps;
  return s;
}

// After gather(): is the star of local vertex i in the gathered 2-complex a single triangle fan
// (at least one triangle, every edge at i in a triangle, the triangles' opposite edges form one
// connected path or cycle)?
bool single_fan(std::uint32_t i, ClusterLinkWorkspace& ws) {
  // Opposite edges of the triangles at i, as pairs of local vertices.
  ws.scratch.clear();
  std::size_t tri_count = 0;
  for (const auto& t : ws.tris) {
    for (int k = 0; k < 3; ++k) {
      if (t[k] != i) continue;
      ws.scratch.push_back(t[(k + 1) % 3]);
      ws.scratch.push_back(t[(k + 2) % 3]);
      ++tri_count;
    }
  }
  if (tri_count == 0) return false;
  // Every edge (i, w) of the complex must be in a triangle at i: its w must appear above.
  for (std::uint64_t e : ws.edges) {
    const auto a = static_cast<std::uint32_t>(e >> 32), b = static_cast<std::uint32_t>(e & 0xffffffffu);
    if (a != i && b != i) continue;
    const std::uint32_t w = a == i ? b : a;
    if (std::find(ws.scratch.begin(), ws.scratch.end(), w) == ws.scratch.end()) return false;
  }
  // Connectivity of the link of i (vertices = distinct entries of scratch).
  std::vector<std::uint32_t>& nodes = ws.fan_nodes;
  nodes.assign(ws.scratch.begin(), ws.scratch.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  std::vector<std::uint32_t>& parent = ws.fan_parent;
  parent.resize(nodes.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto pos = [&](std::uint32_t x) {
    return static_cast<std::uint32_t>(std::lower_bound(nodes.begin(), nodes.end(), x) - nodes.begin());
  };
  std::size_t comps = nodes.size();
  std::vector<std::uint32_t>& deg = ws.fan_degree;
  deg.assign(nodes.size(), 0);
  for (std::size_t k = 0; k < ws.scratch.size(); k += 2) {
    const std::uint32_t a = pos(ws.scratch[k]), b = pos(ws.scratch[k + 1]);
    ++deg[a];
    ++deg[b];
    const std::uint32_t ra = find(parent, a), rb = find(parent, b);
    if (ra != rb) {
      parent[ra] = rb;
      --comps;
    }
  }
  if (comps != 1) return false;
  for (std::uint32_t d : deg)
    if (d > 2) return false;
  return true;
}

int classify_k(const LinkStats& s, ClusterLinkWorkspace& ws) {
  if (!s.simply_connected()) return 0;
  if (s.vertices == 1) return 1;
  if (s.triangles == 0) {
    // A tree; a path iff no vertex has degree > 2.
    ws.degree.assign(s.vertices, 0);
    for (std::uint64_t e : ws.edges) {
      ++ws.degree[e >> 32];
      ++ws.degree[e & 0xffffffffu];
    }
    for (std::uint32_t d : ws.degree)
      if (d > 2) return 0;
    return 2;
  }
  // A disc: pure 2-dimensional and every vertex a single fan (then a connected 2-manifold with
  // boundary of chi 1).
  for (std::uint32_t i = 0; i < s.vertices; ++i)
    if (!single_fan(i, ws)) return 0;
  return 3;
}

}  // namespace

LinkStats unexpanded_link_stats(const TetMesh& m, VertexId v, std::span<const char> unexpanded,
                                ClusterLinkWorkspace& ws) {
  return gather(m, v, unexpanded, true, ws);
}

LinkStats expanded_link_stats(const TetMesh& m, VertexId v, std::span<const char> unexpanded,
                              ClusterLinkWorkspace& ws) {
  return gather(m, v, unexpanded, false, ws);
}

bool is_topologically_expandable(const TetMesh& m, VertexId v, std::span<const char> unexpanded,
                                 ClusterLinkWorkspace& ws) {
  return unexpanded_link_stats(m, v, unexpanded, ws).simply_connected();
}

int manifold_expandability(const TetMesh& m, VertexId v, std::span<const char> unexpanded,
                           ClusterLinkWorkspace& ws) {
  const LinkStats s = gather(m, v, unexpanded, true, ws);
  return classify_k(s, ws);
}

ClusterVertexStatus classify_cluster_vertex(const TetMesh& m, VertexId v, std::span<const char> unexpanded,
                                            ClusterLinkWorkspace& ws) {
  ClusterVertexStatus st;
  st.unexpanded_link = gather(m, v, unexpanded, true, ws);
  st.expandable = st.unexpanded_link.simply_connected();
  st.expanded_neighbors = ws.all_neighbors - st.unexpanded_link.vertices;
  st.manifold_k = classify_k(st.unexpanded_link, ws);
  return st;
}

std::vector<VertexId> expanded_link_cut_vertices(const TetMesh& m, VertexId v, std::span<const char> unexpanded) {
  ClusterLinkWorkspace ws;
  const LinkStats s = gather(m, v, unexpanded, false, ws);
  std::vector<VertexId> out;
  for (std::uint32_t i = 0; i < s.vertices; ++i)
    if (!single_fan(i, ws)) out.push_back(ws.verts[i]);
  return out;
}

SubcomplexCounts cluster_mesh_counts(const TetMesh& m, std::span<const char> unexpanded) {
  return subcomplex_counts(m, VertexSubset(unexpanded));
}

bool is_degenerate_tet(const Tet& t, std::span<const char> unexpanded) {
  int n = 0;
  for (VertexId v : t) n += in_side(unexpanded, v, true) ? 1 : 0;
  return n >= 2;
}

std::size_t count_degenerate_tets(const TetMesh& m, std::span<const char> unexpanded) {
  std::size_t n = 0;
  for (TetId t : m.live_tets()) n += is_degenerate_tet(m.tet(t), unexpanded) ? 1 : 0;
  return n;
}

SimplexSet unexpanded_link(const TetMesh& m, VertexId v, std::span<const char> unexpanded) {
  return vertex_link(m, v, VertexSubset(unexpanded));
}

SimplexSet expanded_link(const TetMesh& m, VertexId v, std::span<const char> unexpanded) {
  return vertex_link(m, v, VertexSubset(unexpanded, true));
}

}  // namespace cmx::topology
