#include "generators/boundary_shapes.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string_view>
#include <utility>

#include "generators/boundary_corners.hpp"
#include "generators/boundary_surface.hpp"
#include "kernel/orient.hpp"
#include "topology/complex_queries.hpp"
#include "topology/indexed_tasks.hpp"

// The placement and the checks; the surface and its helpers are in generators/boundary_surface.hpp,
// the corners and the paths between them in generators/boundary_corners.hpp.
namespace cmx::generators::detail {
namespace {

using topology::invalid_index;

constexpr std::uint64_t default_seed = BoundaryShapeSpec{}.seed;

constexpr std::array<std::pair<BoundaryShape, std::string_view>, 4> shape_names{{
    {BoundaryShape::tet, "tet"},
    {BoundaryShape::stiff_tet, "stiff-tet"},
    {BoundaryShape::sphere, "sphere"},
    {BoundaryShape::star, "star"},
}};

std::string face_text(const topology::Triangle& f) { return text("(", f[0], ", ", f[1], ", ", f[2], ")"); }

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
// touches a fixed vertex. False when some coordinate stopped at the iteration bound short of the
// tolerance (or on a direction of no descent): the weights then span more than conjugate
// gradients in doubles resolve, and the positions are whatever the last iterate was.
bool solve_tutte_group(const Surface& s, const EdgeWeights& weight, bool uniform,
                       const std::vector<std::uint32_t>& group, const std::vector<std::uint32_t>& slot,
                       const std::vector<char>& fixed, std::vector<Vec3>& pos) {
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
  bool converged = true;
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
    if (!(scaled_residual() <= tolerance)) converged = false;
    for (std::size_t i = 0; i < n; ++i) pos[group[i]][std::size_t(axis)] = x[i];
  }
  return converged;
}

enum class Placement {
  solved,
  unresolved,     // some group's solve stopped short of its tolerance (solve_tutte_group)
  group_unfixed,  // a group of free vertices touches no fixed vertex
};

// Places every free vertex by a Tutte embedding with the given weights. A group that touches no
// fixed vertex cannot happen on a connected surface with a fixed vertex.
Placement place_free_vertices(const Surface& s, const EdgeWeights& weight, bool uniform,
                              const std::vector<char>& fixed, std::vector<Vec3>& pos) {
  const std::size_t n = s.vertices.size();
  std::vector<std::uint32_t> slot(n, invalid_index);
  std::vector<std::uint32_t> group;
  Placement result = Placement::solved;
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
    if (!touches_fixed) return Placement::group_unfixed;
    if (!solve_tutte_group(s, weight, uniform, group, slot, fixed, pos)) result = Placement::unresolved;
  }
  return result;
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
// enough), at the first invalid step after a valid one, or after a reweighted step whose solve
// did not converge (in both cases the weights have begun to span more than the solver resolves,
// and later steps only compound them; the plain embedding's uniform weights are not the cause
// when its solve stops short, so spreading goes on after it; a solve at its iteration bound
// costs 10n iterations, so without this stop a hopeless attempt ran all its steps at that cost).
// "" or why the plain embedding failed (when no step was valid).
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
    const Placement placed = place_free_vertices(s, weight, step == 0, fixed, pos);
    if (placed == Placement::group_unfixed) return "a group of free boundary vertices touches no path";
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
    if (step > 0 && placed == Placement::unresolved) break;
  }
  if (best.empty()) return first_failure;
  g.positions = std::move(best);
  return "";
}

// One attempt: corners drawn from the attempt's own stream, the paths between them, then the
// embedding and its checks. "" with g.positions set, or why the attempt failed.
std::string attempt(const topology::TetMesh& mesh, const Surface& s, const std::vector<Vec3>& src,
                    const BoundaryShapeSpec& spec, int index, GeneratedBoundary& g) {
  std::mt19937_64 rng(mix(spec.seed + 0x9E3779B97F4A7C15ull * std::uint64_t(index + 1)));
  const auto corners = choose_corners(s, src, spec, index, rng);
  std::vector<char> fixed;
  std::vector<Vec3> pos;
  const bool keep_apart = spec.corners == CornerChoice::farthest;
  std::string why =
      fix_corner_paths(s, src, corners, keep_apart, spec.shape == BoundaryShape::stiff_tet, fixed, pos);
  if (why.empty()) why = place_and_check(mesh, s, src, fixed, spec, pos, g);
  return why;
}

GeneratedBoundary failure(std::string message, int attempts = 0) {
  GeneratedBoundary g;
  g.message = std::move(message);
  g.attempts = attempts;
  return g;
}

}  // namespace
}  // namespace cmx::generators::detail

namespace cmx::generators {

const char* shape_name(BoundaryShape shape) {
  using namespace detail;
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
  using namespace detail;
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
  using namespace detail;
  std::string name = shape_name(spec.shape);
  if (spec.shape == BoundaryShape::star || spec.seed != default_seed) name += text(":", spec.seed);
  return name;
}

GeneratedBoundary generate_boundary(const topology::TetMesh& mesh, const std::vector<std::array<double, 3>>& source,
                                    const BoundaryShapeSpec& spec) {
  using namespace detail;
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

  // The result is the earliest attempt that succeeds, all earlier ones having failed, whatever
  // the thread count (topology::run_indexed hands them out in order and starts none past it).
  std::vector<GeneratedBoundary> results(static_cast<std::size_t>(max_boundary_attempts));
  std::vector<std::string> why(results.size());
  const std::size_t first = topology::run_indexed(
      results.size(), topology::thread_count(spec.threads, results.size()), [&](std::size_t k) {
        GeneratedBoundary& g = results[k];
        g.vertices = s.vertices;
        why[k] = attempt(mesh, s, src, spec, int(k), g);
        if (!why[k].empty()) g = GeneratedBoundary{};  // a failed attempt keeps only its message
        return why[k].empty();
      });
  if (first < results.size()) {
    GeneratedBoundary& g = results[first];
    g.attempts = int(first) + 1;
    g.ok = true;
    return std::move(g);
  }
  return failure(text("no valid ", shape_name(spec.shape), " boundary in ", max_boundary_attempts,
                      " attempts (first failure: ", why.front(), "; last failure: ", why.back(), ")"),
                 max_boundary_attempts);
}

std::string check_star_shaped_about_origin(const topology::TetMesh& mesh, const GeneratedBoundary& boundary) {
  using namespace detail;
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
