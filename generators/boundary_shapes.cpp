#include "generators/boundary_shapes.hpp"

#include <algorithm>
#include <charconv>
#include <concepts>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <queue>
#include <random>
#include <set>
#include <span>
#include <string_view>
#include <utility>

#include "generators/disjoint_paths.hpp"
#include "kernel/orient.hpp"
#include "topology/complex_queries.hpp"

namespace cmx::generators {
namespace {

using topology::invalid_index;
using Vec3 = std::array<double, 3>;

constexpr std::uint64_t default_seed = BoundaryShapeSpec{}.seed;

constexpr std::array<std::pair<BoundaryShape, std::string_view>, 4> shape_names{{
    {BoundaryShape::tet, "tet"},
    {BoundaryShape::stiff_tet, "stiff-tet"},
    {BoundaryShape::sphere, "sphere"},
    {BoundaryShape::star, "star"},
}};

// ---- small vector helpers -------------------------------------------------------------------

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 scaled(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
bool finite(const Vec3& a) { return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]); }

// Message text from pieces (strings and integers); avoids "literal" + std::string, on which g++ 12
// emits a false -Wrestrict warning.
void append_part(std::string& out, std::string_view part) { out += part; }
template <std::integral T>
void append_part(std::string& out, T number) {
  out += std::to_string(number);
}
template <class Tag>
void append_part(std::string& out, topology::Handle<Tag> handle) {
  out += std::to_string(handle.idx());
}
template <class... Parts>
std::string text(const Parts&... parts) {
  std::string out;
  (append_part(out, parts), ...);
  return out;
}

std::string face_text(const topology::Triangle& f) { return text("(", f[0], ", ", f[1], ", ", f[2], ")"); }

// ---- seeded choices, identical on every platform -------------------------------------------

// SplitMix64's finaliser: spreads a seed and a counter over all 64 bits.
std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// Uniform on [0, n), n >= 1, by rejection (std::uniform_int_distribution is not specified
// bit for bit, this is): accept r >= 2^64 mod n, so that r mod n is unbiased.
std::uint64_t draw_below(std::mt19937_64& rng, std::uint64_t n) {
  const std::uint64_t reject_below = (0 - n) % n;
  for (;;) {
    const std::uint64_t r = rng();
    if (r >= reject_below) return r % n;
  }
}

// ---- the boundary surface, in local numbering ----------------------------------------------

struct Surface {
  std::vector<std::uint32_t> vertices;                  // global ids, ascending
  std::vector<std::uint32_t> local;                     // global id -> local id, or invalid_index
  std::vector<topology::Triangle> faces;                // local ids, outward
  std::vector<std::vector<std::uint32_t>> neighbors;    // local adjacency over boundary edges, ascending
};

// Builds the surface; returns "" or why the boundary is not a closed, consistently oriented surface.
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
  const std::size_t n = s.vertices.size();
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<std::uint32_t> prev(n, invalid_index);
  using Item = std::pair<double, std::uint32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  dist[from] = 0;
  queue.push({0.0, from});
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > dist[v]) continue;
    if (v == to) break;
    for (auto u : s.neighbors[v]) {
      if (fixed[u] && u != to) continue;
      const double step = src.empty() ? 1.0 : norm(sub(src[u], src[v]));
      const double du = d + (keep_apart && next_to_fixed(u) ? 2 * step : step);
      if (du < dist[u]) {
        dist[u] = du;
        prev[u] = v;
        queue.push({du, u});
      }
    }
  }
  if (prev[to] == invalid_index) return {};
  std::vector<std::uint32_t> path{to};
  while (path.back() != from) path.push_back(prev[path.back()]);
  std::reverse(path.begin(), path.end());
  return path;
}

// ---- Tutte embedding of the free vertices ----------------------------------------------------

// Edge weights of the Tutte system, aligned with Surface::neighbors (weight[v][k] belongs to the
// edge from v to neighbors[v][k]; symmetric: the same value is stored at both ends).
using EdgeWeights = std::vector<std::vector<double>>;

