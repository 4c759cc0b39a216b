#include "topology/complex_queries.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

#include "topology/union_find.hpp"

namespace cmx::topology {
namespace {

template <class T>
void sort_unique(std::vector<T>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

Edge make_edge(VertexId a, VertexId b) { return a < b ? Edge{a, b} : Edge{b, a}; }
Triangle make_tri(VertexId a, VertexId b, VertexId c) {
  Triangle t{a, b, c};
  std::sort(t.begin(), t.end());
  return t;
}

void add_closure_of(SimplexSet& s, const std::vector<VertexId>& verts) {
  // All faces of the simplex spanned by verts (size 1..4), all already sorted ascending.
  const std::size_t n = verts.size();
  for (std::size_t i = 0; i < n; ++i) {
    s.vertices.push_back(verts[i]);
    for (std::size_t j = i + 1; j < n; ++j) {
      s.edges.push_back({verts[i], verts[j]});
      for (std::size_t k = j + 1; k < n; ++k) {
        s.triangles.push_back({verts[i], verts[j], verts[k]});
        for (std::size_t l = k + 1; l < n; ++l) s.tets.push_back({verts[i], verts[j], verts[k], verts[l]});
      }
    }
  }
}

void finish(SimplexSet& s) {
  sort_unique(s.vertices);
  sort_unique(s.edges);
  sort_unique(s.triangles);
  sort_unique(s.tets);
}

// Builds star/closure/link of the simplex `center` (1 or 2 vertices, sorted) from the tets
// around it. mode: 0 star, 1 closure, 2 link.
SimplexSet simplex_neighborhood(const TetMesh& m, std::vector<VertexId> center, VertexSubset subset,
                                int mode) {
  SimplexSet s;
  // A link never contains its center, so only stars and closures need the center inside.
  if (mode != 2)
    for (VertexId c : center)
      if (!subset.contains(c)) return s;
  std::vector<VertexId> verts;
  for (TetId t : m.tets_of(center[0])) {
    const Tet& tet = m.tet(t);
    bool has_all = true;
    for (VertexId c : center) has_all = has_all && contains(tet, c);
    if (!has_all) continue;
    // Keep the vertices of this tet that are in the subset: the largest face of the tet inside
    // the induced subcomplex; everything below it is in the subcomplex too.
    verts.clear();
    for (VertexId v : tet)
      if (subset.contains(v)) verts.push_back(v);
    std::sort(verts.begin(), verts.end());
    if (mode == 2) {
      std::vector<VertexId> rest;
      for (VertexId v : verts)
        if (std::find(center.begin(), center.end(), v) == center.end()) rest.push_back(v);
      if (!rest.empty()) add_closure_of(s, rest);
      continue;
    }
    SimplexSet face;
    add_closure_of(face, verts);
    if (mode == 1) {
      add_closure_of(s, verts);
      continue;
    }
    // Star: faces of the kept simplex that contain the center.
    auto has_center = [&](auto const& simplex) {
      for (VertexId c : center)
        if (std::find(simplex.begin(), simplex.end(), c) == simplex.end()) return false;
      return true;
    };
    for (VertexId v : face.vertices)
      if (center.size() == 1 && v == center[0]) s.vertices.push_back(v);
    for (const Edge& e : face.edges)
      if (has_center(e)) s.edges.push_back(e);
    for (const Triangle& f : face.triangles)
      if (has_center(f)) s.triangles.push_back(f);
    for (const Tet& x : face.tets)
      if (has_center(x)) s.tets.push_back(x);
  }
  if (mode == 1 && s.vertices.empty()) s.vertices = center;  // an isolated vertex/edge
  if (mode == 0 && center.size() == 1 && s.vertices.empty()) s.vertices.push_back(center[0]);
  finish(s);
  return s;
}

}  // namespace

std::int64_t euler_characteristic(const SimplexSet& s) {
  return static_cast<std::int64_t>(s.vertices.size()) - static_cast<std::int64_t>(s.edges.size()) +
         static_cast<std::int64_t>(s.triangles.size()) - static_cast<std::int64_t>(s.tets.size());
}

std::size_t connected_components(const SimplexSet& s) {
  UnionFind uf(s.vertices.size());
  auto idx = [&](VertexId v) {
    return static_cast<std::uint32_t>(std::lower_bound(s.vertices.begin(), s.vertices.end(), v) -
                                      s.vertices.begin());
  };
  for (const Edge& e : s.edges) uf.unite(idx(e[0]), idx(e[1]));
  for (const Triangle& f : s.triangles) {
    uf.unite(idx(f[0]), idx(f[1]));
    uf.unite(idx(f[0]), idx(f[2]));
  }
  for (const Tet& t : s.tets) {
    uf.unite(idx(t[0]), idx(t[1]));
    uf.unite(idx(t[0]), idx(t[2]));
    uf.unite(idx(t[0]), idx(t[3]));
  }
  std::size_t roots = 0;
  for (std::uint32_t i = 0; i < s.vertices.size(); ++i) roots += uf.find(i) == i ? 1 : 0;
  return roots;
}

std::vector<TetId> tets_around_edge(const TetMesh& m, VertexId a, VertexId b) {
  std::vector<TetId> out;
  for (TetId t : m.tets_of(a))
    if (contains(m.tet(t), b)) out.push_back(t);
  return out;
}

std::vector<TetId> tets_around_face(const TetMesh& m, VertexId a, VertexId b, VertexId c) {
  std::vector<TetId> out;
  for (TetId t : m.tets_of(a))
    if (contains(m.tet(t), b) && contains(m.tet(t), c)) out.push_back(t);
  return out;
}

bool edge_on_boundary(const TetMesh& m, VertexId a, VertexId b) {
  std::vector<std::pair<VertexId, int>> faces;  // third vertex of each face (a, b, x) -> its tets
  for (TetId t : tets_around_edge(m, a, b))
    for (VertexId x : m.tet(t)) {
      if (x == a || x == b) continue;
      auto it = std::find_if(faces.begin(), faces.end(), [x](const auto& f) { return f.first == x; });
      if (it == faces.end())
        faces.emplace_back(x, 1);
      else
        ++it->second;
    }
  return std::any_of(faces.begin(), faces.end(), [](const auto& f) { return f.second == 1; });
}

std::vector<VertexId> vertex_neighbors(const TetMesh& m, VertexId v) {
  std::vector<VertexId> out;
  for (TetId t : m.tets_of(v))
    for (VertexId w : m.tet(t))
      if (w != v) out.push_back(w);
  sort_unique(out);
  return out;
}

SimplexSet vertex_star(const TetMesh& m, VertexId v, VertexSubset subset) {
  return simplex_neighborhood(m, {v}, subset, 0);
}
SimplexSet vertex_closure(const TetMesh& m, VertexId v, VertexSubset subset) {
  return simplex_neighborhood(m, {v}, subset, 1);
}
SimplexSet vertex_link(const TetMesh& m, VertexId v, VertexSubset subset) {
  return simplex_neighborhood(m, {v}, subset, 2);
}
SimplexSet edge_star(const TetMesh& m, VertexId a, VertexId b, VertexSubset subset) {
  const Edge e = make_edge(a, b);
  if (tets_around_edge(m, a, b).empty()) return {};
  SimplexSet s = simplex_neighborhood(m, {e[0], e[1]}, subset, 0);
  return s;
}
SimplexSet edge_closure(const TetMesh& m, VertexId a, VertexId b, VertexSubset subset) {
  const Edge e = make_edge(a, b);
  if (tets_around_edge(m, a, b).empty()) return {};
  return simplex_neighborhood(m, {e[0], e[1]}, subset, 1);
}
SimplexSet edge_link(const TetMesh& m, VertexId a, VertexId b, VertexSubset subset) {
  const Edge e = make_edge(a, b);
  return simplex_neighborhood(m, {e[0], e[1]}, subset, 2);
}

SubcomplexCounts subcomplex_counts(const TetMesh& m, VertexSubset subset) {
  SubcomplexCounts c;
  const std::size_t n = m.num_vertices();
  UnionFind uf(n);
  std::vector<VertexId> nbrs;
  std::vector<std::uint64_t> faces;
  for (VertexId a{0}; a < n; ++a) {
    if (m.tets_of(a).empty() || !subset.contains(a)) continue;
    ++c.vertices;
    nbrs.clear();
    faces.clear();
    for (TetId t : m.tets_of(a)) {
      const Tet& tet = m.tet(t);
      bool all_in = true;
      for (VertexId w : tet) {
        if (!subset.contains(w)) {
          all_in = false;
          continue;
        }
        if (w > a) nbrs.push_back(w);
      }
      // Count each tet once, at its smallest vertex.
      if (all_in && a == *std::min_element(tet.begin(), tet.end())) ++c.tets;
      // Triangles whose smallest vertex is a.
      for (int i = 0; i < 4; ++i) {
        const Triangle f = make_tri(tet[(i + 1) % 4], tet[(i + 2) % 4], tet[(i + 3) % 4]);
        if (f[0] != a || !subset.contains(f[1]) || !subset.contains(f[2])) continue;
        faces.push_back((std::uint64_t{f[1]} << 32) | f[2]);
      }
    }
    sort_unique(nbrs);
    sort_unique(faces);
    c.edges += nbrs.size();
    c.triangles += faces.size();
    for (VertexId w : nbrs) uf.unite(a, w);
  }
  for (VertexId a{0}; a < n; ++a)
    if (!m.tets_of(a).empty() && subset.contains(a) && uf.find(a) == a) ++c.components;
  c.euler = static_cast<std::int64_t>(c.vertices) - static_cast<std::int64_t>(c.edges) +
            static_cast<std::int64_t>(c.triangles) - static_cast<std::int64_t>(c.tets);
  return c;
}

TetAdjacency tet_adjacency(const TetMesh& m) {
  TetAdjacency adj;
  adj.neighbor.assign(m.tet_capacity(), {invalid_tet, invalid_tet, invalid_tet, invalid_tet});
  struct Key {
    std::uint64_t other;  // the two larger vertices of the face
    TetId tet;
    std::uint8_t local;
  };
  std::vector<Key> keys;
  for (VertexId a{0}; a < m.num_vertices(); ++a) {
    keys.clear();
    for (TetId t : m.tets_of(a)) {
      const Tet& tet = m.tet(t);
      for (int i = 0; i < 4; ++i) {
        if (tet[i] == a) continue;
        const Triangle f = make_tri(tet[(i + 1) % 4], tet[(i + 2) % 4], tet[(i + 3) % 4]);
        if (f[0] != a) continue;  // each face handled at its smallest vertex
        keys.push_back({(std::uint64_t{f[1]} << 32) | f[2], t, static_cast<std::uint8_t>(i)});
      }
    }
    std::sort(keys.begin(), keys.end(), [](const Key& x, const Key& y) {
      return x.other != y.other ? x.other < y.other : x.tet < y.tet;
    });
    for (std::size_t i = 0; i < keys.size();) {
      std::size_t j = i;
      while (j < keys.size() && keys[j].other == keys[i].other) ++j;
      if (j - i == 2) {
        adj.neighbor[keys[i].tet][keys[i].local] = keys[i + 1].tet;
        adj.neighbor[keys[i + 1].tet][keys[i + 1].local] = keys[i].tet;
      } else if (j - i > 2 && adj.manifold) {
        adj.manifold = false;
        adj.nonmanifold_face = {a, static_cast<VertexId>(keys[i].other >> 32),
                                static_cast<VertexId>(keys[i].other & 0xffffffffu)};
      }
      i = j;
    }
  }
  return adj;
}

std::vector<BoundaryFace> boundary_faces(const TetMesh& m) {
  const TetAdjacency adj = tet_adjacency(m);
  std::vector<BoundaryFace> out;
  for (std::size_t t = 0; t < m.tet_capacity(); ++t) {
    if (!m.is_alive(static_cast<TetId>(t))) continue;
    for (int i = 0; i < 4; ++i)
      if (adj.neighbor[t][i] == invalid_index)
        out.push_back({tet_face(m.tet(static_cast<TetId>(t)), i), static_cast<TetId>(t),
                       static_cast<std::uint8_t>(i)});
  }
  return out;
}

std::vector<char> boundary_vertex_flags(const TetMesh& m) {
  std::vector<char> flags(m.num_vertices(), 0);
  for (const BoundaryFace& f : boundary_faces(m))
    for (VertexId v : f.face) flags[v] = 1;
  return flags;
}

std::vector<char> interior_vertex_flags(const TetMesh& m) {
  std::vector<char> flags = boundary_vertex_flags(m);
  for (VertexId v{0}; v < m.num_vertices(); ++v)
    flags[v] = (flags[v] == 0 && !m.tets_of(v).empty()) ? 1 : 0;
  return flags;
}

}  // namespace cmx::topology
