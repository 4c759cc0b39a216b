#include "generators/boundary_corners.hpp"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <set>
#include <span>

#include "generators/disjoint_paths.hpp"

namespace cmx::generators::detail {
namespace {

using topology::invalid_index;

// Dijkstra over boundary edges from every vertex of `from` (each at distance 0), a step from v
// to u costing cost(v, u) (infinity: not taken); it stops once `stop` is settled (invalid_index:
// never). Ties are broken by vertex id, so the result is deterministic.
struct SurfaceDistances {
  std::vector<double> dist;
  std::vector<std::uint32_t> prev;  // invalid_index where unreached, and at the sources
};
template <class Cost>
SurfaceDistances surface_dijkstra(const Surface& s, std::span<const std::uint32_t> from, Cost cost,
                                  std::uint32_t stop = invalid_index) {
  const std::size_t n = s.vertices.size();
  SurfaceDistances out{std::vector<double>(n, std::numeric_limits<double>::infinity()),
                       std::vector<std::uint32_t>(n, invalid_index)};
  using Item = std::pair<double, std::uint32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  for (auto v : from) {
    out.dist[v] = 0;
    queue.push({0.0, v});
  }
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > out.dist[v]) continue;
    if (v == stop) break;
    for (auto u : s.neighbors[v]) {
      const double du = d + cost(v, u);
      if (du < out.dist[u]) {
        out.dist[u] = du;
        out.prev[u] = v;
        queue.push({du, u});
      }
    }
  }
  return out;
}

// Shortest path from `from` to `to` over boundary edges, avoiding fixed vertices other than `to`
// (Dijkstra; ties broken by vertex id, so the result is deterministic). Empty when none exists.
// With `keep_apart`, a step onto a vertex next to a fixed one costs twice its length: a path then
// keeps off the paths already fixed where it can, and leaves free vertices between them through
// which the later paths still pass.
std::vector<std::uint32_t> shortest_path(const Surface& s, const std::vector<Vec3>& src, const std::vector<char>& fixed,
                                         std::uint32_t from, std::uint32_t to, bool keep_apart) {
  const auto next_to_fixed = [&](std::uint32_t u) {
    for (auto w : s.neighbors[u])
      if (fixed[w] && w != to && w != from) return true;
    return false;
  };
  const auto& adj = s.neighbors[from];
  if (std::binary_search(adj.begin(), adj.end(), to)) return {from, to};
  const auto cost = [&](std::uint32_t v, std::uint32_t u) {
    if (fixed[u] && u != to) return std::numeric_limits<double>::infinity();
    const double step = src.empty() ? 1.0 : norm(sub(src[u], src[v]));
    return keep_apart && next_to_fixed(u) ? 2 * step : step;
  };
  const std::vector<std::uint32_t> prev = surface_dijkstra(s, std::span(&from, 1), cost, to).prev;
  if (prev[to] == invalid_index) return {};
  std::vector<std::uint32_t> path{to};
  while (path.back() != from) path.push_back(prev[path.back()]);
  std::reverse(path.begin(), path.end());
  return path;
}

const std::array<Vec3, 4>& tet_corners() {
  static const std::array<Vec3, 4> corners{{
      {std::sqrt(8.0) / 3, 0.0, -1.0 / 3},
      {-std::sqrt(2.0) / 3, std::sqrt(2.0 / 3), -1.0 / 3},
      {-std::sqrt(2.0) / 3, -std::sqrt(2.0 / 3), -1.0 / 3},
      {0.0, 0.0, 1.0},
  }};
  return corners;
}

// Surface distances (Dijkstra, the source's edge lengths or unit lengths without a source) from
// the nearest of `from`.
std::vector<double> distances_from(const Surface& s, const std::vector<Vec3>& src,
                                   std::span<const std::uint32_t> from) {
  const auto length = [&](std::uint32_t v, std::uint32_t u) { return src.empty() ? 1.0 : norm(sub(src[u], src[v])); };
  return surface_dijkstra(s, from, length).dist;
}

// The vertex farthest from `from` among those with `allowed` set (all when empty; the lowest id
// among equals; unreachable ones are skipped).
std::uint32_t farthest_from(const Surface& s, const std::vector<Vec3>& src,
                            std::span<const std::uint32_t> from, const std::vector<char>& allowed = {}) {
  const auto dist = distances_from(s, src, from);
  std::uint32_t best = from[0];
  for (std::uint32_t v = 0; v < dist.size(); ++v)
    if ((allowed.empty() || allowed[v]) && std::isfinite(dist[v]) &&
        (best == from[0] || dist[v] > dist[best]))
      best = v;
  return best;
}