EdgeWeights uniform_weights(const Surface& s) {
  EdgeWeights w(s.neighbors.size());
  for (std::size_t v = 0; v < w.size(); ++v) w[v].assign(s.neighbors[v].size(), 1.0);
  return w;
}

// Solves the weighted Laplacian system of one connected group of free vertices,
//   (sum_u w_vu) x_v - sum_{free u ~ v} w_vu x_u = sum_{fixed u ~ v} w_vu p_u,
// for the three coordinates, by conjugate gradients with the Jacobi preconditioner. The matrix is
// symmetric positive definite because the weights are symmetric and positive and the group
// touches a fixed vertex.
void solve_tutte_group(const Surface& s, const EdgeWeights& weight, bool uniform, const std::vector<std::uint32_t>& group,
                       const std::vector<std::uint32_t>& slot, const std::vector<char>& fixed, std::vector<Vec3>& pos) {
  const std::size_t n = group.size();
  std::vector<double> diag(n), b(n), x(n), r(n), z(n), p(n), ap(n);
  const auto apply = [&](const std::vector<double>& in, std::vector<double>& out) {
    for (std::size_t i = 0; i < n; ++i) {
      double sum = diag[i] * in[i];
      const auto& adj = s.neighbors[group[i]];
      for (std::size_t k = 0; k < adj.size(); ++k)
        if (!fixed[adj[k]]) sum -= weight[group[i]][k] * in[slot[adj[k]]];
      out[i] = sum;
    }
  };
  const auto inner = [&](const std::vector<double>& a, const std::vector<double>& c) {
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) sum += a[i] * c[i];
    return sum;
  };
  for (std::size_t i = 0; i < n; ++i) {
    diag[i] = 0;
    for (double w : weight[group[i]]) diag[i] += w;
  }
  const std::size_t max_iterations = 10 * n + 100;
  for (int axis = 0; axis < 3; ++axis) {
    for (std::size_t i = 0; i < n; ++i) {
      double sum = 0;
      const auto& adj = s.neighbors[group[i]];
      for (std::size_t k = 0; k < adj.size(); ++k)
        if (fixed[adj[k]]) sum += weight[group[i]][k] * pos[adj[k]][std::size_t(axis)];
      b[i] = sum;
      x[i] = sum / diag[i];  // start: the fixed neighbours' contribution alone
    }
    apply(x, ap);
    for (std::size_t i = 0; i < n; ++i) r[i] = b[i] - ap[i];
    // Uniform weights: converged at a residual 1e-15 of the right-hand side's. Spread weights
    // span many orders of magnitude, so that criterion would ignore the rows of small weight:
    // converged when every vertex is within 1e-16 (of the fixed positions' scale) of its
    // neighbours' weighted mean, the residual scaled row by row.
    double scale = 0;
    for (std::size_t i = 0; i < n; ++i) scale = std::max(scale, std::abs(b[i] / diag[i]));
    const double tolerance = uniform ? 1e-15 * std::max(std::sqrt(inner(b, b)), 1e-300) : 1e-16 * std::max(scale, 1e-300);
    const auto scaled_residual = [&] {
      if (uniform) return std::sqrt(inner(r, r));
      double worst = 0;
      for (std::size_t i = 0; i < n; ++i) worst = std::max(worst, std::abs(r[i] / diag[i]));
      return worst;
    };
    for (std::size_t i = 0; i < n; ++i) p[i] = z[i] = r[i] / diag[i];
    double rz = inner(r, z);
    for (std::size_t it = 0; it < max_iterations && scaled_residual() > tolerance; ++it) {
      apply(p, ap);
      const double pap = inner(p, ap);
      if (!(pap > 0)) break;
      const double alpha = rz / pap;
      for (std::size_t i = 0; i < n; ++i) {
        x[i] += alpha * p[i];
        r[i] -= alpha * ap[i];
        z[i] = r[i] / diag[i];
      }
      const double rz_next = inner(r, z);
      const double beta = rz_next / rz;
      rz = rz_next;
      for (std::size_t i = 0; i < n; ++i) p[i] = z[i] + beta * p[i];
    }
    for (std::size_t i = 0; i < n; ++i) pos[group[i]][std::size_t(axis)] = x[i];
  }
}

