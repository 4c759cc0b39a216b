#include "topology/mesh_edits.hpp"

#include <algorithm>
#include <array>

#include "topology/complex_queries.hpp"

namespace cmx::topology {
namespace {

template <class T>
bool includes_sorted(const std::vector<T>& big, const std::vector<T>& small) {
  return std::includes(big.begin(), big.end(), small.begin(), small.end());
}

template <class T>
std::vector<T> intersect(const std::vector<T>& x, const std::vector<T>& y) {
  std::vector<T> out;
  std::set_intersection(x.begin(), x.end(), y.begin(), y.end(), std::back_inserter(out));
  return out;
}

// Link of v inside the boundary surface: boundary vertices and edges (x,y) with (v,x,y) a
// boundary face. Sorted. A face at v lies only in tets of v, so it is a boundary face when it
// occurs once among them: counted there, not by a search around each face, which costs the
// degree of the face's first vertex (a vertex at p_c can have thousands of tets, and the
// collapses that undo pushes ask this for each of them).
void boundary_link(const TetMesh& m, VertexId v, std::vector<VertexId>& verts, std::vector<Edge>& edges) {
  verts.clear();
  edges.clear();
  for (TetId t : m.tets_of(v)) {
    const Tet& x = m.tet(t);
    VertexId o[3];
    int n = 0;
    for (VertexId w : x)
      if (w != v) o[n++] = w;
    std::sort(o, o + 3);
    edges.push_back(Edge{o[0], o[1]});
    edges.push_back(Edge{o[0], o[2]});
    edges.push_back(Edge{o[1], o[2]});
  }
  std::sort(edges.begin(), edges.end());
  std::size_t kept = 0;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i == 1) edges[kept++] = edges[i];
    i = j;
  }
  edges.resize(kept);
  for (const Edge& e : edges) {
    verts.push_back(e[0]);
    verts.push_back(e[1]);
  }
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
}

// The even permutation of t that puts x and y last, as (p, q, x, y). Precondition: x, y in t.
Tet with_last(const Tet& t, VertexId x, VertexId y) {
  Tet rest{};
  int n = 0;
  for (VertexId v : t)
    if (v != x && v != y) rest[n++] = v;
  const Tet candidate{rest[0], rest[1], x, y};
  // Even iff the permutation t -> candidate has an even number of inversions.
  std::array<int, 4> pos{};
  for (int i = 0; i < 4; ++i) pos[i] = local_index(t, candidate[i]);
  int inversions = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) inversions += pos[i] > pos[j] ? 1 : 0;
  return inversions % 2 == 0 ? candidate : Tet{rest[1], rest[0], x, y};
}

bool is_edge(const TetMesh& m, VertexId a, VertexId b) {
  for (TetId t : m.tets_of(a))
    if (contains(m.tet(t), b)) return true;
  return false;
}

}  // namespace

SplitResult split_edge(TetMesh& m, VertexId a, VertexId b) {
  SplitResult r;
  if (a >= m.num_vertices() || b >= m.num_vertices() || a == b) {
    r.message = "invalid edge";
    return r;
  }
  const std::vector<TetId> around = tets_around_edge(m, a, b);
  if (around.empty()) {
    r.message = "edge (" + std::to_string(a) + " " + std::to_string(b) + ") is in no tet";
    return r;
  }
  const VertexId mid = m.add_vertex();
  r.new_vertex = mid;
  for (TetId t : around) {
    Tet first = m.tet(t), second = m.tet(t);
    first[local_index(first, b)] = mid;    // (.., a, .., m, ..)
    second[local_index(second, a)] = mid;  // (.., m, .., b, ..)
    m.set_tet(t, first);
    r.modified.push_back(t);
    r.created.push_back(m.add_tet(second));
  }
  r.ok = true;
  return r;
}

SplitResult split_face(TetMesh& m, VertexId a, VertexId b, VertexId c) {
  SplitResult r;
  if (a >= m.num_vertices() || b >= m.num_vertices() || c >= m.num_vertices() || a == b || b == c || a == c) {
    r.message = "invalid face";
    return r;
  }
  const std::vector<TetId> around = tets_around_face(m, a, b, c);
  if (around.empty()) {
    r.message =
        "face (" + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + ") is in no tet";
    return r;
  }
  const VertexId mid = m.add_vertex();
  r.new_vertex = mid;
  for (TetId t : around) {
    const Tet orig = m.tet(t);
    Tet parts[3] = {orig, orig, orig};
    parts[0][local_index(orig, a)] = mid;
    parts[1][local_index(orig, b)] = mid;
    parts[2][local_index(orig, c)] = mid;
    m.set_tet(t, parts[0]);
    r.modified.push_back(t);
    r.created.push_back(m.add_tet(parts[1]));
    r.created.push_back(m.add_tet(parts[2]));
  }
  r.ok = true;
  return r;
}

