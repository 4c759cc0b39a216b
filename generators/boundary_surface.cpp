#include "generators/boundary_surface.hpp"

#include <algorithm>

#include "topology/complex_queries.hpp"

namespace cmx::generators::detail {

using topology::invalid_index;

std::string build_surface(const topology::TetMesh& mesh, Surface& s) {
  const auto faces = topology::boundary_faces(mesh);
  s.local.assign(mesh.num_vertices(), invalid_index);
  for (const auto& f : faces)
    for (auto v : f.face) s.local[v] = 0;
  for (std::uint32_t v = 0; v < mesh.num_vertices(); ++v)
    if (s.local[v] == 0) {
      s.local[v] = static_cast<std::uint32_t>(s.vertices.size());
      s.vertices.push_back(v);
    }
  // Each undirected edge must be in exactly two faces, once in each direction.
  std::vector<std::array<std::uint32_t, 3>> directed;  // (min, max, 1 when listed min -> max)
  for (const auto& f : faces) {
    topology::Triangle t{topology::VertexId{s.local[f.face[0]]}, topology::VertexId{s.local[f.face[1]]}, topology::VertexId{s.local[f.face[2]]}};
    s.faces.push_back(t);
    for (int i = 0; i < 3; ++i) {
      const auto a = t[std::size_t(i)], b = t[std::size_t((i + 1) % 3)];
      directed.push_back({std::min(a, b), std::max(a, b), a < b ? 1u : 0u});
    }
  }
  std::sort(directed.begin(), directed.end());
  s.neighbors.assign(s.vertices.size(), {});
  for (std::size_t i = 0; i < directed.size();) {
    std::size_t j = i;
    while (j < directed.size() && directed[j][0] == directed[i][0] && directed[j][1] == directed[i][1]) ++j;
    const auto a = directed[i][0], b = directed[i][1];
    if (j - i != 2 || directed[i][2] == directed[i + 1][2])
      return text("boundary edge (", s.vertices[a], ", ", s.vertices[b], ") is in ", j - i, " boundary faces",
                  j - i == 2 ? " listed in the same direction" : "", ": the boundary is not a closed oriented surface");
    s.neighbors[a].push_back(b);
    s.neighbors[b].push_back(a);
    i = j;
  }
  for (auto& n : s.neighbors) std::sort(n.begin(), n.end());
  return "";
}

}  // namespace cmx::generators::detail
