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

}  // namespace

Certificate certify_basis(const Problem& p, const Basis& basis, const FloatForm* filter) {
  Certificate cert;
  const std::size_t n = p.num_vars;
  if (basis.tight.size() + basis.zero_vars.size() != n) return cert;
  // The square system, rows in basis order: tight constraints, then x_j = 0.
  std::vector<Integer> M(n * n), h(n);
  std::vector<std::size_t> tight_sorted = basis.tight;
  std::sort(tight_sorted.begin(), tight_sorted.end());
  {
    std::size_t r = 0;
    for (std::size_t id : basis.tight) {
      IntegerRow row = integer_row(p, id);
      for (std::size_t j = 0; j < n; ++j) M[r * n + j].swap(row.v[j]);
      h[r].swap(row.v[n]);
      ++r;
    }
    for (std::size_t j : basis.zero_vars) {
      if (j >= n) return cert;
      M[r * n + j] = 1;
      ++r;
    }
  }
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
  // (3) dual feasibility first: it is cheaper than the primal scan and fails more often.
  std::vector<Integer> Y;
  // DT > 0 (normalised by the solver), so the signs of Y are those of y.
  const Integer DT = solve_integer_system(std::move(MT), integer_objective(p), n, Y);
  if (sgn(DT) == 0) return cert;  // cannot happen: det(M^T) = det(M) != 0
  for (std::size_t k = 0; k < n; ++k) {
    const int s = sgn(Y[k]);
    if (k < basis.tight.size() ? s < 0 : s != 0) {
      cert.verdict = Certificate::Verdict::dual_infeasible;
      return cert;
    }
  }
  // (2) primal feasibility of every constraint outside the basis.
  std::vector<double> px;
  bool px_ok = filter != nullptr;
  if (px_ok) {
    px.resize(n);
    for (std::size_t j = 0; j < n; ++j) {
      px[j] = approx_ratio(X[j], D);
      if (std::isnan(px[j])) px_ok = false;
    }
  }
  const std::vector<std::size_t> ids = filter ? filter->ids : constraint_ids(p);
  // Error bound of the double slack h' - g'.x~ relative to S = |h'| + sum |g'_j x~_j|: inputs
  // carry relative error <= 2^-52 (conversion) + 2^-53 (normalisation), x~ < 2^-50, products
  // 2^-53, and the sum of n + 1 terms (n + 1) 2^-53. All magnitudes are kept in [2^-300, 2^300]
  // (and the normalisation divides by a norm in the same range), so nothing underflows.
  const double rel = (8.0 + double(n)) * 0x1p-48;
  Integer acc;
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const std::size_t id = ids[k];
    if (std::binary_search(tight_sorted.begin(), tight_sorted.end(), id)) continue;
    if (px_ok && filter->filterable[k]) {
      const double* g = &filter->g[k * n];
      double s = filter->h[k], S = std::fabs(s);
      for (std::size_t j = 0; j < n; ++j) {
        const double t = g[j] * px[j];
        s -= t;
        S += std::fabs(t);
      }
      const double E = rel * S * (1 + 0x1p-40);
      if (s > E) continue;
      if (s < -E) {
        cert.verdict = Certificate::Verdict::primal_infeasible;
        return cert;
      }
    }
    const IntegerRow row = integer_row(p, id);
    mpz_mul(acc.get_mpz_t(), row.rhs().get_mpz_t(), D.get_mpz_t());
    for (std::size_t j = 0; j < n; ++j) mpz_submul(acc.get_mpz_t(), row.v[j].get_mpz_t(), X[j].get_mpz_t());
    if (sgn(acc) < 0) {
      cert.verdict = Certificate::Verdict::primal_infeasible;
      return cert;
    }
  }
  cert.verdict = Certificate::Verdict::optimal;
  cert.value = objective_value(p, cert.x);
  return cert;
}

}  // namespace cmx::lp
