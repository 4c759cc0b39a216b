// A whole map through the installed library: the unit cube, each face cut into two triangles and
// coned to one interior vertex, mapped onto the cube with its corners pushed out radially.
#include <cstdio>
#include <utility>

#include "algorithm/map.hpp"
#include "checks.hpp"
#include "kernel/orient_exact.hpp"

namespace {

using cmx::Rational;
using cmx::algorithm::Point3;

cmx::HPoint to_hpoint(const Point3& p) { return cmx::HPoint(p[0], p[1], p[2]); }

// Corners 0..7 at (x, y, z) with index x + 2y + 4z, then the interior vertex 8.
cmx::algorithm::MapProblem cube_problem() {
  cmx::algorithm::MapProblem p;
  for (int v = 0; v < 8; ++v) p.source.push_back({Rational(v & 1), Rational((v >> 1) & 1), Rational((v >> 2) & 1)});
  p.source.push_back({Rational(2, 5), Rational(1, 2), Rational(3, 5)});
  const std::uint32_t faces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  for (const auto& f : faces)
    for (const cmx::topology::Tet t : {cmx::topology::Tet{8, f[0], f[1], f[2]}, cmx::topology::Tet{8, f[0], f[2], f[3]}}) {
      cmx::topology::Tet positive = t;
      const cmx::Sign s = cmx::orient3d_exact(to_hpoint(p.source[t[0]]), to_hpoint(p.source[t[1]]),
                                              to_hpoint(p.source[t[2]]), to_hpoint(p.source[t[3]]));
      if (s == cmx::Sign::negative) std::swap(positive[2], positive[3]);
      p.tets.push_back(positive);
    }
  // Corner v moves away from the centre by the factor 1 + v/8: still star-shaped about the centre.
  const Rational half(1, 2);
  for (std::uint32_t v = 0; v < 8; ++v) {
    const Rational factor = 1 + Rational(v, 8);
    p.boundary_vertices.push_back(v);
    Point3 q;
    for (int k = 0; k < 3; ++k) q[k] = half + factor * (p.source[v][k] - half);
    p.boundary_positions.push_back(q);
  }
  return p;
}

}  // namespace

int check_map() {
  const cmx::algorithm::MapResult r = cmx::algorithm::map_to_domain(cube_problem());
  const bool ok = r.outcome == cmx::algorithm::MapOutcome::success && r.verification.ok();
  std::printf("map_to_domain: %s, %zu tets, verification %s%s\n", cmx::algorithm::to_string(r.outcome),
              r.tets.size(), r.verification.ok() ? "ok" : "failed: ", r.verification.first_failure.c_str());
  return ok ? 0 : 1;
}