// Places every free vertex by a Tutte embedding with the given weights; false when a group of
// free vertices touches no fixed vertex (cannot happen on a connected surface with a fixed vertex).
bool place_free_vertices(const Surface& s, const EdgeWeights& weight, bool uniform, const std::vector<char>& fixed,
                         std::vector<Vec3>& pos) {
  const std::size_t n = s.vertices.size();
  std::vector<std::uint32_t> slot(n, invalid_index);
  std::vector<std::uint32_t> group;
  for (std::uint32_t start = 0; start < n; ++start) {
    if (fixed[start] || slot[start] != invalid_index) continue;
    // Breadth-first over free-free edges: one group, numbered in discovery order.
    group.assign(1, start);
    slot[start] = 0;
    bool touches_fixed = false;
    for (std::size_t head = 0; head < group.size(); ++head)
      for (auto u : s.neighbors[group[head]]) {
        if (fixed[u]) touches_fixed = true;
        else if (slot[u] == invalid_index) {
          slot[u] = static_cast<std::uint32_t>(group.size());
          group.push_back(u);
        }
      }
    if (!touches_fixed) return false;
    solve_tutte_group(s, weight, uniform, group, slot, fixed, pos);
  }
  return true;
}

// ---- spreading: weights that undo the Tutte map's crowding ------------------------------------

// Squared L2 stretch (Sander et al. 2001) of the linear map from the embedded triangle `to` back to
// the source triangle `from`: half the squared Frobenius norm of its Jacobian. Large where the
// embedding crowds the source; infinite for a flat embedded triangle.
double squared_stretch(const std::array<Vec3, 3>& from, const std::array<Vec3, 3>& to, double outward) {
  const Vec3 e1 = sub(to[1], to[0]), e2 = sub(to[2], to[0]);
  const Vec3 n = cross(e1, e2);
  const double twice_area = norm(n);
  const double len1 = norm(e1);
  // Flat or turned over (its normal against the surface's orientation, about the origin): crowded
  // beyond what doubles resolve.
  if (!(twice_area > 0) || !(len1 > 0) || !(outward * dot(n, to[0]) > 0)) return std::numeric_limits<double>::infinity();
  // Orthonormal frame of the embedded triangle's plane: u along e1, w = n x u / |n|.
  const Vec3 u = scaled(e1, 1.0 / len1), w = scaled(cross(n, u), 1.0 / twice_area);
  // P = [[p1x, p2x], [p1y, p2y]] (the edge vectors in the frame), J = Q P^-1 with Q the source edges.
  const double p1x = len1, p1y = 0, p2x = dot(e2, u), p2y = dot(e2, w);
  const double det = p1x * p2y - p2x * p1y;
  const Vec3 q1 = sub(from[1], from[0]), q2 = sub(from[2], from[0]);
  // Columns of J: Q times the columns of P^-1 = (1/det) [[p2y, -p2x], [-p1y, p1x]].
  const Vec3 c1 = scaled(sub(scaled(q1, p2y), scaled(q2, p1y)), 1.0 / det);
  const Vec3 c2 = scaled(sub(scaled(q2, p1x), scaled(q1, p2x)), 1.0 / det);
  return 0.5 * (dot(c1, c1) + dot(c2, c2));
}

