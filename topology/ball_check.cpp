#include "topology/ball_check.hpp"

#include <algorithm>
#include <numeric>
#include <optional>
#include <sstream>

#include "topology/complex_queries.hpp"
#include "topology/union_find.hpp"

namespace cmx::topology {
namespace {

std::string ids(std::span<const VertexId> s) {
  std::ostringstream os;
  os << '(';
  for (std::size_t i = 0; i < s.size(); ++i) os << (i ? " " : "") << s[i];
  os << ')';
  return os.str();
}

BallVerdict fail(BallVerdict v, BallFailure f, std::vector<VertexId> simplex, const std::string& what) {
  v.ok = false;
  v.failure = f;
  v.simplex = std::move(simplex);
  v.message = what;
  return v;
}

// Face neighbours: adj[t][i] is the tet across face i of t (invalid_index on the boundary).
using Adjacency = std::vector<std::array<TetId, 4>>;
using Failure = std::optional<BallVerdict>;

// Tets that repeat a vertex, vertices in no tet.
Failure tet_failure(const TetMesh& m, const std::vector<TetId>& live, const BallVerdict& v) {
  for (TetId t : live) {
    const Tet& x = m.tet(t);
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        if (x[i] == x[j])
          return fail(v, BallFailure::degenerate_tet, {x.begin(), x.end()},
                      "tet " + std::to_string(t) + " " + ids(x) + " repeats vertex " + std::to_string(x[i]));
  }
  for (VertexId a{0}; a < m.num_vertices(); ++a)
    if (m.tets_of(a).empty())
      return fail(v, BallFailure::isolated_vertex, {a}, "vertex " + std::to_string(a) + " is used by no tet");
  return std::nullopt;
}

// A face of some tet, keyed at its smallest vertex by the other two.
struct FaceKey {
  std::uint64_t other;
  TetId tet;
  std::uint8_t local;
};

// The faces whose smallest vertex is a, sorted by their other two vertices.
void faces_at(const TetMesh& m, VertexId a, std::vector<FaceKey>& keys) {
  keys.clear();
  for (TetId t : m.tets_of(a)) {
    const Tet& x = m.tet(t);
    for (int i = 0; i < 4; ++i) {
      if (x[i] == a) continue;
      Triangle f = tet_face(x, i);
      std::sort(f.begin(), f.end());
      if (f[0] != a) continue;
      keys.push_back({(std::uint64_t{f[1]} << 32) | f[2], t, static_cast<std::uint8_t>(i)});
    }
  }
  std::sort(keys.begin(), keys.end(), [](const FaceKey& x, const FaceKey& y) {
    return x.other != y.other ? x.other < y.other : x.tet < y.tet;
  });
}

// One face and the keys [i, j) of the tets that have it: duplicates, 3+ tets, orientation.
Failure face_failure(const TetMesh& m, VertexId a, const std::vector<FaceKey>& keys, std::size_t i, std::size_t j,
                     const BallVerdict& v) {
  const std::vector<VertexId> face{a, static_cast<VertexId>(keys[i].other >> 32),
                                   static_cast<VertexId>(keys[i].other & 0xffffffffu)};
  // Duplicate tets share every face; they show up as two entries with the same apex.
  for (std::size_t p = i; p < j; ++p)
    for (std::size_t q = p + 1; q < j; ++q)
      if (m.tet(keys[p].tet)[keys[p].local] == m.tet(keys[q].tet)[keys[q].local]) {
        Tet s = m.tet(keys[p].tet);
        std::sort(s.begin(), s.end());
        return fail(v, BallFailure::duplicate_tet, {s.begin(), s.end()},
                    "tets " + std::to_string(keys[p].tet) + " and " + std::to_string(keys[q].tet) +
                        " both have vertices " + ids(s));
      }
  if (j - i > 2)
    return fail(v, BallFailure::face_in_three_or_more_tets, face,
                "face " + ids(face) + " lies in " + std::to_string(j - i) + " tets (at most 2 allowed)");
  if (j - i == 2) {
    const Triangle fp = tet_face(m.tet(keys[i].tet), keys[i].local);
    const Triangle fq = tet_face(m.tet(keys[i + 1].tet), keys[i + 1].local);
    if (same_orientation(fp, fq))
      return fail(v, BallFailure::inconsistent_orientation, {fp.begin(), fp.end()},
                  "face " + ids(fp) + " has the same orientation in tets " + std::to_string(keys[i].tet) + " and " +
                      std::to_string(keys[i + 1].tet) + " (must be opposite)");
  }
  return std::nullopt;
}

// Faces, grouped at their smallest vertex: duplicates, 3+ tets, orientation; fills adj and the
// face counts of v.
Failure face_adjacency(const TetMesh& m, BallVerdict& v, Adjacency& adj) {
  adj.assign(m.tet_capacity(), {invalid_tet, invalid_tet, invalid_tet, invalid_tet});
  std::vector<FaceKey> keys;
  std::size_t interior_faces = 0, bfaces = 0;
  for (VertexId a{0}; a < m.num_vertices(); ++a) {
    faces_at(m, a, keys);
    for (std::size_t i = 0; i < keys.size();) {
      std::size_t j = i;
      while (j < keys.size() && keys[j].other == keys[i].other) ++j;
      if (auto f = face_failure(m, a, keys, i, j, v)) return f;
      if (j - i == 2) {
        adj[keys[i].tet][keys[i].local] = keys[i + 1].tet;
        adj[keys[i + 1].tet][keys[i + 1].local] = keys[i].tet;
        ++interior_faces;
      } else {
        ++bfaces;
      }
      i = j;
    }
  }
  v.faces = interior_faces + bfaces;
  v.boundary_faces = bfaces;
  return std::nullopt;
}

// Connectivity of the complex (through vertices: two pieces sharing only a vertex are
// connected, and reported later as a non-manifold vertex instead).
Failure disconnection(const TetMesh& m, const std::vector<TetId>& live, const BallVerdict& v) {
  UnionFind uf(m.num_vertices());
  for (TetId t : live)
    for (int i = 1; i < 4; ++i) uf.unite(m.tet(t)[0], m.tet(t)[i]);
  const std::uint32_t root = uf.find(m.tet(live.front())[0]);
  for (VertexId a{0}; a < m.num_vertices(); ++a)
    if (uf.find(a) != root)
      return fail(v, BallFailure::disconnected, {a},
                  "vertex " + std::to_string(a) + " is not connected to vertex " +
                      std::to_string(m.tet(live.front())[0]));
  return std::nullopt;
}

std::vector<char> boundary_vertex_marks(const TetMesh& m, const std::vector<TetId>& live, const Adjacency& adj) {
  std::vector<char> on_boundary(m.num_vertices(), 0);
  for (TetId t : live)
    for (int i = 0; i < 4; ++i)
      if (adj[t][i] == invalid_index)
        for (VertexId w : tet_face(m.tet(t), i)) on_boundary[w] = 1;
  return on_boundary;
}

// The tets around a, as a star: their face-connectivity through faces containing a and the
// counts of the link (a's link: vertices, edges, triangles).
struct VertexStar {
  std::size_t pieces = 0;               // face-connected pieces of the tets around a
  std::size_t link_edges2 = 0;          // 2 * interior link edges
  std::size_t boundary_link_edges = 0;  // link edges on the boundary
};

VertexStar vertex_star(const TetMesh& m, const Adjacency& adj, VertexId a, const std::vector<TetId>& star,
                       UnionFind& pieces) {
  const auto pos = [&](TetId t) {
    return static_cast<std::uint32_t>(std::lower_bound(star.begin(), star.end(), t) - star.begin());
  };
  pieces.reset(star.size());
  VertexStar s;
  s.pieces = star.size();
  for (TetId t : star) {
    const int ia = local_index(m.tet(t), a);
    for (int i = 0; i < 4; ++i) {
      if (i == ia) continue;
      const TetId n = adj[t][i];
      if (n == invalid_index) {
        ++s.boundary_link_edges;
        continue;
      }
      ++s.link_edges2;
      if (pieces.unite(pos(t), pos(n))) --s.pieces;
    }
  }
  return s;
}

// How many tets around edge ab are reached from `first` through faces containing ab (a fan:
// every tet has at most two such neighbours).
std::size_t edge_fan_size(const TetMesh& m, const Adjacency& adj, VertexId a, VertexId b, TetId first) {
  std::vector<TetId> fan{first}, visited;
  while (!fan.empty()) {
    const TetId t = fan.back();
    fan.pop_back();
    if (std::find(visited.begin(), visited.end(), t) != visited.end()) continue;
    visited.push_back(t);
    const Tet& x = m.tet(t);
    for (int k = 0; k < 4; ++k)
      if (x[k] != a && x[k] != b && adj[t][k] != invalid_index) fan.push_back(adj[t][k]);
  }
  return visited.size();
}

// Edges ab (b > a) around vertex a whose tets form more than one fan; counts a's link vertices
// and, into edges, the edges ab with b > a.
Failure edge_failure(const TetMesh& m, const Adjacency& adj, VertexId a, const std::vector<TetId>& star,
                     const BallVerdict& v, std::size_t& link_vertices, std::size_t& edges,
                     std::vector<std::pair<VertexId, TetId>>& by_other) {
  by_other.clear();
  for (TetId t : star)
    for (VertexId b : m.tet(t))
      if (b != a) by_other.push_back({b, t});
  std::sort(by_other.begin(), by_other.end());
  link_vertices = 0;
  for (std::size_t i = 0; i < by_other.size();) {
    std::size_t j = i;
    while (j < by_other.size() && by_other[j].first == by_other[i].first) ++j;
    ++link_vertices;
    const VertexId b = by_other[i].first;
    if (b > a) {
      ++edges;
      if (edge_fan_size(m, adj, a, b, by_other[i].second) != j - i)
        return fail(v, BallFailure::non_manifold_edge, {a, b},
                    "edge (" + std::to_string(a) + " " + std::to_string(b) + "): its " + std::to_string(j - i) +
                        " tets form more than one fan");
    }
    i = j;
  }
  return std::nullopt;
}

// Per vertex a: its edges are manifold (one fan each), its tets one face-connected piece, its
// link a disc (boundary vertex) or a sphere (interior). Counts the edges.
Failure vertex_star_failure(const TetMesh& m, const Adjacency& adj, const BallVerdict& v, std::size_t& edges) {
  // Buffers reused from vertex to vertex: this loop runs for every star a local repair grows.
  std::vector<TetId> star;
  std::vector<std::pair<VertexId, TetId>> by_other;
  UnionFind pieces;
  for (VertexId a{0}; a < m.num_vertices(); ++a) {
    const auto ts = m.tets_of(a);
    star.assign(ts.begin(), ts.end());
    std::sort(star.begin(), star.end());
    const VertexStar s = vertex_star(m, adj, a, star, pieces);
    std::size_t link_vertices = 0;
    if (auto f = edge_failure(m, adj, a, star, v, link_vertices, edges, by_other)) return f;
    if (s.pieces != 1)
      return fail(v, BallFailure::non_manifold_vertex, {a},
                  "vertex " + std::to_string(a) + ": its tets form " + std::to_string(s.pieces) +
                      " pieces connected only through the vertex");
    // Link: V = link_vertices, E = (interior link edges)/2 + boundary link edges, F = #tets.
    const std::int64_t chi = static_cast<std::int64_t>(link_vertices) -
                             static_cast<std::int64_t>(s.link_edges2 / 2 + s.boundary_link_edges) +
                             static_cast<std::int64_t>(star.size());
    const bool boundary = s.boundary_link_edges > 0;
    if ((boundary && chi != 1) || (!boundary && chi != 2))
      return fail(v, BallFailure::vertex_link_not_disc_or_sphere, {a},
                  "vertex " + std::to_string(a) + ": link has Euler characteristic " + std::to_string(chi) +
                      (boundary ? " with boundary (a disc needs 1)" : " without boundary (a sphere needs 2)"));
  }
  return std::nullopt;
}

// Boundary surface: a closed 2-manifold (vertex links are discs); one component with chi 2.
Failure boundary_sphere_failure(const TetMesh& m, const std::vector<TetId>& live, const Adjacency& adj,
                                const std::vector<char>& on_boundary, BallVerdict& v) {
  UnionFind uf(m.num_vertices());
  const std::size_t bverts = std::size_t(std::count(on_boundary.begin(), on_boundary.end(), 1));
  std::size_t bcomps = bverts;
  for (TetId t : live)
    for (int i = 0; i < 4; ++i)
      if (adj[t][i] == invalid_index) {
        const Triangle f = tet_face(m.tet(t), i);
        bcomps -= uf.unite(f[0], f[1]) ? 1 : 0;
        bcomps -= uf.unite(f[0], f[2]) ? 1 : 0;
      }
  v.boundary_vertices = bverts;
  v.boundary_euler = static_cast<std::int64_t>(bverts) - static_cast<std::int64_t>(v.boundary_faces) / 2;
  if (bcomps != 1) {
    VertexId other{0};
    std::uint32_t first_root = invalid_index;
    for (VertexId a{0}; a < m.num_vertices() && !other; ++a) {
      if (!on_boundary[a]) continue;
      if (first_root == invalid_index) first_root = uf.find(a);
      else if (uf.find(a) != first_root) other = a;
    }
    return fail(v, BallFailure::boundary_not_sphere, {other},
                "boundary has " + std::to_string(bcomps) + " components (vertex " + std::to_string(other) +
                    " is on another one); a ball's boundary is one sphere");
  }
  if (v.boundary_euler != 2)
    return fail(v, BallFailure::boundary_not_sphere, {},
                "boundary surface has Euler characteristic " + std::to_string(v.boundary_euler) +
                    " (a sphere has 2)");
  return std::nullopt;
}

}  // namespace

const char* to_string(BallFailure f) {
  switch (f) {
    case BallFailure::none: return "none";
    case BallFailure::empty: return "empty";
    case BallFailure::degenerate_tet: return "degenerate_tet";
    case BallFailure::isolated_vertex: return "isolated_vertex";
    case BallFailure::duplicate_tet: return "duplicate_tet";
    case BallFailure::face_in_three_or_more_tets: return "face_in_three_or_more_tets";
    case BallFailure::inconsistent_orientation: return "inconsistent_orientation";
    case BallFailure::disconnected: return "disconnected";
    case BallFailure::non_manifold_edge: return "non_manifold_edge";
    case BallFailure::non_manifold_vertex: return "non_manifold_vertex";
    case BallFailure::vertex_link_not_disc_or_sphere: return "vertex_link_not_disc_or_sphere";
    case BallFailure::euler_characteristic: return "euler_characteristic";
    case BallFailure::boundary_not_sphere: return "boundary_not_sphere";
  }
  return "unknown";
}

BallVerdict check_ball(const TetMesh& m) {
  BallVerdict v;
  v.vertices = m.num_vertices();
  v.tets = m.num_tets();
  if (m.num_tets() == 0) return fail(v, BallFailure::empty, {}, "the mesh has no tets");
  const std::vector<TetId> live = m.live_tets();
  if (auto f = tet_failure(m, live, v)) return *f;
  Adjacency adj;
  if (auto f = face_adjacency(m, v, adj)) return *f;
  if (auto f = disconnection(m, live, v)) return *f;
  const std::vector<char> on_boundary = boundary_vertex_marks(m, live, adj);
  std::size_t edges = 0;
  if (auto f = vertex_star_failure(m, adj, v, edges)) return *f;
  v.edges = edges;
  v.euler = static_cast<std::int64_t>(m.num_vertices()) - static_cast<std::int64_t>(edges) +
            static_cast<std::int64_t>(v.faces) - static_cast<std::int64_t>(live.size());
  if (v.euler != 1)
    return fail(v, BallFailure::euler_characteristic, {},
                "Euler characteristic V-E+F-T = " + std::to_string(v.euler) + " (a ball has 1)");
  if (auto f = boundary_sphere_failure(m, live, adj, on_boundary, v)) return *f;
  v.ok = true;
  v.message = "ball";
  return v;
}

}  // namespace cmx::topology
