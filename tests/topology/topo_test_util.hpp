#pragma once
// Helpers shared by the topology tests.

#include <array>
#include <cstdint>
#include <vector>

#include "topology/generators.hpp"
#include "topology/tet_mesh.hpp"

namespace cmx::topology::test {

// det[b-a, c-a, d-a] with integer positions.
inline std::int64_t orientation(const std::array<std::int32_t, 3>& a, const std::array<std::int32_t, 3>& b,
                                const std::array<std::int32_t, 3>& c, const std::array<std::int32_t, 3>& d) {
  const std::int64_t u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const std::int64_t v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const std::int64_t w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

// The live tets whose vertices are all flagged, as a new mesh on the same vertex ids, with the
// unused vertices dropped (renumbered in increasing order).
inline TetMesh flagged_submesh(const TetMesh& m, const std::vector<char>& flags) {
  std::vector<std::uint32_t> id(m.num_vertices(), invalid_index);
  std::vector<Tet> tets;
  for (TetId t : m.live_tets()) {
    const Tet& x = m.tet(t);
    bool all = true;
    for (VertexId v : x) all = all && flags[v];
    if (all) tets.push_back(x);
  }
  for (const Tet& x : tets)
    for (VertexId v : x) id[v] = 0;
  std::uint32_t next = 0;
  for (auto& slot : id)
    if (slot != invalid_index) slot = next++;
  for (Tet& x : tets)
    for (VertexId& v : x) v = VertexId{id[v]};
  return TetMesh(next, tets);
}

// Cells of an nx*ny*nz block minus the listed cells.
inline std::vector<char> all_cells_but(std::uint32_t nx, std::uint32_t ny, std::uint32_t nz,
                                       const std::vector<std::array<std::uint32_t, 3>>& removed) {
  std::vector<char> keep(std::size_t{nx} * ny * nz, 1);
  for (const auto& c : removed) keep[c[0] + std::size_t{nx} * (c[1] + std::size_t{ny} * c[2])] = 0;
  return keep;
}

// A hexagonal bipyramid coned from a center: vertex 0 = center v (0,0,0), 1 = north b (0,0,1),
// 2 = south s (0,0,-1), 3..8 = p0..p5 on the unit circle. 12 tets, a ball with one interior
// vertex (0) whose link is the bipyramid surface.
inline TetMesh hex_bipyramid_cone() {
  std::vector<TetIndices> tets;
  for (std::uint32_t i = 0; i < 6; ++i) {
    const std::uint32_t p = 3 + i, q = 3 + (i + 1) % 6;
    tets.push_back({0, 1, p, q});
    tets.push_back({0, 2, q, p});
  }
  return TetMesh(9, tets);
}

}  // namespace cmx::topology::test
