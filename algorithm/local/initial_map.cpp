#include "algorithm/local/initial_map.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <array>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "algorithm/run_control.hpp"
#include "arith/rounding.hpp"

namespace cmx::algorithm {
namespace {

using Clock = std::chrono::steady_clock;
constexpr std::uint32_t not_interior = UINT32_MAX;

InitialMap failed(std::string why, Clock::time_point start) {
  InitialMap out;
  out.message = std::move(why);
  out.seconds = seconds_since(start);
  return out;
}

// Empty when the boundary lists are well formed: as long as each other, indices in range, none
// listed twice.
std::string boundary_list_error(const MapProblem& p) {
  const std::size_t n = p.source.size();
  if (p.boundary_vertices.size() != p.boundary_positions.size())
    return "the problem lists " + std::to_string(p.boundary_vertices.size()) + " boundary vertices but " +
           std::to_string(p.boundary_positions.size()) + " boundary positions";
  std::vector<char> seen(n, 0);
  for (std::size_t i = 0; i < p.boundary_vertices.size(); ++i) {
    const std::uint32_t v = p.boundary_vertices[i];
    if (v >= n)
      return "boundary vertex " + std::to_string(v) + " (entry " + std::to_string(i) + ") is beyond the " +
             std::to_string(n) + " vertices";
    if (seen[v]) return "boundary vertex " + std::to_string(v) + " is listed twice";
    seen[v] = 1;
  }
  return {};
}

std::string tet_index_error(const MapProblem& p) {
  const std::size_t n = p.source.size();
  for (std::size_t t = 0; t < p.tets.size(); ++t)
    for (std::uint32_t v : p.tets[t])
      if (v >= n)
        return "tet " + std::to_string(t) + " lists vertex " + std::to_string(v) + ", beyond the " +
               std::to_string(n) + " vertices";
  return {};
}

// The neighbours of every vertex through the tets' edges, each edge once per direction, sorted
// (compressed rows: the neighbours of v are neighbour[offset[v] .. offset[v + 1])).
struct EdgeAdjacency {
  std::vector<std::size_t> offset;
  std::vector<std::uint32_t> neighbour;
  std::span<const std::uint32_t> of(std::uint32_t v) const {
    return std::span<const std::uint32_t>(neighbour).subspan(offset[v], offset[v + 1] - offset[v]);
  }
};

EdgeAdjacency edge_adjacency(const std::vector<topology::Tet>& tets, std::size_t n) {
  std::vector<std::uint64_t> arcs;  // (from << 32) | to
  arcs.reserve(tets.size() * 12);
  for (const topology::Tet& t : tets)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        if (i != j && t[i] != t[j]) arcs.push_back((std::uint64_t{t[i]} << 32) | t[j]);
  std::sort(arcs.begin(), arcs.end());
  arcs.erase(std::unique(arcs.begin(), arcs.end()), arcs.end());
  EdgeAdjacency adj;
  adj.offset.assign(n + 1, 0);
  adj.neighbour.reserve(arcs.size());
  for (std::uint64_t a : arcs) {
    ++adj.offset[(a >> 32) + 1];
    adj.neighbour.push_back(static_cast<std::uint32_t>(a));
  }
  for (std::size_t v = 0; v < n; ++v) adj.offset[v + 1] += adj.offset[v];
  return adj;
}

// Empty when every non-boundary vertex has a path to a boundary vertex: then the system is
// irreducibly diagonally dominant with a positive diagonal, hence positive definite.
std::string unreachable_error(const EdgeAdjacency& adj, const std::vector<char>& boundary) {
  std::vector<char> reached(boundary);
  std::vector<std::uint32_t> queue;
  for (std::uint32_t v = 0; v < boundary.size(); ++v)
    if (boundary[v]) queue.push_back(v);
  for (std::size_t head = 0; head < queue.size(); ++head)
    for (std::uint32_t u : adj.of(queue[head]))
      if (!reached[u]) {
        reached[u] = 1;
        queue.push_back(u);
      }
  for (std::uint32_t v = 0; v < boundary.size(); ++v) {
    if (reached[v]) continue;
    if (adj.of(v).empty()) return "vertex " + std::to_string(v) + " is in no tet and not a boundary vertex";
    return "interior vertex " + std::to_string(v) + " has no path to a boundary vertex";
  }
  return {};
}

// The prescribed positions rounded to nearest doubles (zero for interior vertices); empty when
// one is beyond the doubles, `why` then names it.
std::vector<std::array<double, 3>> prescribed_doubles(const MapProblem& p, std::string& why) {
  std::vector<std::array<double, 3>> out(p.source.size(), {0.0, 0.0, 0.0});
  for (std::size_t i = 0; i < p.boundary_vertices.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const double x = to_double(p.boundary_positions[i][k]);
      if (!std::isfinite(x)) {
        why = "the prescribed position of boundary vertex " + std::to_string(p.boundary_vertices[i]) +
              " is beyond the doubles";
        return {};
      }
      out[p.boundary_vertices[i]][k] = x;
    }
  return out;
}

// Eigen's simplicial LDLT with the cost of its factorisation known before it runs: the symbolic
// analysis counts the nonzeros of every column of L (Eigen keeps the counts in a protected
// member, hence the subclass), and the factorisation costs about the sum of their squares in
// multiply-adds. The factorisation itself cannot be interrupted, so this is what decides whether
// it may run at all.
class CountedLDLT : public Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> {
 public:
  double factorisation_flops() const {
    double flops = 0;
    for (Eigen::Index j = 0; j < m_nonZerosPerCol.size(); ++j) {
      const double c = m_nonZerosPerCol[j];
      flops += c * c;
    }
    return flops;
  }
};

// The approximate solve of TutteScreen: conjugate gradients, column by column. False when a
// column does not reach the tolerance within the bound (then nothing is screened).
bool solve_approximately(const Eigen::SparseMatrix<double>& laplacian, const Eigen::MatrixX3d& rhs,
                         int max_iterations, Eigen::MatrixX3d& x) {
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg;
  cg.setTolerance(1e-10);
  cg.setMaxIterations(max_iterations);
  cg.compute(laplacian);
  x.resize(rhs.rows(), 3);
  for (int k = 0; k < 3; ++k) {
    x.col(k) = cg.solve(rhs.col(k));
    if (cg.info() != Eigen::Success || !x.col(k).allFinite()) return false;
  }
  return true;
}

// Sets the interior vertices of `map` (interior[r] is row r of `x`).
void set_interior(std::vector<std::array<double, 3>>& map, const std::vector<std::uint32_t>& interior,
                  const Eigen::MatrixX3d& x) {
  for (std::size_t r = 0; r < interior.size(); ++r)
    for (int k = 0; k < 3; ++k) map[interior[r]][k] = x(static_cast<Eigen::Index>(r), k);
}

// Solves the Laplacian system on the interior vertices (interior[r] is row r, slot its inverse)
// with one factorisation and three right-hand sides. False, with `why`, when the factorisation
// or the solve fails or a value is not finite, or when `screen` gives the map up (screened_out).
bool solve_laplacian(const EdgeAdjacency& adj, const std::vector<std::uint32_t>& interior,
                     const std::vector<std::uint32_t>& slot,
                     const std::vector<std::array<double, 3>>& prescribed, double max_flops,
                     const TutteScreen* screen, Eigen::MatrixX3d& x, std::string& why, bool& screened_out) {
  const auto m = static_cast<Eigen::Index>(interior.size());
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(adj.neighbour.size() + interior.size());
  Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Zero(m, 3);
  for (Eigen::Index r = 0; r < m; ++r) {
    const auto nbrs = adj.of(interior[static_cast<std::size_t>(r)]);
    entries.emplace_back(r, r, static_cast<double>(nbrs.size()));
    for (std::uint32_t u : nbrs) {
      if (slot[u] != not_interior) {
        entries.emplace_back(r, static_cast<Eigen::Index>(slot[u]), -1.0);
        continue;
      }
      for (int k = 0; k < 3; ++k) rhs(r, k) += prescribed[u][k];
    }
  }
  Eigen::SparseMatrix<double> laplacian(m, m);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  CountedLDLT solver;
  solver.analyzePattern(laplacian);
  const double flops = solver.factorisation_flops();
  if (flops > max_flops) {
    char text[160];
    std::snprintf(text, sizeof text, "about %.3g multiply-adds for %zu interior vertices, more than the %.3g allowed",
                  flops, interior.size(), max_flops);
    why = std::string("the Tutte system's sparse Cholesky factorisation would take ") + text;
    return false;
  }
  if (screen && screen->reject && flops > screen->above_flops &&
      solve_approximately(laplacian, rhs, screen->max_iterations, x)) {
    std::vector<std::array<double, 3>> approximate = prescribed;
    set_interior(approximate, interior, x);
    why = screen->reject(approximate);
    if (!why.empty()) {
      screened_out = true;
      return false;
    }
  }
  solver.factorize(laplacian);
  if (solver.info() != Eigen::Success) {
    why = "the sparse Cholesky factorisation of the Tutte system failed";
    return false;
  }
  x = solver.solve(rhs);
  if (solver.info() != Eigen::Success) {
    why = "the solve of the factorised Tutte system failed";
    return false;
  }
  for (Eigen::Index r = 0; r < m; ++r)
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(x(r, k))) {
        why = "the Tutte solution of interior vertex " +
              std::to_string(interior[static_cast<std::size_t>(r)]) + " is not finite";
        return false;
      }
  return true;
}

std::vector<char> boundary_flags(const MapProblem& p) {
  std::vector<char> flags(p.source.size(), 0);
  for (std::uint32_t v : p.boundary_vertices) flags[v] = 1;
  return flags;
}

}  // namespace

