#include "lp/chebyshev_center.hpp"

#include <algorithm>
#include <cmath>

#include "lp/backend_registry.hpp"
#include "lp/float_simplex.hpp"

namespace cmx::lp {

std::string_view to_string(ChebyshevStatus s) {
  switch (s) {
    case ChebyshevStatus::interior:
      return "interior";
    case ChebyshevStatus::empty_interior:
      return "empty_interior";
    case ChebyshevStatus::infeasible:
      return "infeasible";
    case ChebyshevStatus::unbounded:
      return "unbounded";
  }
  return "?";
}

Problem chebyshev_problem(const std::vector<HalfSpace>& halfspaces, const ChebyshevOptions& options,
                          std::vector<std::size_t>* kept, bool* zero_row_infeasible) {
  Problem p(4);
  p.objective[3] = 1;
  p.matrix.reserve(4 * halfspaces.size());
  p.rhs.reserve(halfspaces.size());
  if (kept) kept->clear();
  if (zero_row_infeasible) *zero_row_infeasible = false;
  for (std::size_t i = 0; i < halfspaces.size(); ++i) {
    const HalfSpace& h = halfspaces[i];
    if (sgn(h.a) == 0 && sgn(h.b) == 0 && sgn(h.c) == 0) {
      if (sgn(h.d) < 0 && zero_row_infeasible) *zero_row_infeasible = true;
      continue;
    }
    p.matrix.push_back(h.a);
    p.matrix.push_back(h.b);
    p.matrix.push_back(h.c);
    p.matrix.push_back(row_weight(options.norm, h.a, h.b, h.c, options.weight_bits));
    p.rhs.push_back(h.d);
    if (kept) kept->push_back(i);
  }
  p.set_lower(3, Rational(0));
  return p;
}

ChebyshevResult chebyshev_center(const std::vector<HalfSpace>& halfspaces, const ChebyshevOptions& options) {
  const SolveFunction solve_fn = find_backend(options.backend);
  if (!solve_fn)
    throw std::invalid_argument("chebyshev_center: unknown LP backend '" + options.backend + "'");
  ChebyshevResult res;
  bool zero_infeasible = false;
  const Problem p = chebyshev_problem(halfspaces, options, nullptr, &zero_infeasible);
  if (zero_infeasible) {
    res.status = ChebyshevStatus::infeasible;
    res.lp.status = Status::infeasible;
    res.lp.info.backend = options.backend;
    return res;
  }
  res.lp = solve_fn(p);
  switch (res.lp.status) {
    case Status::infeasible:
      res.status = ChebyshevStatus::infeasible;
      return res;
    case Status::unbounded:
      res.status = ChebyshevStatus::unbounded;
      return res;
    case Status::optimal:
      break;
  }
  for (int k = 0; k < 3; ++k) res.center[std::size_t(k)] = res.lp.x[std::size_t(k)];
  res.radius = res.lp.x[3];
  res.status = sgn(res.radius) > 0 ? ChebyshevStatus::interior : ChebyshevStatus::empty_interior;
  return res;
}

FloatChebyshev float_chebyshev(const std::vector<std::array<double, 4>>& halfspaces) {
  // The FloatForm of chebyshev_problem directly: rows (a, b, c, w) . (x, y, z, r) <= d and the
  // bound -r <= 0, each scaled to a unit coefficient vector; objective r.
  FloatForm f;
  f.n = 4;
  auto add = [&](double a, double b, double c, double w, double d) {
    const double norm = std::sqrt(a * a + b * b + c * c + w * w);
    if (!(norm > 0) || !std::isfinite(norm) || !std::isfinite(d)) return false;
    f.ids.push_back(f.ids.size());
    for (double x : {a, b, c, w}) f.g.push_back(x / norm);
    f.h.push_back(d / norm);
    f.filterable.push_back(0);
    return true;
  };
  FloatChebyshev out;
  std::vector<std::size_t> input_row;  // form row -> input row
  for (std::size_t i = 0; i < halfspaces.size(); ++i) {
    const auto& h = halfspaces[i];
    const double w = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    if (w == 0) {
      if (h[3] < 0) return out;  // 0 <= d < 0: empty
      continue;
    }
    if (!add(h[0], h[1], h[2], w, h[3])) return out;
    input_row.push_back(i);
  }
  for (double h : f.h) out.scale = std::max(out.scale, std::fabs(h));
  add(0, 0, 0, -1, 0);
  f.c = {0, 0, 0, 1};
  const FloatResult r = float_simplex(f);
  if (r.kind != FloatResult::Kind::optimal) return out;
  out.optimal = true;
  out.radius = r.value;  // the objective is r itself (coefficient 1)
  for (std::size_t id : r.basis.tight)
    if (id < input_row.size()) out.tight_rows.push_back(input_row[id]);
  const std::vector<double> x = float_basic_point(f, r.basis);
  for (std::size_t k = 0; k < 3; ++k) out.centre[k] = x.empty() ? std::nan("") : x[k];
  return out;
}

namespace {

int worst_side(const std::vector<HalfSpace>& halfspaces, const std::array<Rational, 3>& p) {
  // Largest sign of a x + b y + c z - d. A zero row 0 <= d with d >= 0 is all of space, whose
  // interior is all of space: it counts as strictly satisfied.
  int worst = -1;
  Rational s;
  for (const HalfSpace& h : halfspaces) {
    if (sgn(h.a) == 0 && sgn(h.b) == 0 && sgn(h.c) == 0) {
      if (sgn(h.d) < 0) return 1;
      continue;
    }
    s = h.a * p[0] + h.b * p[1] + h.c * p[2] - h.d;
    const int v = sgn(s);
    if (v > worst) worst = v;
    if (worst > 0) break;
  }
  return worst;
}

}  // namespace

bool strictly_inside(const std::vector<HalfSpace>& halfspaces, const std::array<Rational, 3>& p) {
  return worst_side(halfspaces, p) < 0;
}

bool inside(const std::vector<HalfSpace>& halfspaces, const std::array<Rational, 3>& p) {
  return worst_side(halfspaces, p) <= 0;
}

}  // namespace cmx::lp
