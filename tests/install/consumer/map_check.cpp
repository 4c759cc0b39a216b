// A whole map through the installed library: the unit cube, each face cut into two triangles and
// coned to one interior vertex, mapped onto the cube with its corners pushed out radially.
#include <cmx/kernel.hpp>
#include <cmx/map.hpp>
#include <cstdio>
#include <utility>
#include <vector>

#include "checks.hpp"

int check_map() {
  // Corners 0..7 at (x, y, z) with index x + 2y + 4z, then the interior vertex 8.
  std::vector<cmx::Point3d> V;
  for (int v = 0; v < 8; ++v) V.push_back({double(v & 1), double((v >> 1) & 1), double((v >> 2) & 1)});
  V.push_back({0.4, 0.5, 0.6});
  const std::uint32_t faces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                     {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  std::vector<cmx::Tet> T;
  for (const auto& f : faces)
    for (cmx::Tet t : {cmx::Tet{8, f[0], f[1], f[2]}, cmx::Tet{8, f[0], f[2], f[3]}}) {
      if (cmx::orient3d(V[t[0]], V[t[1]], V[t[2]], V[t[3]]) < 0) std::swap(t[2], t[3]);
      T.push_back(t);
    }
  // Corner v moves away from the centre by the factor 1 + v/8 (exact in doubles): still
  // star-shaped about the centre.
  const std::vector<std::uint32_t> ids = cmx::boundary_vertices(T, V.size());
  std::vector<cmx::Point3d> P;
  for (const std::uint32_t v : ids) {
    const double factor = 1 + v / 8.0;
    P.push_back(
        {0.5 + factor * (V[v][0] - 0.5), 0.5 + factor * (V[v][1] - 0.5), 0.5 + factor * (V[v][2] - 0.5)});
  }
  const cmx::MapResult r = cmx::map_to_domain(V, T, ids, P);
  std::printf("map_to_domain: %s%s%s, %zu tets, exact_valid %s, double_valid %s\n", cmx::to_string(r.status),
              r.message.empty() ? "" : ": ", r.message.c_str(), r.tets.size(), r.exact_valid ? "yes" : "no",
              r.double_valid ? "yes" : "no");
  return r.ok() && r.exact_valid && ids.size() == 8 ? 0 : 1;
}
