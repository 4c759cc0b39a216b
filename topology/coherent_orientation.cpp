#include "topology/coherent_orientation.hpp"

#include <deque>
#include <vector>

#include "topology/complex_queries.hpp"

namespace cmx::topology {
namespace {

// The tet as currently ordered: two vertices swapped when flipped.
Tet current(const TetMesh& m, const std::vector<char>& flipped, TetId t) {
  Tet x = m.tet(t);
  if (flipped[t]) std::swap(x[2], x[3]);
  return x;
}

// The local index, in t's order as listed, of the face of t that is not at vertex `apex`.
int face_opposite(const TetMesh& m, TetId t, VertexId apex) { return local_index(m.tet(t), apex); }

// The face opposite listed local index i of t, oriented as t currently induces it.
Triangle oriented_face(const TetMesh& m, const std::vector<char>& flipped, TetId t, int i) {
  const int now = flipped[t] && i >= 2 ? 5 - i : i;  // swapping vertices 2 and 3 swaps their faces
  return tet_face(current(m, flipped, t), now);
}

// Built by appending: g++ 12 warns falsely (-Wrestrict) on "literal" + std::string.
std::string face_text(const Triangle& f) {
  std::string out = "face (";
  for (int k = 0; k < 3; ++k) {
    if (k > 0) out += ' ';
    out += std::to_string(f[std::size_t(k)]);
  }
  out += ')';
  return out;
}

}  // namespace

CoherentOrientation orient_coherently(TetMesh& m) {
  CoherentOrientation out;
  const TetAdjacency adj = tet_adjacency(m);
  if (!adj.manifold) {
    out.message = face_text(adj.nonmanifold_face);
    out.message += " lies in three or more tets";
    return out;
  }
  std::vector<char> flipped(m.tet_capacity(), 0), seen(m.tet_capacity(), 0);
  std::deque<TetId> work;
  for (TetId start : m.live_tets()) {
    if (seen[start]) continue;
    seen[start] = 1;
    work.push_back(start);
    while (!work.empty()) {
      const TetId t = work.front();
      work.pop_front();
      for (int i = 0; i < 4; ++i) {
        const TetId u = adj.neighbor[t][i];
        if (u == invalid_tet) continue;
        const Triangle f = oriented_face(m, flipped, t, i);
        VertexId apex = invalid_vertex;
        for (VertexId w : m.tet(u))
          if (!contains(m.tet(t), w)) apex = w;
        const Triangle g = oriented_face(m, flipped, u, face_opposite(m, u, apex));
        if (!same_orientation(f, g)) continue;  // coherent already
        if (seen[u]) {
          out.message = "the tets around ";
          out.message += face_text(tet_face(m.tet(t), i));
          out.message += " cannot be oriented alike: the complex is not orientable";
          return out;
        }
        flipped[u] = 1;
      }
      for (int i = 0; i < 4; ++i)
        if (const TetId u = adj.neighbor[t][i]; u != invalid_tet && !seen[u]) {
          seen[u] = 1;
          work.push_back(u);
        }
    }
  }
  for (TetId t : m.live_tets())
    if (flipped[t]) {
      m.set_tet(t, current(m, flipped, t));
      ++out.flipped;
    }
  out.ok = true;
  return out;
}

}  // namespace cmx::topology