// The two ends of the surface's longest stretch found from a drawn start: {inner, outer} (which
// end is which is not known, so `swap_ends` swaps them).
std::array<std::uint32_t, 2> stretch_ends(const Surface& s, const std::vector<Vec3>& src, bool swap_ends,
                                          std::mt19937_64& rng) {
  const auto start = static_cast<std::uint32_t>(draw_below(rng, s.vertices.size()));
  std::array<std::uint32_t, 2> ends{};
  ends[1] = farthest_from(s, src, std::span(&start, 1));
  ends[0] = farthest_from(s, src, std::span(ends.data() + 1, 1));
  if (swap_ends) std::swap(ends[0], ends[1]);
  return ends;
}

// CornerChoice::farthest: from a drawn vertex, the vertex farthest from it and the one farthest
// from that: the two ends of the surface's longest stretch (the closed end of a tunnel or the tip
// of a protrusion, typically, and a point far from its mouth). One end becomes corner 0, from
// which three paths leave (fix_corner_paths), so that they run together down the stretch and
// space its vertices along three of the tetrahedron's edges instead of crowding it into a face;
// which end is the inner one is not known, so `swap_ends` swaps them. Corners 2 and 3 are taken
// far out of the stretch: among the vertices at least 3/4 as far from corner 0 as corner 1 is
// and, with a source, less than 3/2 as far from corner 1 over the surface as in space (a vertex
// in a tunnel is much farther over the surface), the farthest from corner 1 and then from 1 and
// 2 when `draw_rest` is false, drawn ones when it is true.
std::array<std::uint32_t, 4> farthest_corners(const Surface& s, const std::vector<Vec3>& src, bool swap_ends,
                                              bool draw_rest, std::mt19937_64& rng) {
  const auto ends = stretch_ends(s, src, swap_ends, rng);
  std::array<std::uint32_t, 4> c{ends[0], ends[1], 0, 0};
  const auto from0 = distances_from(s, src, std::span(c.data(), 1));
  const auto from1 = distances_from(s, src, std::span(c.data() + 1, 1));
  std::vector<char> far_out(from0.size(), 0);
  std::vector<std::uint32_t> candidates;
  for (std::uint32_t v = 0; v < from0.size(); ++v) {
    far_out[v] = std::isfinite(from0[v]) && from0[v] >= 0.75 * from0[c[1]] && v != c[1] &&
                 (src.empty() || from1[v] < 1.5 * norm(sub(src[v], src[c[1]])));
    if (far_out[v]) candidates.push_back(v);
  }
  if (candidates.size() < 2) return c;  // c[2] = c[3]: the caller draws instead
  if (draw_rest) {
    c[2] = candidates[draw_below(rng, candidates.size())];
    c[3] = candidates[draw_below(rng, candidates.size())];
  } else {
    c[2] = farthest_from(s, src, std::span(c.data() + 1, 1), far_out);
    c[3] = farthest_from(s, src, std::span(c.data() + 1, 2), far_out);
  }
  return c;
}

// stiff-tet with CornerChoice::farthest: corner 3, from which the three paths leave together, at
// the inner end of the longest stretch, and corners 0, 1, 2 on a boundary triangle at its outer
// end (the first one listed there).
std::array<std::uint32_t, 4> farthest_stiff_corners(const Surface& s, const std::vector<Vec3>& src, bool swap_ends,
                                                    std::mt19937_64& rng) {
  const auto ends = stretch_ends(s, src, swap_ends, rng);
  for (const auto& f : s.faces)
    if (std::find(f.begin(), f.end(), ends[1]) != f.end()) return {f[0], f[1], f[2], ends[0]};
  return {ends[0], ends[0], ends[0], ends[0]};  // not distinct: the caller draws instead
}

}  // namespace

// Four distinct corners (local ids) for attempt `rng`.
// CornerChoice::farthest alternates: farthest corners on even attempts (from different drawn
// starts, which often lead to the same corners; every other time with the ends swapped), drawn
// ones on odd attempts.
std::array<std::uint32_t, 4> choose_corners(const Surface& s, const std::vector<Vec3>& src,
                                            const BoundaryShapeSpec& spec, int attempt,
                                            std::mt19937_64& rng) {
  const BoundaryShape shape = spec.shape;
  if (spec.corners == CornerChoice::farthest && attempt % 2 == 0) {
    const auto c = shape == BoundaryShape::stiff_tet ? farthest_stiff_corners(s, src, attempt % 4 == 2, rng)
                                                     : farthest_corners(s, src, attempt % 4 == 2, attempt >= 4, rng);
    if (std::set<std::uint32_t>(c.begin(), c.end()).size() == 4) return c;
  }
  std::array<std::uint32_t, 4> c{};
  int chosen = 0;
  if (shape == BoundaryShape::stiff_tet) {
    const auto& f = s.faces[draw_below(rng, s.faces.size())];
    c = {f[0], f[1], f[2], 0};
    chosen = 3;
  }
  while (chosen < 4) {
    const auto v = static_cast<std::uint32_t>(draw_below(rng, s.vertices.size()));
    if (std::find(c.begin(), c.begin() + chosen, v) == c.begin() + chosen) c[std::size_t(chosen++)] = v;
  }
  return c;
}

