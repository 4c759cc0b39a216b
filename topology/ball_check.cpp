#include "topology/ball_check.hpp"

#include <algorithm>
#include <numeric>
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
  for (TetId t : live) {
    const Tet& x = m.tet(t);
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        if (x[i] == x[j])
          return fail(v, BallFailure::degenerate_tet, {x.begin(), x.end()},
                      "tet " + std::to_string(t) + " " + ids(x) + " repeats vertex " + std::to_string(x[i]));
  }
  for (VertexId a = 0; a < m.num_vertices(); ++a)
    if (m.tets_of(a).empty())
      return fail(v, BallFailure::isolated_vertex, {a},
                  "vertex " + std::to_string(a) + " is used by no tet");

  // Faces, grouped at their smallest vertex: duplicates, 3+ tets, orientation, adjacency.
  std::vector<std::array<TetId, 4>> adj(m.tet_capacity(),
                                        {invalid_index, invalid_index, invalid_index, invalid_index});
  struct Key {
    std::uint64_t other;
    TetId tet;
    std::uint8_t local;
  };
  std::vector<Key> keys;
  std::size_t interior_faces = 0, bfaces = 0;
  for (VertexId a = 0; a < m.num_vertices(); ++a) {
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
    std::sort(keys.begin(), keys.end(), [](const Key& x, const Key& y) {
      return x.other != y.other ? x.other < y.other : x.tet < y.tet;
    });
    for (std::size_t i = 0; i < keys.size();) {
      std::size_t j = i;
      while (j < keys.size() && keys[j].other == keys[i].other) ++j;
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
        const Key& p = keys[i];
        const Key& q = keys[i + 1];
        const Triangle fp = tet_face(m.tet(p.tet), p.local);
        const Triangle fq = tet_face(m.tet(q.tet), q.local);
        if (same_orientation(fp, fq))
          return fail(v, BallFailure::inconsistent_orientation, {fp.begin(), fp.end()},
                      "face " + ids(fp) + " has the same orientation in tets " + std::to_string(p.tet) +
                          " and " + std::to_string(q.tet) + " (must be opposite)");
        adj[p.tet][p.local] = q.tet;
        adj[q.tet][q.local] = p.tet;
        ++interior_faces;
      } else {
        ++bfaces;
      }
      i = j;
    }
  }
  v.faces = interior_faces + bfaces;
  v.boundary_faces = bfaces;

  // Connectivity of the complex (through vertices: two pieces sharing only a vertex are
  // connected, and reported below as a non-manifold vertex instead).
  {
    UnionFind uf(m.num_vertices());
    for (TetId t : live)
      for (int i = 1; i < 4; ++i) uf.unite(m.tet(t)[0], m.tet(t)[i]);
    const std::uint32_t root = uf.find(m.tet(live.front())[0]);
    for (VertexId a = 0; a < m.num_vertices(); ++a)
      if (uf.find(a) != root)
        return fail(v, BallFailure::disconnected, {a},
                    "vertex " + std::to_string(a) + " is not connected to vertex " +
                        std::to_string(m.tet(live.front())[0]));
  }

  // Edges and vertex links, per vertex a: the tets around a, their face-connectivity (vertex
  // manifoldness) and, for each edge ab with b > a, the face-connectivity of the tets around ab.
  std::vector<std::pair<VertexId, TetId>> by_other;
  std::vector<TetId> star, fan, visited;
  std::vector<std::uint32_t> local_parent;
  std::vector<char> on_boundary(m.num_vertices(), 0);
  std::size_t edges = 0;
  for (TetId t : live)
    for (int i = 0; i < 4; ++i)
      if (adj[t][i] == invalid_index)
        for (VertexId w : tet_face(m.tet(t), i)) on_boundary[w] = 1;
  auto local_find = [&](std::uint32_t x) {
    while (local_parent[x] != x) x = local_parent[x] = local_parent[local_parent[x]];
    return x;
  };
  for (VertexId a = 0; a < m.num_vertices(); ++a) {
    const auto ts = m.tets_of(a);
    star.assign(ts.begin(), ts.end());
    std::sort(star.begin(), star.end());
    auto pos = [&](TetId t) {
      return static_cast<std::uint32_t>(std::lower_bound(star.begin(), star.end(), t) - star.begin());
    };
    // Vertex manifoldness: tets around a connected through faces containing a.
    local_parent.resize(star.size());
    std::iota(local_parent.begin(), local_parent.end(), 0u);
    std::size_t comps = star.size();
    std::size_t link_edges2 = 0;  // 2 * #faces containing a, minus boundary ones
    std::size_t boundary_link_edges = 0;
    for (TetId t : star) {
      const int ia = local_index(m.tet(t), a);
      for (int i = 0; i < 4; ++i) {
        if (i == ia) continue;
        const TetId n = adj[t][i];
        if (n == invalid_index) {
          ++boundary_link_edges;
          continue;
        }
        ++link_edges2;
        const std::uint32_t x = local_find(pos(t)), y = local_find(pos(n));
        if (x != y) {
          local_parent[x] = y;
          --comps;
        }
      }
    }
    // Edges ab, b > a: tets around ab connected through the two faces containing ab.
    by_other.clear();
    for (TetId t : star)
      for (VertexId b : m.tet(t))
        if (b != a) by_other.push_back({b, t});
    std::sort(by_other.begin(), by_other.end());
    std::size_t link_vertices = 0;
    for (std::size_t i = 0; i < by_other.size();) {
      std::size_t j = i;
      while (j < by_other.size() && by_other[j].first == by_other[i].first) ++j;
      ++link_vertices;
      const VertexId b = by_other[i].first;
      if (b > a) {
        ++edges;
        // Around an edge every tet has at most two neighbours containing ab: walk the fan.
        std::size_t seen = 0;
        fan.clear();
        visited.clear();
        fan.push_back(by_other[i].second);
        while (!fan.empty()) {
          const TetId t = fan.back();
          fan.pop_back();
          if (std::find(visited.begin(), visited.end(), t) != visited.end()) continue;
          visited.push_back(t);
          ++seen;
          const Tet& x = m.tet(t);
          for (int k = 0; k < 4; ++k)
            if (x[k] != a && x[k] != b && adj[t][k] != invalid_index) fan.push_back(adj[t][k]);
        }
        if (seen != j - i)
          return fail(v, BallFailure::non_manifold_edge, {a, b},
                      "edge (" + std::to_string(a) + " " + std::to_string(b) + "): its " +
                          std::to_string(j - i) + " tets form more than one fan");
      }
      i = j;
    }
    if (comps != 1)
      return fail(v, BallFailure::non_manifold_vertex, {a},
                  "vertex " + std::to_string(a) + ": its tets form " + std::to_string(comps) +
                      " pieces connected only through the vertex");
    // Link: V = link_vertices, E = (interior link edges)/2 + boundary link edges, F = #tets.
    const std::int64_t chi = static_cast<std::int64_t>(link_vertices) -
                             static_cast<std::int64_t>(link_edges2 / 2 + boundary_link_edges) +
                             static_cast<std::int64_t>(star.size());
    const bool boundary = boundary_link_edges > 0;
    if ((boundary && chi != 1) || (!boundary && chi != 2))
      return fail(v, BallFailure::vertex_link_not_disc_or_sphere, {a},
                  "vertex " + std::to_string(a) + ": link has Euler characteristic " + std::to_string(chi) +
                      (boundary ? " with boundary (a disc needs 1)" : " without boundary (a sphere needs 2)"));
  }
  v.edges = edges;
  v.euler = static_cast<std::int64_t>(m.num_vertices()) - static_cast<std::int64_t>(edges) +
            static_cast<std::int64_t>(v.faces) - static_cast<std::int64_t>(live.size());
  if (v.euler != 1)
    return fail(v, BallFailure::euler_characteristic, {},
                "Euler characteristic V-E+F-T = " + std::to_string(v.euler) + " (a ball has 1)");

  // Boundary surface: a closed 2-manifold (vertex links are discs); one component with chi 2.
  UnionFind uf(m.num_vertices());
  std::size_t bverts = 0;
  for (VertexId a = 0; a < m.num_vertices(); ++a) bverts += on_boundary[a] ? 1 : 0;
  std::size_t bcomps = bverts;
  for (TetId t : live)
    for (int i = 0; i < 4; ++i)
      if (adj[t][i] == invalid_index) {
        const Triangle f = tet_face(m.tet(t), i);
        bcomps -= uf.unite(f[0], f[1]) ? 1 : 0;
        bcomps -= uf.unite(f[0], f[2]) ? 1 : 0;
      }
  v.boundary_vertices = bverts;
  v.boundary_euler = static_cast<std::int64_t>(bverts) - static_cast<std::int64_t>(bfaces) / 2;
  if (bcomps != 1) {
    VertexId other = 0;
    std::uint32_t first_root = invalid_index;
    for (VertexId a = 0; a < m.num_vertices(); ++a) {
      if (!on_boundary[a]) continue;
      if (first_root == invalid_index) first_root = uf.find(a);
      else if (uf.find(a) != first_root) {
        other = a;
        break;
      }
    }
    return fail(v, BallFailure::boundary_not_sphere, {other},
                "boundary has " + std::to_string(bcomps) + " components (vertex " + std::to_string(other) +
                    " is on another one); a ball's boundary is one sphere");
  }
  if (v.boundary_euler != 2)
    return fail(v, BallFailure::boundary_not_sphere, {},
                "boundary surface has Euler characteristic " + std::to_string(v.boundary_euler) +
                    " (a sphere has 2)");
  v.ok = true;
  v.message = "ball";
  return v;
}

}  // namespace cmx::topology
