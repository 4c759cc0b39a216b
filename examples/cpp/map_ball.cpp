// Maps a small ball (a cube coned from an interior point into 12 tets) onto a sphere.
#include <cmx/kernel.hpp>
#include <cmx/map.hpp>
#include <cstdio>
#include <utility>
#include <vector>

int main() {
  std::vector<cmx::Point3d> V;  // corners x + 2y + 4z, then the interior vertex 8
  for (int v = 0; v < 8; ++v) V.push_back({double(v & 1), double(v >> 1 & 1), double(v >> 2 & 1)});
  V.push_back({0.5, 0.5, 0.5});
  std::vector<cmx::Tet> T;
  for (auto [a, b, c, d] :
       {std::array{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}})
    for (cmx::Tet t : {cmx::Tet{8, uint32_t(a), uint32_t(b), uint32_t(c)},
                       cmx::Tet{8, uint32_t(a), uint32_t(c), uint32_t(d)}}) {
      if (cmx::orient3d(V[t[0]], V[t[1]], V[t[2]], V[t[3]]) < 0) std::swap(t[2], t[3]);  // make it positive
      T.push_back(t);
    }
  const cmx::ShapeBoundary sphere = cmx::boundary_for_shape(V, T, "sphere");
  const cmx::MapResult r = cmx::map_to_domain(V, T, sphere.ids, sphere.positions);
  std::printf("status: %s %s\nexact_valid: %s\ndouble_valid: %s\ntets: %zu\n", cmx::to_string(r.status),
              r.message.c_str(), r.exact_valid ? "yes" : "no", r.double_valid ? "yes" : "no", r.tets.size());
  return r.ok() ? 0 : 1;
}