namespace {

// Fixes the inner vertices of `path` (from corner `a` to corner `b`) on the tetrahedron's edge
// between them, evenly spaced.
void place_on_edge(const std::vector<std::uint32_t>& path, std::size_t a, std::size_t b, std::vector<char>& fixed,
                   std::vector<Vec3>& pos) {
  const auto& tet = tet_corners();
  const std::size_t m = path.size() - 2;  // inner vertices
  for (std::size_t k = 1; k <= m; ++k) {
    const double t = double(k) / double(m + 1);
    fixed[path[k]] = 1;
    for (std::size_t i = 0; i < 3; ++i) pos[path[k]][i] = (1 - t) * tet[a][i] + t * tet[b][i];
  }
}

// Farthest corners: the three paths from the hub corner (the inner end of a tunnel or protrusion:
// corner 0, or corner 3 for stiff-tet) together, as disjoint paths of least total length, which
// exist on every triangulated sphere; one after another, the first two shortest paths down a
// narrow tunnel can leave the third no way in.
std::string fix_paths_from_hub(const Surface& s, const std::vector<Vec3>& src, const std::array<std::uint32_t, 4>& corners,
                               std::size_t hub, std::vector<char>& fixed, std::vector<Vec3>& pos) {
  const auto length = [&](std::uint32_t u, std::uint32_t v) { return src.empty() ? 1.0 : norm(sub(src[u], src[v])); };
  const std::vector<char> none(s.vertices.size(), 0);
  std::array<std::size_t, 3> others{};
  std::array<std::uint32_t, 3> targets{};
  for (std::size_t j = 0, k = 0; j < 4; ++j)
    if (j != hub) {
      others[k] = j;
      targets[k++] = corners[j];
    }
  const auto paths = disjoint_paths(s.neighbors, length, corners[hub], targets, none);
  if (paths.empty()) return text("no three disjoint boundary paths from corner ", s.vertices[corners[hub]]);
  for (std::size_t k = 0; k < 3; ++k) place_on_edge(paths[k], hub, others[k], fixed, pos);
  return "";
}

}  // namespace

// Steps 1 and 2 of the construction: the corners go to the tetrahedron's corners, the paths
// between them to its edges; marks them fixed. "" or why it failed. Drawn corners: the paths
// one after another, 1-0, 2-0, 2-1, 3-0, 3-1, 3-2. Farthest corners (keep_apart): the three
// into the hub corner first (fix_paths_from_hub: corner 0, or 3 for stiff-tet), then the other
// three, each of which cuts a face off the disc that remains.
std::string fix_corner_paths(const Surface& s, const std::vector<Vec3>& src, const std::array<std::uint32_t, 4>& corners,
                             bool keep_apart, bool stiff, std::vector<char>& fixed, std::vector<Vec3>& pos) {
  const auto& tet = tet_corners();
  const std::size_t n = s.vertices.size();
  fixed.assign(n, 0);
  pos.assign(n, Vec3{0, 0, 0});
  for (std::size_t j = 0; j < 4; ++j) {
    fixed[corners[j]] = 1;
    pos[corners[j]] = tet[j];
  }
  using Pair = std::array<std::size_t, 2>;
  static constexpr std::array<Pair, 6> drawn_order{{{1, 0}, {2, 0}, {2, 1}, {3, 0}, {3, 1}, {3, 2}}};
  static constexpr std::array<Pair, 3> after_hub0{{{2, 1}, {3, 1}, {3, 2}}};
  static constexpr std::array<Pair, 3> after_hub3{{{1, 0}, {2, 0}, {2, 1}}};
  if (keep_apart) {
    if (auto why = fix_paths_from_hub(s, src, corners, stiff ? 3 : 0, fixed, pos); !why.empty()) return why;
  }
  const std::span<const Pair> order = !keep_apart ? std::span<const Pair>(drawn_order)
                                      : stiff     ? std::span<const Pair>(after_hub3)
                                                  : std::span<const Pair>(after_hub0);
  for (const auto& [j, i] : order) {
    const auto path = shortest_path(s, src, fixed, corners[j], corners[i], keep_apart);
    if (path.empty())
      return text("no free boundary path between corners ", s.vertices[corners[j]], " and ", s.vertices[corners[i]]);
    place_on_edge(path, j, i, fixed, pos);
  }
  return "";
}
}  // namespace cmx::generators::detail
