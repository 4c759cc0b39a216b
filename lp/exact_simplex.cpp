#include "lp/exact_simplex.hpp"

#include <algorithm>
#include <stdexcept>

#include "lp/integer_rows.hpp"
#include "lp/simplex_engine.hpp"

namespace cmx::lp {
namespace {

// Integer arithmetic with the common denominator `den` of the whole tableau (always > 0).
struct IntegerField {
  using value_type = Integer;
  Integer den = 1;
  mutable Integer tmp, save;  // scratch, to avoid allocations
  static Integer one() { return Integer(1); }
  static Integer zero() { return Integer(0); }
  Integer unit() const { return den; }  // 1 in the current dictionary (entries are over den)
  static int sg(const Integer& x) { return mpz_sgn(x.get_mpz_t()); }
  int sign_coef(const Integer& x) const { return sg(x); }
  int sign_cost(const Integer& x) const { return sg(x); }
  int sign_value(const Integer& x) const { return sg(x); }
  bool abs_less(const Integer& a, const Integer& b) const { return mpz_cmpabs(a.get_mpz_t(), b.get_mpz_t()) < 0; }
  bool less(const Integer& a, const Integer& b) const { return mpz_cmp(a.get_mpz_t(), b.get_mpz_t()) < 0; }
  void negate(Integer& x) const { mpz_neg(x.get_mpz_t(), x.get_mpz_t()); }
  // a0 / (-as) versus b0 / (-bs) with as, bs < 0: compare a0 * bs with b0 * as, reversed.
  int compare_ratio(const Integer& a0, const Integer& as, const Integer& b0, const Integer& bs) const {
    mpz_mul(tmp.get_mpz_t(), a0.get_mpz_t(), bs.get_mpz_t());
    mpz_mul(save.get_mpz_t(), b0.get_mpz_t(), as.get_mpz_t());
    const int c = mpz_cmp(tmp.get_mpz_t(), save.get_mpz_t());
    return c > 0 ? -1 : c < 0 ? 1 : 0;
  }
  void pivot(Integer* t, std::size_t rows, std::size_t cols, std::size_t r, std::size_t s,
             const std::vector<char>& row_active, const std::vector<char>& col_active) {
    Integer* pr = t + r * cols;
    const Integer p = pr[s];
    const int sgp = sg(p);
    const Integer ap = abs(p);
    for (std::size_t i = 0; i < rows; ++i) {
      if (i == r || !row_active[i]) continue;
      Integer* pi = t + i * cols;
      save = pi[s];
      if (sgp < 0) mpz_neg(save.get_mpz_t(), save.get_mpz_t());  // sign(p) * T[i][s]
      for (std::size_t j = 0; j < cols; ++j) {
        if (j == s || (j != 0 && !col_active[j])) continue;
        mpz_mul(tmp.get_mpz_t(), pi[j].get_mpz_t(), ap.get_mpz_t());
        mpz_submul(tmp.get_mpz_t(), save.get_mpz_t(), pr[j].get_mpz_t());
        mpz_divexact(pi[j].get_mpz_t(), tmp.get_mpz_t(), den.get_mpz_t());
      }
      pi[s] = save;
    }
    for (std::size_t j = 0; j < cols; ++j) {
      if (j == s || (j != 0 && !col_active[j])) continue;
      if (sgp > 0) mpz_neg(pr[j].get_mpz_t(), pr[j].get_mpz_t());
    }
    pr[s] = sgp > 0 ? den : Integer(-den);
    den = ap;
  }
};

}  // namespace

Solution exact_simplex(const Problem& p, const Basis* warm) {
  p.validate();
  const std::size_t n = p.num_vars;
  const std::vector<std::size_t> ids = constraint_ids(p);
  const std::size_t R = ids.size();
  detail::SimplexEngine<IntegerField> e(n, R, IntegerField{});
  for (std::size_t k = 0; k < R; ++k) {
    const IntegerRow row = integer_row(p, ids[k]);
    e.set_row(k, [&row](std::size_t j) { return row.v[j]; }, row.rhs());
  }
  const std::vector<Integer> c = integer_objective(p);
  for (std::size_t j = 0; j < n; ++j) e.set_objective(j, c[j]);
  e.init_phase1_row();
  std::vector<std::size_t> warm_rows;
  if (warm) {
    for (std::size_t id : warm->tight) {
      const auto it = std::lower_bound(ids.begin(), ids.end(), id);
      if (it != ids.end() && *it == id) warm_rows.push_back(std::size_t(it - ids.begin()));
    }
  }
  // Bland's rule guarantees termination; the limit only guards against a bug.
  const detail::EngineStatus s = e.solve(warm_rows, 1 << 30);
  Solution sol;
  sol.info.backend = "exact";
  sol.info.exact_pivots = e.pivots();
  switch (s) {
    case detail::EngineStatus::infeasible: sol.status = Status::infeasible; return sol;
    case detail::EngineStatus::unbounded: sol.status = Status::unbounded; return sol;
    case detail::EngineStatus::failed: throw std::logic_error("lp::exact_simplex: internal failure");
    case detail::EngineStatus::optimal: break;
  }
  sol.status = Status::optimal;
  sol.x.assign(n, Rational(0));
  const Integer& den = e.field().den;
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t i = e.row_of(int(j));
    if (i == 0) continue;
    sol.x[j] = Rational(e.at(i, 0), den);
    sol.x[j].canonicalize();
    if (e.is_flipped(j)) sol.x[j] = -sol.x[j];
  }
  std::vector<std::size_t> rows;
  e.basis(rows, sol.basis.zero_vars);
  for (std::size_t k : rows) sol.basis.tight.push_back(ids[k]);
  sol.value = objective_value(p, sol.x);
  return sol;
}

}  // namespace cmx::lp