// One step of Yoshizawa, Belyaev and Seidel's stretch minimisation (2004): each vertex's stretch
// sigma_v is the source-area-weighted mean of its faces' squared stretches (square root), and every
// edge weight is divided by sigma_a sigma_b, i.e. by sigma of the other end in each vertex's
// averaging equation (the symmetric form of their update, so that the system stays symmetric):
// a crowded region pulls its neighbours less and so spreads. Each
// step's factors are clamped to within 10^3 of the median so that one step cannot make the system
// singular in doubles. Returns the worst vertex stretch over the median (before clamping), or 0
// when no face has a finite stretch (the weights are then unchanged).
double spread_weights(const Surface& s, const std::vector<Vec3>& src, const std::vector<Vec3>& pos, EdgeWeights& weight) {
  const std::size_t n = s.vertices.size();
  double volume = 0;
  for (const auto& f : s.faces) volume += dot(pos[f[0]], cross(pos[f[1]], pos[f[2]]));
  const double outward = volume < 0 ? -1.0 : 1.0;
  std::vector<double> sum(n, 0.0), area(n, 0.0);
  for (const auto& f : s.faces) {
    // Without a source geometry every face stands for the same equilateral triangle.
    const std::array<Vec3, 3> from = src.empty() ? std::array<Vec3, 3>{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0.5, std::sqrt(0.75), 0}}
                                                 : std::array<Vec3, 3>{src[f[0].idx()], src[f[1].idx()], src[f[2].idx()]};
    const std::array<Vec3, 3> to{pos[f[0].idx()], pos[f[1].idx()], pos[f[2].idx()]};
    const double a = 0.5 * norm(cross(sub(from[1], from[0]), sub(from[2], from[0])));
    const double st = std::min(squared_stretch(from, to, outward), std::numeric_limits<double>::max());
    for (auto v : f) {
      sum[v.idx()] += a * st;
      area[v.idx()] += a;
    }
  }
  std::vector<double> sigma(n, 0.0);
  for (std::size_t v = 0; v < n; ++v) sigma[v] = area[v] > 0 ? std::sqrt(sum[v] / area[v]) : 0.0;
  std::vector<double> sorted;
  for (double x : sigma)
    if (std::isfinite(x) && x > 0) sorted.push_back(x);
  if (sorted.empty()) return 0;
  std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2), sorted.end());
  const double median = sorted[sorted.size() / 2];
  const double worst = *std::max_element(sorted.begin(), sorted.end()) / median;
  for (auto& x : sigma) x = std::clamp(std::isfinite(x) ? x : median * 1e3, median * 1e-3, median * 1e3) / median;
  for (std::size_t v = 0; v < n; ++v)
    for (std::size_t k = 0; k < s.neighbors[v].size(); ++k)
      weight[v][k] /= sigma[v] * sigma[s.neighbors[v][k]];
  return worst;
}

// ---- one attempt -----------------------------------------------------------------------------

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
  std::vector<double> dist(s.vertices.size(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, std::uint32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  for (auto v : from) {
    dist[v] = 0;
    queue.push({0.0, v});
  }
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > dist[v]) continue;
    for (auto u : s.neighbors[v]) {
      const double du = d + (src.empty() ? 1.0 : norm(sub(src[u], src[v])));
      if (du < dist[u]) {
        dist[u] = du;
        queue.push({du, u});
      }
    }
  }
  return dist;
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

// Inside-out (the corners' cyclic order is the mirror image)? Reflect y -> -y: exact, and it
// maps the tetrahedron onto itself.
void orient_outward(const Surface& s, std::vector<Vec3>& pos) {
  double volume = 0;
  for (const auto& f : s.faces) volume += dot(pos[f[0]], cross(pos[f[1]], pos[f[2]]));
  if (volume < 0)
    for (auto& p : pos) p[1] = -p[1];
}

void apply_shape(const BoundaryShapeSpec& spec, std::vector<Vec3>& pos) {
  if (spec.shape == BoundaryShape::tet || spec.shape == BoundaryShape::stiff_tet) return;
  for (auto& p : pos) p = scaled(p, 1.0 / norm(p));
  if (spec.shape != BoundaryShape::star) return;
  std::mt19937_64 rng(mix(spec.seed ^ 0x5354415253484150ull));  // "STARSHAP": a stream apart from the corners'
  for (auto& p : pos) {
    const double factor = 1.0 + 9.0 * double(draw_below(rng, std::uint64_t{1} << 20)) * 0x1p-20;
    p = scaled(p, factor);
  }
}

