#include "lp/float_simplex.hpp"

#include <gmp.h>

#include <algorithm>
#include <cmath>

#include "lp/simplex_engine.hpp"

namespace cmx::lp {
namespace {

// Approximate arithmetic: tolerances relative to the unit scale of normalised rows.
struct DoubleField {
  using value_type = double;
  static constexpr double tol = 1e-9;
  static double one() { return 1.0; }
  static double zero() { return 0.0; }
  static double unit() { return 1.0; }
  static int sgn(double x) { return x > tol ? 1 : x < -tol ? -1 : 0; }
  int sign_coef(double x) const { return sgn(x); }
  int sign_cost(double x) const { return sgn(x); }
  int sign_value(double x) const { return sgn(x); }
  bool abs_less(double a, double b) const { return std::fabs(a) < std::fabs(b); }
  bool less(double a, double b) const { return a < b; }
  void negate(double& x) const { x = -x; }
  int compare_ratio(double a0, double as, double b0, double bs) const {
    const double ra = std::max(a0, 0.0) / -as, rb = std::max(b0, 0.0) / -bs;
    const double slack = 1e-12 * (1 + std::max(ra, rb));
    return ra < rb - slack ? -1 : ra > rb + slack ? 1 : 0;
  }
  void pivot(double* t, std::size_t rows, std::size_t cols, std::size_t r, std::size_t s,
             const std::vector<char>& row_active, const std::vector<char>& col_active) const {
    double* pr = t + r * cols;
    const double p = pr[s];
    for (std::size_t j = 0; j < cols; ++j)
      if (j != s) pr[j] = -pr[j] / p;
    pr[s] = 1.0 / p;
    for (std::size_t i = 0; i < rows; ++i) {
      if (i == r || !row_active[i]) continue;
      double* pi = t + i * cols;
      const double f = pi[s];
      if (f == 0) continue;
      for (std::size_t j = 0; j < cols; ++j)
        if (j != s && (j == 0 || col_active[j])) pi[j] += f * pr[j];
      pi[s] = f * pr[s];
    }
  }
};

// q as a double (truncated); `ok` cleared when a nonzero q leaves [2^-900, 2^900].
double approx(const Rational& q, bool& ok) {
  // Integers (the common case) skip mpq_get_d's division; both truncate toward zero.
  const double d =
      mpz_cmp_ui(q.get_den_mpz_t(), 1) == 0 ? mpz_get_d(q.get_num_mpz_t()) : mpq_get_d(q.get_mpq_t());
  if (sgn(q) != 0) {
    const double a = std::fabs(d);
    if (!(a >= 0x1p-900 && a <= 0x1p900)) ok = false;
  }
  return d;
}

}  // namespace

FloatForm float_form(const Problem& p) {
  FloatForm f;
  const std::size_t n = f.n = p.num_vars;
  f.ids = constraint_ids(p);
  const std::size_t R = f.ids.size();
  f.g.resize(R * n);
  f.h.resize(R);
  f.filterable.assign(R, 1);
  const std::size_t m = p.num_rows();
  for (std::size_t k = 0; k < R; ++k) {
    const std::size_t id = f.ids[k];
    double* g = &f.g[k * n];
    bool ok = true;
    if (id < m) {
      for (std::size_t j = 0; j < n; ++j) g[j] = approx(p.a(id, j), ok);
      f.h[k] = approx(p.rhs[id], ok);
    } else {
      std::fill(g, g + n, 0.0);
      if (id < m + n) {
        g[id - m] = -1;
        f.h[k] = -approx(*p.lower[id - m], ok);
      } else {
        g[id - m - n] = 1;
        f.h[k] = approx(*p.upper[id - m - n], ok);
      }
    }
    // Euclidean norm with scaling, so that 2^900-sized entries do not overflow.
    double big = 0;
    for (std::size_t j = 0; j < n; ++j) big = std::max(big, std::fabs(g[j]));
    double norm = 1;
    if (big > 0) {
      double s = 0;
      for (std::size_t j = 0; j < n; ++j) s += (g[j] / big) * (g[j] / big);
      norm = big * std::sqrt(s);
    }
    for (std::size_t j = 0; j < n; ++j) g[j] /= norm;
    f.h[k] /= norm;
    f.filterable[k] = ok;
    if (!std::isfinite(f.h[k]) || !std::isfinite(norm)) f.finite = false;
  }
  f.c.resize(n);
  bool ok = true;
  double big = 0;
  for (std::size_t j = 0; j < n; ++j) big = std::max(big, std::fabs(f.c[j] = approx(p.objective[j], ok)));
  if (big > 0)
    for (double& x : f.c) x /= big;
  if (!ok && big == 0) f.finite = false;  // a nonzero objective underflowed
  for (double x : f.c)
    if (!std::isfinite(x)) f.finite = false;
  return f;
}

FloatResult float_simplex(const FloatForm& form) {
  FloatResult res;
  if (!form.finite) return res;
  const std::size_t n = form.n, R = form.ids.size();
  detail::SimplexEngine<DoubleField> e(n, R, DoubleField{});
  for (std::size_t k = 0; k < R; ++k) {
    const double* g = &form.g[k * n];
    e.set_row(
        k, [g](std::size_t j) { return g[j]; }, form.h[k]);
  }
  for (std::size_t j = 0; j < n; ++j) e.set_objective(j, form.c[j]);
  e.init_phase1_row();
  const detail::EngineStatus s = e.solve({}, int(20 + 10 * (R + n)));
  res.pivots = e.pivots();
  switch (s) {
    case detail::EngineStatus::optimal:
      res.kind = FloatResult::Kind::optimal;
      res.value = e.at(0, 0);
      break;
    case detail::EngineStatus::infeasible:
      res.kind = FloatResult::Kind::infeasible;
      break;
    case detail::EngineStatus::unbounded:
      res.kind = FloatResult::Kind::unbounded;
      break;
    case detail::EngineStatus::failed:
      res.kind = FloatResult::Kind::failed;
      break;
  }
  std::vector<std::size_t> rows;
  e.basis(rows, res.basis.zero_vars);
  for (std::size_t k : rows) res.basis.tight.push_back(form.ids[k]);
  return res;
}

std::vector<double> float_basic_point(const FloatForm& form, const Basis& basis) {
  const std::size_t n = form.n;
  std::vector<double> a(n * (n + 1), 0.0);
  std::size_t r = 0;
  for (std::size_t id : basis.tight) {
    const auto it = std::find(form.ids.begin(), form.ids.end(), id);
    if (it == form.ids.end()) return {};
    const std::size_t k = std::size_t(it - form.ids.begin());
    for (std::size_t j = 0; j < n; ++j) a[r * (n + 1) + j] = form.g[k * n + j];
    a[r * (n + 1) + n] = form.h[k];
    ++r;
  }
  for (std::size_t j : basis.zero_vars) a[r++ * (n + 1) + j] = 1.0;
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t piv = c;
    for (std::size_t i = c + 1; i < n; ++i)
      if (std::fabs(a[i * (n + 1) + c]) > std::fabs(a[piv * (n + 1) + c])) piv = i;
    if (a[piv * (n + 1) + c] == 0.0) return {};
    for (std::size_t j = 0; j <= n; ++j) std::swap(a[piv * (n + 1) + j], a[c * (n + 1) + j]);
    for (std::size_t i = 0; i < n; ++i) {
      if (i == c) continue;
      const double f = a[i * (n + 1) + c] / a[c * (n + 1) + c];
      for (std::size_t j = c; j <= n; ++j) a[i * (n + 1) + j] -= f * a[c * (n + 1) + j];
    }
  }
  std::vector<double> x(n);
  for (std::size_t j = 0; j < n; ++j) x[j] = a[j * (n + 1) + n] / a[j * (n + 1) + j];
  return x;
}

}  // namespace cmx::lp