bool satisfies_link_condition(const TetMesh& m, VertexId a, VertexId b) {
  if (a == b || a >= m.num_vertices() || b >= m.num_vertices()) return false;
  const SimplexSet la = vertex_link(m, a), lb = vertex_link(m, b), lab = edge_link(m, a, b);
  if (lab.vertices.empty()) return false;  // not an edge
  // Lk(ab) is always inside Lk(a) ∩ Lk(b); equality needs the intersection to be no larger.
  const auto iv = intersect(la.vertices, lb.vertices);
  const auto ie = intersect(la.edges, lb.edges);
  const auto it = intersect(la.triangles, lb.triangles);
  if (iv != lab.vertices || ie != lab.edges || !it.empty()) return false;
  // Boundary rule: with a virtual vertex coning off the boundary.
  std::vector<VertexId> bva, bvb;
  std::vector<Edge> bea, beb;
  boundary_link(m, a, bva, bea);
  boundary_link(m, b, bvb, beb);
  if (bva.empty() || bvb.empty()) return true;  // at most one endpoint on the boundary
  // Both on the boundary: ab must be a boundary edge, and the boundary links meet exactly in
  // Lk_boundary(ab) (the two apexes of the boundary faces at ab) with no common edge.
  if (!std::binary_search(bva.begin(), bva.end(), b)) return false;
  std::vector<VertexId> apex;
  for (VertexId x : lab.vertices) {
    if (tets_around_face(m, a, b, x).size() == 1) apex.push_back(x);
  }
  std::sort(apex.begin(), apex.end());
  return intersect(bva, bvb) == apex && intersect(bea, beb).empty();
}

CollapseResult collapse_edge(TetMesh& m, VertexId keep, VertexId gone) {
  CollapseResult r;
  if (tets_around_edge(m, keep, gone).empty() || keep == gone) {
    r.message = "no such edge";
    return r;
  }
  if (!satisfies_link_condition(m, keep, gone)) {
    r.message = "link condition fails for edge (" + std::to_string(keep) + " " + std::to_string(gone) + ")";
    return r;
  }
  const std::vector<TetId> star(m.tets_of(gone).begin(), m.tets_of(gone).end());
  for (TetId t : star) {
    if (contains(m.tet(t), keep)) {
      m.remove_tet(t);
      r.removed.push_back(t);
    } else {
      Tet x = m.tet(t);
      x[local_index(x, gone)] = keep;
      m.set_tet(t, x);
      r.modified.push_back(t);
    }
  }
  r.ok = true;
  return r;
}

FlipPlan plan_flip_23(const TetMesh& m, VertexId a, VertexId b, VertexId c) {
  FlipPlan r;
  r.old = tets_around_face(m, a, b, c);
  if (r.old.size() != 2) {
    r.message = "face is not shared by two tets";
    return r;
  }
  const Tet& first = m.tet(r.old[0]);
  VertexId d = invalid_vertex, e = invalid_vertex;
  for (VertexId v : first)
    if (v != a && v != b && v != c) d = v;
  for (VertexId v : m.tet(r.old[1]))
    if (v != a && v != b && v != c) e = v;
  if (is_edge(m, d, e)) {
    r.message = "the new edge is already an edge";
    return r;
  }
  // with_last gives (p', q', a, d) even; moving d to the front is odd, so (d, q', p', a) is even:
  // seen from d the ring runs p = q', q = p', r = a.
  const Tet x = with_last(first, a, d);
  const VertexId p = x[1], q = x[0], r0 = a;
  r.fresh = {Tet{p, q, d, e}, Tet{q, r0, d, e}, Tet{r0, p, d, e}};
  r.ok = true;
  return r;
}

FlipPlan plan_flip_32(const TetMesh& m, VertexId d, VertexId e) {
  FlipPlan r;
  r.old = tets_around_edge(m, d, e);
  if (r.old.size() != 3) {
    r.message = "edge is not in three tets";
    return r;
  }
  const Tet pqde = with_last(m.tet(r.old[0]), d, e);
  const VertexId p = pqde[0], q = pqde[1];
  // A closed ring of three tets has three ring vertices; a boundary edge in three tets has four.
  std::vector<VertexId> ring;
  for (TetId t : r.old)
    for (VertexId v : m.tet(t))
      if (v != d && v != e) ring.push_back(v);
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  if (ring.size() != 3) {
    r.message = "the ring is not three vertices (a boundary edge)";
    return r;
  }
  VertexId third = invalid_vertex;
  for (VertexId v : ring)
    if (v != p && v != q) third = v;
  if (!tets_around_face(m, p, q, third).empty()) {
    r.message = "the ring's face is already a face";
    return r;
  }
  r.fresh = {Tet{d, p, q, third}, Tet{e, q, p, third}};
  r.ok = true;
  return r;
}

FlipResult apply_flip(TetMesh& m, const FlipPlan& plan) {
  FlipResult r;
  if (!plan.ok) {
    r.message = plan.message;
    return r;
  }
  for (TetId t : plan.old) {
    r.removed.push_back(m.tet(t));
    m.remove_tet(t);
  }
  for (const Tet& t : plan.fresh) r.created.push_back(m.add_tet(t));
  r.ok = true;
  return r;
}

FlipResult flip_23(TetMesh& m, VertexId a, VertexId b, VertexId c) {
  return apply_flip(m, plan_flip_23(m, a, b, c));
}

FlipResult flip_32(TetMesh& m, VertexId d, VertexId e) {
  return apply_flip(m, plan_flip_32(m, d, e));
}

void undo_flip(TetMesh& m, const FlipResult& flip) {
  // By content, not by handle: undoing a later flip that took one of these tets out put it back
  // under a new handle.
  for (TetId t : flip.created) {
    const Tet x = m.tet(t);
    for (TetId u : m.tets_of(x[0]))
      if (m.tet(u) == x) {
        m.remove_tet(u);
        break;
      }
  }
  for (const Tet& t : flip.removed) m.add_tet(t);
}

}  // namespace cmx::topology
