#include "topology/chords.hpp"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <numeric>
#include <set>

#include "topology/cluster_links.hpp"
#include "topology/complex_queries.hpp"
#include "topology/mesh_edits.hpp"
#include "topology/union_find.hpp"

namespace cmx::topology {

namespace {

bool is_boundary_face(const TetMesh& m, const Triangle& f) {
  return tets_around_face(m, f[0], f[1], f[2]).size() == 1;
}

bool all_boundary(const std::vector<char>& boundary, const Triangle& f) {
  return boundary[f[0]] && boundary[f[1]] && boundary[f[2]];
}

VertexId split_edge(ChordContext& c, VertexId a, VertexId b) {
  return c.split(a, b, invalid_vertex);
}

// Every edge between two boundary vertices, sorted.
std::set<std::pair<VertexId, VertexId>> boundary_pairs(const TetMesh& m, const std::vector<char>& boundary) {
  std::set<std::pair<VertexId, VertexId>> out;
  for (TetId t : m.live_tets()) {
    const Tet& tet = m.tet(t);
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        if (boundary[tet[i]] && boundary[tet[j]])
          out.insert({std::min(tet[i], tet[j]), std::max(tet[i], tet[j])});
  }
  return out;
}

std::vector<Triangle> trace(const TetMesh& m, const std::vector<char>& boundary, TetId t,
                            const std::vector<std::pair<TetId, int>>& from) {
  std::vector<Triangle> faces;
  while (from[t].first != invalid_index) {
    const auto [prev, i] = from[t];
    const Triangle f = tet_face(m.tet(prev), i);
    if (all_boundary(boundary, f)) faces.push_back(f);
    t = prev;
  }
  return faces;
}

// Chord faces on a shortest path (counting chord faces) from the component of the first interior
// vertex to a tet of another component.
std::vector<Triangle> chord_path_between_components(const TetMesh& m, const std::vector<char>& boundary,
                                                    const std::vector<char>& interior) {
  UnionFind components(m.num_vertices());
  VertexId first = invalid_vertex;
  for (TetId t : m.live_tets()) {
    VertexId prev = invalid_vertex;
    for (VertexId w : m.tet(t))
      if (interior[w]) {
        if (first == invalid_vertex) first = w;
        if (prev != invalid_vertex) components.unite(w, prev);
        prev = w;
      }
  }
  if (first == invalid_vertex) return {};
  const std::uint32_t root = components.find(first);
  // The representative of the interior component t touches (invalid_index: none).
  auto component = [&](TetId t) -> std::uint32_t {
    for (VertexId w : m.tet(t))
      if (interior[w]) return components.find(w);
    return invalid_index;
  };
  const TetAdjacency adj = tet_adjacency(m);
  const std::size_t cap = m.tet_capacity();
  std::vector<std::uint32_t> dist(cap, UINT32_MAX);
  std::vector<std::pair<TetId, int>> from(cap, {invalid_tet, -1});
  std::deque<TetId> q;
  for (TetId t : m.live_tets())
    if (component(t) == root) {
      dist[t] = 0;
      q.push_back(t);
    }
  while (!q.empty()) {
    const TetId t = q.front();
    q.pop_front();
    const std::uint32_t c = component(t);
    if (c != invalid_index && c != root) return trace(m, boundary, t, from);
    for (int i = 0; i < 4; ++i) {
      const TetId u = adj.neighbor[t][i];
      if (u == invalid_index) continue;
      const std::uint32_t w = all_boundary(boundary, tet_face(m.tet(t), i)) ? 1 : 0;
      if (dist[t] + w >= dist[u]) continue;
      dist[u] = dist[t] + w;
      from[u] = {t, i};
      if (w)
        q.push_back(u);
      else
        q.push_front(u);
    }
  }
  return {};
}

}  // namespace

bool is_chord_edge(const TetMesh& m, const std::vector<char>& boundary, VertexId a, VertexId b) {
  if (!boundary[a] || !boundary[b]) return false;
  const auto around = tets_around_edge(m, a, b);
  if (around.empty()) return false;
  for (TetId t : around) {
    const Tet& tet = m.tet(t);
    for (int i = 0; i < 4; ++i)
      if (tet[i] != a && tet[i] != b && is_boundary_face(m, tet_face(tet, i))) return false;
  }
  return true;
}

bool is_chord_face(const TetMesh& m, const std::vector<char>& boundary, const Triangle& f) {
  return all_boundary(boundary, f) && !is_boundary_face(m, f);
}

int interior_runs(const TetMesh& m, const std::vector<char>& interior, VertexId a, VertexId b,
                  bool& all_interior) {
  std::vector<VertexId> cycle;
  int edges = 0;
  for (TetId t : tets_around_edge(m, a, b)) {
    VertexId xy[2];
    int n = 0;
    for (VertexId w : m.tet(t))
      if (w != a && w != b) xy[n++] = w;
    cycle.push_back(xy[0]);
    cycle.push_back(xy[1]);
    if (interior[xy[0]] && interior[xy[1]]) ++edges;
  }
  std::sort(cycle.begin(), cycle.end());
  cycle.erase(std::unique(cycle.begin(), cycle.end()), cycle.end());
  int verts = 0;
  for (VertexId w : cycle) verts += interior[w] ? 1 : 0;
  all_interior = verts == int(cycle.size());
  return all_interior ? 0 : verts - edges;
}

std::size_t connect_interior(ChordContext& c) {
  std::size_t splits = 0;
  for (;;) {
    if (cluster_mesh_counts(c.mesh, c.interior).components <= 1) return splits;
    const std::vector<Triangle> path = chord_path_between_components(c.mesh, c.boundary, c.interior);
    if (path.empty()) return splits;  // cannot connect: the caller falls back
    for (const Triangle& f : path) {
      if (tets_around_face(c.mesh, f[0], f[1], f[2]).empty()) continue;  // split already
      int edge = -1;
      for (int i = 0; i < 3 && edge < 0; ++i)
        if (is_chord_edge(c.mesh, c.boundary, f[i], f[(i + 1) % 3])) edge = i;
      if (edge >= 0)
        split_edge(c, f[edge], f[(edge + 1) % 3]);
      else
        c.split(f[0], f[1], f[2]);
      ++splits;
    }
  }
}

std::size_t fill_interior_handles(ChordContext& c) {
  std::size_t splits = 0;
  for (const auto& [a, b] : boundary_pairs(c.mesh, c.boundary)) {
    if (!is_chord_edge(c.mesh, c.boundary, a, b)) continue;
    bool all_interior = false;
    (void)interior_runs(c.mesh, c.interior, a, b, all_interior);
    if (!all_interior) continue;
    split_edge(c, a, b);
    ++splits;
  }
  return splits;
}

std::size_t split_all_chords(ChordContext& c) {
  std::size_t splits = 0;
  std::set<Triangle> faces;
  for (TetId t : c.mesh.live_tets())
    for (int i = 0; i < 4; ++i) {
      Triangle f = tet_face(c.mesh.tet(t), i);
      if (!is_chord_face(c.mesh, c.boundary, f)) continue;
      std::sort(f.begin(), f.end());
      faces.insert(f);
    }
  for (const Triangle& f : faces)
    if (!tets_around_face(c.mesh, f[0], f[1], f[2]).empty() &&
        !is_chord_edge(c.mesh, c.boundary, f[0], f[1]) && !is_chord_edge(c.mesh, c.boundary, f[1], f[2]) &&
        !is_chord_edge(c.mesh, c.boundary, f[0], f[2])) {
      c.split(f[0], f[1], f[2]);
      ++splits;
    }
  for (const auto& [a, b] : boundary_pairs(c.mesh, c.boundary))
    if (is_chord_edge(c.mesh, c.boundary, a, b)) {
      split_edge(c, a, b);
      ++splits;
    }
  return splits;
}

bool interior_simply_connected(const TetMesh& m, const std::vector<char>& interior) {
  const auto counts = cluster_mesh_counts(m, interior);
  return counts.vertices == 0 || (counts.components == 1 && counts.euler == 1);
}

std::size_t make_interior_simply_connected(ChordContext& c) {
  std::size_t splits = connect_interior(c);
  splits += fill_interior_handles(c);
  if (!interior_simply_connected(c.mesh, c.interior)) splits += split_all_chords(c);
  return splits;
}

ChordSplits make_interior_simply_connected(TetMesh& mesh) {
  std::vector<char> boundary = boundary_vertex_flags(mesh);
  ChordSplits out{interior_vertex_flags(mesh), 0};
  ChordContext c{mesh, boundary, out.interior, [&](VertexId a, VertexId b, VertexId f) {
                   const SplitResult r =
                       f == invalid_index ? split_edge(mesh, a, b) : split_face(mesh, a, b, f);
                   boundary.push_back(0);
                   out.interior.push_back(1);
                   return r.new_vertex;
                 }};
  out.splits = make_interior_simply_connected(c);
  return out;
}

}  // namespace cmx::topology
