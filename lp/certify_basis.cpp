#include "lp/certify_basis.hpp"

#include <algorithm>
#include <cmath>

#include "lp/integer_rows.hpp"

namespace cmx::lp {

Integer solve_integer_system(std::vector<Integer> M, std::vector<Integer> rhs, std::size_t k,
                             std::vector<Integer>& X) {
  // Augmented k x (k+1) matrix; integer-preserving Gauss-Jordan: after pivoting column c every
  // entry is a (c+1)-minor of the input, so the division by the previous pivot is exact, and at
  // the end the matrix is det * I (up to the row order chosen by the swaps).
  const std::size_t w = k + 1;
  std::vector<Integer> a(k * w);
  for (std::size_t i = 0; i < k; ++i) {
    for (std::size_t j = 0; j < k; ++j) a[i * w + j].swap(M[i * k + j]);
    a[i * w + k].swap(rhs[i]);
  }
  Integer prev = 1, tmp;
  for (std::size_t c = 0; c < k; ++c) {
    std::size_t piv = c;
    while (piv < k && sgn(a[piv * w + c]) == 0) ++piv;
    if (piv == k) {
      X.clear();
      return Integer(0);
    }
    if (piv != c)
      for (std::size_t j = 0; j < w; ++j) a[piv * w + j].swap(a[c * w + j]);
    const Integer& p = a[c * w + c];
    for (std::size_t i = 0; i < k; ++i) {
      if (i == c) continue;
      Integer& f = a[i * w + c];
      for (std::size_t j = 0; j < w; ++j) {
        if (j == c) continue;
        mpz_mul(tmp.get_mpz_t(), a[i * w + j].get_mpz_t(), p.get_mpz_t());
        mpz_submul(tmp.get_mpz_t(), f.get_mpz_t(), a[c * w + j].get_mpz_t());
        mpz_divexact(a[i * w + j].get_mpz_t(), tmp.get_mpz_t(), prev.get_mpz_t());
      }
      f = 0;
    }
    // Row c stays as it is: every earlier pivot row now also has diagonal p (its diagonal was
    // prev and its entry in column c is eliminated), so all rows share the scale p.
    prev = p;
  }
  // Now a = D * I | X with D = prev (the determinant up to the sign of the row swaps).
  X.resize(k);
  const bool negate = sgn(prev) < 0;
  for (std::size_t i = 0; i < k; ++i) {
    X[i].swap(a[i * w + k]);
    if (negate) X[i] = -X[i];
  }
  return negate ? Integer(-prev) : prev;
}

namespace {

// Double approximation of X / D with relative error < 2^-50, or NaN when outside [2^-300, 2^300].
double approx_ratio(const Integer& X, const Integer& D) {
  if (sgn(X) == 0) return 0.0;
  long ex = 0, ed = 0;
  const double mx = mpz_get_d_2exp(&ex, X.get_mpz_t());
  const double md = mpz_get_d_2exp(&ed, D.get_mpz_t());
  const long e = ex - ed;
  if (e < -298 || e > 298) return std::nan("");
  return std::ldexp(mx / md, int(e));
}

// The square system of a basis, rows in basis order: tight constraints, then x_j = 0 (row-major
// M, right-hand side h). False when a zero variable is out of range.
bool basis_system(const Problem& p, const Basis& basis, std::vector<Integer>& M, std::vector<Integer>& h) {
  const std::size_t n = p.num_vars;
  M.assign(n * n, Integer());
  h.assign(n, Integer());
  std::size_t r = 0;
  for (std::size_t id : basis.tight) {
    IntegerRow row = integer_row(p, id);
    for (std::size_t j = 0; j < n; ++j) M[r * n + j].swap(row.v[j]);
    h[r].swap(row.v[n]);
    ++r;
  }
  for (std::size_t j : basis.zero_vars) {
    if (j >= n) return false;
    M[r * n + j] = 1;
    ++r;
  }
  return true;
}

// Dual feasibility: the multipliers y of M^T y = c are >= 0 on tight rows and 0 on the x_j = 0
// rows. DT > 0 (normalised by the solver), so the signs of Y are those of y. Returns optimal
// when they are (the primal side still to check), dual_infeasible, or singular.
Certificate::Verdict dual_verdict(const Problem& p, std::vector<Integer> MT, const Basis& basis) {
  std::vector<Integer> Y;
  const Integer DT = solve_integer_system(std::move(MT), integer_objective(p), p.num_vars, Y);
  if (sgn(DT) == 0) return Certificate::Verdict::singular;  // cannot happen: det(M^T) = det(M) != 0
  for (std::size_t k = 0; k < p.num_vars; ++k) {
    const int s = sgn(Y[k]);
    if (k < basis.tight.size() ? s < 0 : s != 0) return Certificate::Verdict::dual_infeasible;
  }
  return Certificate::Verdict::optimal;
}

// The point X / D in doubles for the filter; empty when some coordinate is outside the range
// where its error bound holds.
std::vector<double> filter_point(const std::vector<Integer>& X, const Integer& D) {
  std::vector<double> px(X.size());
  for (std::size_t j = 0; j < X.size(); ++j) {
    px[j] = approx_ratio(X[j], D);
    if (std::isnan(px[j])) return {};
  }
  return px;
}

// The sign of constraint k's slack at px when the double filter decides it (+1, -1), else 0.
// Error bound of the double slack h' - g'.x~ relative to S = |h'| + sum |g'_j x~_j|: inputs
// carry relative error <= 2^-52 (conversion) + 2^-53 (normalisation), x~ < 2^-50, products
// 2^-53, and the sum of n + 1 terms (n + 1) 2^-53. All magnitudes are kept in [2^-300, 2^300]
// (and the normalisation divides by a norm in the same range), so nothing underflows.
int filtered_slack_sign(const FloatForm& filter, std::size_t k, const std::vector<double>& px) {
  const std::size_t n = px.size();
  const double rel = (8.0 + double(n)) * 0x1p-48;
  const double* g = &filter.g[k * n];
  double s = filter.h[k], S = std::fabs(s);
  for (std::size_t j = 0; j < n; ++j) {
    const double t = g[j] * px[j];
    s -= t;
    S += std::fabs(t);
  }
  const double E = rel * S * (1 + 0x1p-40);
  return s > E ? 1 : s < -E ? -1 : 0;
}

// Primal feasibility of every constraint outside the basis at X / D: the filter first where it
// applies, the exact slack h D - g.X otherwise.
bool primal_feasible(const Problem& p, const Basis& basis, const std::vector<Integer>& X, const Integer& D,
                     const FloatForm* filter) {
  const std::size_t n = p.num_vars;
  std::vector<std::size_t> tight_sorted = basis.tight;
  std::sort(tight_sorted.begin(), tight_sorted.end());
  const std::vector<double> px = filter ? filter_point(X, D) : std::vector<double>{};
  const std::vector<std::size_t> ids = filter ? filter->ids : constraint_ids(p);
  Integer acc;
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const std::size_t id = ids[k];
    if (std::binary_search(tight_sorted.begin(), tight_sorted.end(), id)) continue;
    if (!px.empty() && filter->filterable[k]) {
      const int sign = filtered_slack_sign(*filter, k, px);
      if (sign > 0) continue;
      if (sign < 0) return false;
    }
    const IntegerRow row = integer_row(p, id);
    mpz_mul(acc.get_mpz_t(), row.rhs().get_mpz_t(), D.get_mpz_t());
    for (std::size_t j = 0; j < n; ++j) mpz_submul(acc.get_mpz_t(), row.v[j].get_mpz_t(), X[j].get_mpz_t());
    if (sgn(acc) < 0) return false;
  }
  return true;
}

}  // namespace

Certificate certify_basis(const Problem& p, const Basis& basis, const FloatForm* filter) {
  Certificate cert;
  const std::size_t n = p.num_vars;
  if (basis.tight.size() + basis.zero_vars.size() != n) return cert;
  std::vector<Integer> M, h;
  if (!basis_system(p, basis, M, h)) return cert;
  std::vector<Integer> MT(n * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) MT[j * n + i] = M[i * n + j];
  std::vector<Integer> X;
  const Integer D = solve_integer_system(std::move(M), std::move(h), n, X);
  if (sgn(D) == 0) return cert;
  cert.x.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    cert.x[j] = Rational(X[j], D);
    cert.x[j].canonicalize();
  }
  // Dual feasibility first: it is cheaper than the primal scan and fails more often.
  if (const auto dual = dual_verdict(p, std::move(MT), basis); dual != Certificate::Verdict::optimal) {
    cert.verdict = dual;
    return cert;
  }
  if (!primal_feasible(p, basis, X, D, filter)) {
    cert.verdict = Certificate::Verdict::primal_infeasible;
    return cert;
  }
  cert.verdict = Certificate::Verdict::optimal;
  cert.value = objective_value(p, cert.x);
  return cert;
}

}  // namespace cmx::lp