InitialMap tutte_map(const MapProblem& problem, bool exact, double max_flops, const TutteScreen* screen) {
  const Clock::time_point start = Clock::now();
  std::string why = boundary_list_error(problem);
  if (why.empty()) why = tet_index_error(problem);
  if (!why.empty()) return failed(why, start);
  const std::size_t n = problem.source.size();
  const std::vector<char> boundary = boundary_flags(problem);
  const EdgeAdjacency adj = edge_adjacency(problem.tets, n);
  why = unreachable_error(adj, boundary);
  if (!why.empty()) return failed(why, start);
  InitialMap out;
  out.doubles = prescribed_doubles(problem, why);
  if (!why.empty()) return failed(why, start);

  std::vector<std::uint32_t> interior, slot(n, not_interior);
  for (std::uint32_t v = 0; v < n; ++v)
    if (!boundary[v]) {
      slot[v] = static_cast<std::uint32_t>(interior.size());
      interior.push_back(v);
    }
  if (interior.size() > static_cast<std::size_t>(INT_MAX))
    return failed("too many interior vertices for the sparse solver: " + std::to_string(interior.size()),
                  start);
  Eigen::MatrixX3d x;
  bool screened_out = false;
  if (!interior.empty() &&
      !solve_laplacian(adj, interior, slot, out.doubles, max_flops, screen, x, why, screened_out)) {
    InitialMap f = failed(why, start);
    f.screened_out = screened_out;
    return f;
  }
  set_interior(out.doubles, interior, x);
  out.ok = true;
  out.interior = interior.size();
  if (exact) exact_target(problem, out);
  out.seconds = seconds_since(start);
  return out;
}