// Steps 3 to 6 for fixed corners and paths: the Tutte embedding, then up to spec.spread
// reweighted ones, each oriented, shaped and checked; g.positions gets the last valid one. The
// steps stop early once the worst vertex stretch is within spread_enough of the median (spread
// enough), or at the first invalid step after a valid one (the weights have begun to span more
// than the solver resolves). "" or why the plain embedding failed (when no step was valid).
std::string place_and_check(const topology::TetMesh& mesh, const Surface& s, const std::vector<Vec3>& src,
                            const std::vector<char>& fixed, const BoundaryShapeSpec& spec, std::vector<Vec3>& pos,
                            GeneratedBoundary& g) {
  constexpr double spread_enough = 20;
  EdgeWeights weight = uniform_weights(s);
  std::vector<Vec3> best;
  std::string first_failure;
  for (int step = 0; step <= spec.spread; ++step) {
    if (step > 0) {
      const double worst = spread_weights(s, src, pos, weight);
      if (worst == 0 || (!best.empty() && worst < spread_enough)) break;
    }
    if (!place_free_vertices(s, weight, step == 0, fixed, pos)) return "a group of free boundary vertices touches no path";
    g.positions = pos;
    orient_outward(s, g.positions);
    apply_shape(spec, g.positions);
    std::string why = check_star_shaped_about_origin(mesh, g);
    if (why.empty())
      best = g.positions;
    else if (!best.empty())
      break;
    else if (step == 0)
      first_failure = std::move(why);
  }
  if (best.empty()) return first_failure;
  g.positions = std::move(best);
  return "";
}

GeneratedBoundary failure(std::string message, int attempts = 0) {
  GeneratedBoundary g;
  g.message = std::move(message);
  g.attempts = attempts;
  return g;
}

}  // namespace

const char* shape_name(BoundaryShape shape) {
  for (const auto& [s, name] : shape_names)
    if (s == shape) return name.data();
  return "?";
}

std::optional<CornerChoice> parse_corner_choice(std::string_view text) {
  if (text == "random") return CornerChoice::random;
  if (text == "farthest") return CornerChoice::farthest;
  return std::nullopt;
}

std::optional<BoundaryShapeSpec> parse_boundary_shape(std::string_view text) {
  const auto colon = text.find(':');
  const std::string_view name = text.substr(0, colon);
  BoundaryShapeSpec spec;
  bool known = false;
  for (const auto& [s, n] : shape_names)
    if (n == name) spec.shape = s, known = true;
  if (!known) return std::nullopt;
  if (colon == std::string_view::npos) return spec;
  const std::string_view digits = text.substr(colon + 1);
  if (digits.empty() || digits.find_first_not_of("0123456789") != std::string_view::npos) return std::nullopt;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), spec.seed);
  if (ec != std::errc() || end != digits.data() + digits.size()) return std::nullopt;
  return spec;
}

std::string to_string(const BoundaryShapeSpec& spec) {
  std::string name = shape_name(spec.shape);
  if (spec.shape == BoundaryShape::star || spec.seed != default_seed) name += text(":", spec.seed);
  return name;
}

GeneratedBoundary generate_boundary(const topology::TetMesh& mesh, const std::vector<Vec3>& source,
                                    const BoundaryShapeSpec& spec) {
  if (!source.empty() && source.size() != mesh.num_vertices())
    return failure(text("the mesh has ", mesh.num_vertices(), " vertices but ", source.size(), " source positions were given"));
  for (std::size_t v = 0; v < source.size(); ++v)
    if (!finite(source[v])) return failure(text("source position of vertex ", v, " is not finite"));
  Surface s;
  if (auto why = build_surface(mesh, s); !why.empty()) return failure(why);
  if (s.vertices.size() < 4)
    return failure(text("the boundary has ", s.vertices.size(), " vertices; at least 4 are needed"));
  std::vector<Vec3> src(source.empty() ? 0 : s.vertices.size());  // empty: no geometry
  for (std::size_t i = 0; i < src.size(); ++i) src[i] = source[s.vertices[i]];

  GeneratedBoundary g;
  g.vertices = s.vertices;
  std::string first_failure, last_failure;
  for (int attempt = 0; attempt < max_boundary_attempts; ++attempt) {
    std::mt19937_64 rng(mix(spec.seed + 0x9E3779B97F4A7C15ull * std::uint64_t(attempt + 1)));
    const auto corners = choose_corners(s, src, spec, attempt, rng);
    std::vector<char> fixed;
    std::vector<Vec3> pos;
    const bool keep_apart = spec.corners == CornerChoice::farthest;
    std::string why = fix_corner_paths(s, src, corners, keep_apart, spec.shape == BoundaryShape::stiff_tet, fixed, pos);
    if (why.empty()) why = place_and_check(mesh, s, src, fixed, spec, pos, g);
    g.attempts = attempt + 1;
    if (why.empty()) {
      g.ok = true;
      return g;
    }
    if (first_failure.empty()) first_failure = why;
    last_failure = std::move(why);
  }
  return failure(text("no valid ", shape_name(spec.shape), " boundary in ", max_boundary_attempts,
                      " attempts (first failure: ", first_failure, "; last failure: ", last_failure, ")"),
                 max_boundary_attempts);
}

