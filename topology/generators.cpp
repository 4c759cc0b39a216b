#include "topology/generators.hpp"

#include <algorithm>

namespace cmx::topology {
namespace {

// The 6 tets of the unit cell with lower corner (i,j,k), as offsets, positively oriented for
// the identity placement. The tets follow monotone paths from the chosen diagonal's start
// corner q, stepping along the axes in each of the 6 orders.
void cell_tets(std::int32_t i, std::int32_t j, std::int32_t k, GridTriangulation tri,
               std::vector<std::array<std::array<std::int32_t, 3>, 4>>& out) {
  std::array<std::int32_t, 3> lo{i, j, k};
  std::array<std::int32_t, 3> q = lo, dir{1, 1, 1};
  if (tri == GridTriangulation::reflected) {
    for (int a = 0; a < 3; ++a) {
      const bool even = (lo[a] % 2 + 2) % 2 == 0;
      q[a] = even ? lo[a] : lo[a] + 1;
      dir[a] = even ? 1 : -1;
    }
  }
  static constexpr int perms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  const int dir_sign = dir[0] * dir[1] * dir[2];
  for (int p = 0; p < 6; ++p) {
    std::array<std::array<std::int32_t, 3>, 4> t;
    t[0] = q;
    for (int s = 0; s < 3; ++s) {
      t[s + 1] = t[s];
      t[s + 1][perms[p][s]] += dir[perms[p][s]];
    }
    // det[t1-t0, t2-t0, t3-t0] = sign(perm) * product of the step directions.
    const int sign = (p < 3 ? 1 : -1) * dir_sign;
    if (sign < 0) std::swap(t[2], t[3]);
    out.push_back(t);
  }
}

}  // namespace

GridComplex voxel_complex(std::uint32_t nx, std::uint32_t ny, std::uint32_t nz, std::span<const char> keep_cell,
                          GridTriangulation tri) {
  const std::size_t vx = nx + 1, vy = ny + 1, vz = nz + 1;
  auto gid = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
    return static_cast<std::size_t>(i + static_cast<std::int64_t>(vx) * (j + static_cast<std::int64_t>(vy) * k));
  };
  std::vector<std::uint32_t> id(vx * vy * vz, invalid_index);
  auto kept = [&](std::size_t c) { return keep_cell.empty() || (c < keep_cell.size() && keep_cell[c] != 0); };
  // Mark used vertices, then number them in (i,j,k) order.
  for (std::uint32_t k = 0; k < nz; ++k)
    for (std::uint32_t j = 0; j < ny; ++j)
      for (std::uint32_t i = 0; i < nx; ++i) {
        if (!kept(i + std::size_t{nx} * (j + std::size_t{ny} * k))) continue;
        for (int c = 0; c < 8; ++c) id[gid(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1))] = 0;
      }
  GridComplex g;
  std::uint32_t next = 0;
  for (std::size_t k = 0; k < vz; ++k)
    for (std::size_t j = 0; j < vy; ++j)
      for (std::size_t i = 0; i < vx; ++i) {
        auto& slot = id[gid(static_cast<std::int64_t>(i), static_cast<std::int64_t>(j), static_cast<std::int64_t>(k))];
        if (slot == invalid_index) continue;
        slot = next++;
        g.coords.push_back({static_cast<std::int32_t>(i), static_cast<std::int32_t>(j), static_cast<std::int32_t>(k)});
      }
  std::vector<Tet> tets;
  std::vector<std::array<std::array<std::int32_t, 3>, 4>> local;
  for (std::uint32_t k = 0; k < nz; ++k)
    for (std::uint32_t j = 0; j < ny; ++j)
      for (std::uint32_t i = 0; i < nx; ++i) {
        if (!kept(i + std::size_t{nx} * (j + std::size_t{ny} * k))) continue;
        local.clear();
        cell_tets(static_cast<std::int32_t>(i), static_cast<std::int32_t>(j), static_cast<std::int32_t>(k), tri, local);
        for (const auto& t : local) {
          Tet x;
          for (int a = 0; a < 4; ++a) x[a] = VertexId{id[gid(t[a][0], t[a][1], t[a][2])]};
          tets.push_back(x);
        }
      }
  g.mesh = TetMesh(next, tets);
  return g;
}

GridComplex grid_complex(std::uint32_t nx, std::uint32_t ny, std::uint32_t nz, GridTriangulation tri) {
  return voxel_complex(nx, ny, nz, {}, tri);
}

TetMesh single_tet() {
  return TetMesh(4, make_tets({{0, 1, 2, 3}}));
}

TetMesh two_tets_sharing_face() {
  // Vertex 4 at (1,1,1) lies beyond face (1,2,3): det[2-1, 3-1, 4-1] = 2 > 0.
  return TetMesh(5, make_tets({{0, 1, 2, 3}, {1, 2, 3, 4}}));
}

}  // namespace cmx::topology