void exact_target(const MapProblem& problem, InitialMap& m) {
  const std::vector<char> boundary = boundary_flags(problem);
  m.target.assign(m.doubles.size(), Point3{});
  for (std::size_t i = 0; i < problem.boundary_vertices.size(); ++i)
    m.target[problem.boundary_vertices[i]] = problem.boundary_positions[i];
  for (std::size_t v = 0; v < m.doubles.size(); ++v)
    if (!boundary[v])
      for (int k = 0; k < 3; ++k) m.target[v][k] = rational_from_double(m.doubles[v][k]);
}

InitialMap given_map(const MapProblem& problem, std::vector<Point3> positions) {
  const Clock::time_point start = Clock::now();
  const std::size_t n = problem.source.size();
  if (positions.size() != n)
    return failed("the initial map has " + std::to_string(positions.size()) + " positions, the problem has " +
                      std::to_string(n) + " vertices",
                  start);
  if (std::string why = boundary_list_error(problem); !why.empty()) return failed(why, start);
  std::size_t reset = 0;
  std::uint32_t first = 0;
  for (std::size_t i = 0; i < problem.boundary_vertices.size(); ++i) {
    const std::uint32_t v = problem.boundary_vertices[i];
    if (positions[v] == problem.boundary_positions[i]) continue;
    if (reset++ == 0) first = v;
    positions[v] = problem.boundary_positions[i];
  }
  InitialMap out;
  out.ok = true;
  out.target = std::move(positions);
  out.interior = n - problem.boundary_vertices.size();
  if (reset > 0)
    out.message =
        "note: " + std::to_string(reset) +
        " boundary vertices of the initial map were not at their prescribed positions and were set to "
        "them (first: vertex " +
        std::to_string(first) + ")";
  out.seconds = seconds_since(start);
  return out;
}

}  // namespace cmx::algorithm
