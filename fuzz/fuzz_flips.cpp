// Fuzz target: random sequences of 2-3 and 3-2 flips and undos on a jittered Freudenthal grid
// (topology/mesh_edits.hpp). Asserts that incidences stay consistent after every edit; that a
// flip made only where all its new tets are positive keeps every tet positive and the total volume
// unchanged; that undoing flips in reverse order restores the original tets exactly (by content:
// the handles change); and that the mesh is a ball at the end.
//
// Input layout: byte 0 picks the grid size (1 to 3 cells a side); the next 27 * 3 bytes jitter
// the vertices (integer positions scaled by 8, each coordinate moved by -2..2); then one operation
// per 3 bytes: kind (2-3 of a tet's face, 3-2 of a tet's edge, or undo the last flip), a tet index,
// a local face or edge index.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "topology/ball_check.hpp"
#include "topology/complex_queries.hpp"
#include "topology/consistency.hpp"
#include "topology/generators.hpp"
#include "topology/mesh_edits.hpp"

using namespace cmx::topology;

namespace {

using P = std::array<std::int64_t, 3>;

std::int64_t orientation(const P& a, const P& b, const P& c, const P& d) {
  const std::int64_t u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const std::int64_t v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const std::int64_t w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
         u[2] * (v[0] * w[1] - v[1] * w[0]);
}

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "fuzz_flips: %s\n", what);
  std::abort();
}

std::vector<Tet> sorted_tets(const TetMesh& m) {
  std::vector<Tet> out;
  for (TetId t : m.live_tets()) out.push_back(m.tet(t));
  std::sort(out.begin(), out.end());
  return out;
}

std::int64_t volume(const TetMesh& m, const std::vector<P>& at) {
  std::int64_t sum = 0;
  for (TetId t : m.live_tets()) {
    const Tet& x = m.tet(t);
    sum += orientation(at[x[0]], at[x[1]], at[x[2]], at[x[3]]);
  }
  return sum;
}

bool all_positive(const TetMesh& m, const std::vector<P>& at) {
  for (TetId t : m.live_tets()) {
    const Tet& x = m.tet(t);
    if (orientation(at[x[0]], at[x[1]], at[x[2]], at[x[3]]) <= 0) return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::uint32_t n = 1 + data[0] % 3;
  GridComplex g = grid_complex(n, n, n);
  TetMesh& m = g.mesh;
  std::size_t pos = 1;
  std::vector<P> at;
  for (const auto& c : g.coords) {
    P p{};
    for (int k = 0; k < 3; ++k) {
      const int jitter = pos < size ? int(data[pos++] % 5) - 2 : 0;
      p[std::size_t(k)] = 8 * std::int64_t(c[std::size_t(k)]) + jitter;
    }
    at.push_back(p);
  }
  if (!all_positive(m, at)) return 0;  // a jitter that inverts a tet is not a case
  const std::vector<Tet> original = sorted_tets(m);
  const std::int64_t total = volume(m, at);
  std::vector<FlipResult> made;
  for (; pos + 3 <= size; pos += 3) {
    const int kind = data[pos] % 3;
    if (kind == 2) {
      if (made.empty()) continue;
      undo_flip(m, made.back());
      made.pop_back();
    } else {
      const std::vector<TetId> live = m.live_tets();
      const Tet x = m.tet(live[data[pos + 1] % live.size()]);
      const int i = data[pos + 2] % (kind == 0 ? 4 : 6);
      FlipPlan plan;
      if (kind == 0) {
        const Triangle f = tet_face(x, i);
        plan = plan_flip_23(m, f[0], f[1], f[2]);
      } else {
        static constexpr int edges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
        plan = plan_flip_32(m, x[std::size_t(edges[i][0])], x[std::size_t(edges[i][1])]);
      }
      if (!plan.ok) continue;
      const bool positive = std::all_of(plan.fresh.begin(), plan.fresh.end(), [&](const Tet& t) {
        return orientation(at[t[0]], at[t[1]], at[t[2]], at[t[3]]) > 0;
      });
      if (!positive) continue;
      made.push_back(apply_flip(m, plan));
      if (!made.back().ok) fail("a planned flip was refused");
    }
    if (!check_incidences(m).ok) fail("incidences broken");
    if (!all_positive(m, at)) fail("a flip of positive tets left a tet that is not positive");
    if (volume(m, at) != total) fail("the total volume changed");
  }
  while (!made.empty()) {
    undo_flip(m, made.back());
    made.pop_back();
  }
  if (sorted_tets(m) != original) fail("undoing every flip did not restore the tets");
  if (!check_ball(m).ok) fail("not a ball after the undos");
  return 0;
}