std::string check_star_shaped_about_origin(const topology::TetMesh& mesh, const GeneratedBoundary& boundary) {
  if (boundary.positions.size() != boundary.vertices.size())
    return text(boundary.vertices.size(), " vertices but ", boundary.positions.size(), " positions");
  std::vector<std::uint32_t> slot(mesh.num_vertices(), invalid_index);
  for (std::size_t i = 0; i < boundary.vertices.size(); ++i) {
    const auto v = boundary.vertices[i];
    if (v >= mesh.num_vertices()) return text("vertex ", v, " is not a vertex of the mesh");
    if (slot[v] != invalid_index) return text("vertex ", v, " is listed twice");
    if (!finite(boundary.positions[i])) return text("the position of vertex ", v, " is not finite");
    slot[v] = static_cast<std::uint32_t>(i);
  }
  const auto faces = topology::boundary_faces(mesh);
  std::vector<char> on_boundary(mesh.num_vertices(), 0);
  for (const auto& f : faces)
    for (auto v : f.face) {
      if (slot[v] == invalid_index) return text("boundary vertex ", v, " has no position");
      on_boundary[v] = 1;
    }
  for (auto v : boundary.vertices)
    if (!on_boundary[v]) return text("vertex ", v, " is not a boundary vertex");
  const double origin[3] = {0, 0, 0};
  for (const auto& f : faces) {
    const auto& a = boundary.positions[slot[f.face[0]]];
    const auto& b = boundary.positions[slot[f.face[1]]];
    const auto& c = boundary.positions[slot[f.face[2]]];
    const Sign s = orient3d(a.data(), b.data(), c.data(), origin, PredicateContext::certain());
    if (s == Sign::zero)
      return text("boundary face ", face_text(f.face), " is degenerate or its plane contains the origin");
    if (s == Sign::positive) return text("boundary face ", face_text(f.face), " does not see the origin on its inner side");
  }
  // Winding around each vertex's ray: the angles at v of the centrally projected faces, each in
  // (0, pi) now that every face is positively oriented, sum to 2*pi*k; star-shaped means k = 1.
  std::vector<double> angle(mesh.num_vertices(), 0.0);
  for (const auto& f : faces)
    for (int i = 0; i < 3; ++i) {
      const auto v = f.face[std::size_t(i)];
      const Vec3& p = boundary.positions[slot[v]];
      const Vec3 axis = scaled(p, 1.0 / norm(p));
      const Vec3& u = boundary.positions[slot[f.face[std::size_t((i + 1) % 3)]]];
      const Vec3& w = boundary.positions[slot[f.face[std::size_t((i + 2) % 3)]]];
      const Vec3 tu = sub(u, scaled(axis, dot(u, axis))), tw = sub(w, scaled(axis, dot(w, axis)));
      angle[v] += std::atan2(dot(cross(tu, tw), axis), dot(tu, tw));
    }
  for (auto v : boundary.vertices) {
    const double turns = std::round(angle[v] / (2 * std::numbers::pi));
    if (turns != 1)
      return text("the boundary faces around vertex ", v, " wind ", long(turns), " times around its ray from the origin");
  }
  return "";
}

}  // namespace cmx::generators
