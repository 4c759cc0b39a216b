#include "lp/glpk/glpk_backend.hpp"

#include <glpk.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>

#include "lp/backend_registry.hpp"
#include "lp/certify_basis.hpp"
#include "lp/integer_rows.hpp"

namespace cmx::lp {
namespace {

double exact_double(const Integer& z) {
  if (mpz_sizeinbase(z.get_mpz_t(), 2) > 53)  // |z| >= 2^53: no longer exact for GLPK
    throw UnsupportedProblem("glpk backend: integer-scaled data reach 2^53");
  return z.get_d();
}

unsigned two_adic(const Rational& q) { return unsigned(mpz_scan1(q.get_den_mpz_t(), 0)); }

struct Deleter {
  void operator()(glp_prob* lp) const { glp_delete_prob(lp); }
};

}  // namespace

Solution glpk_solve(const Problem& p) {
  p.validate();
  const std::size_t m = p.num_rows(), n = p.num_vars;
  // Column scales 2^e_j.
  std::vector<unsigned> e(n, 0);
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = 0; j < n; ++j) e[j] = std::max(e[j], two_adic(p.a(i, j)));
  auto scaled = [&](const Rational& q, std::size_t j) {
    Rational r = q;
    mpq_mul_2exp(r.get_mpq_t(), r.get_mpq_t(), e[j]);
    return r;
  };
  // Rows: the m rows of A, then every bound that is not an integer after scaling (as a row).
  std::vector<std::vector<Integer>> rows;
  std::vector<std::size_t> row_ids;
  std::vector<Rational> q(n + 1);
  std::vector<Integer> v(n + 1);
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t j = 0; j < n; ++j) q[j] = scaled(p.a(i, j), j);
    q[n] = p.rhs[i];
    integerise(q.data(), n + 1, v.data());
    rows.push_back(v);
    row_ids.push_back(i);
  }
  std::vector<std::optional<Rational>> lo(n), up(n);  // integral scaled column bounds
  for (std::size_t j = 0; j < n; ++j) {
    for (int side = 0; side < 2; ++side) {
      const std::optional<Rational>* b = side == 0 ? p.lower_bound(j) : p.upper_bound(j);
      if (!b || !*b) continue;
      Rational s = **b;
      mpq_div_2exp(s.get_mpq_t(), s.get_mpq_t(), e[j]);
      if (s.get_den() == 1) {
        (side == 0 ? lo : up)[j] = s;
      } else {  // -x'_j <= -s or x'_j <= s, integerised
        std::fill(q.begin(), q.end(), Rational(0));
        q[j] = side == 0 ? -1 : 1;
        q[n] = side == 0 ? Rational(-s) : s;
        integerise(q.data(), n + 1, v.data());
        rows.push_back(v);
        row_ids.push_back(side == 0 ? lower_bound_id(p, j) : upper_bound_id(p, j));
      }
    }
  }
  std::vector<Rational> cs(n);
  for (std::size_t j = 0; j < n; ++j) cs[j] = scaled(p.objective[j], j);
  std::vector<Integer> c(n);
  integerise(cs.data(), n, c.data());

  glp_term_out(GLP_OFF);
  std::unique_ptr<glp_prob, Deleter> lp(glp_create_prob());
  glp_set_obj_dir(lp.get(), GLP_MAX);
  const int R = int(rows.size()) == 0 ? 1 : int(rows.size());  // glp_exact refuses 0 rows
  glp_add_rows(lp.get(), R);
  glp_add_cols(lp.get(), int(n));
  std::vector<int> ind(n + 1);
  std::vector<double> val(n + 1);
  for (int r = 0; r < int(rows.size()); ++r) {
    int len = 0;
    for (std::size_t j = 0; j < n; ++j)
      if (sgn(rows[std::size_t(r)][j]) != 0) {
        ++len;
        ind[std::size_t(len)] = int(j) + 1;
        val[std::size_t(len)] = exact_double(rows[std::size_t(r)][j]);
      }
    glp_set_mat_row(lp.get(), r + 1, len, ind.data(), val.data());
    glp_set_row_bnds(lp.get(), r + 1, GLP_UP, 0.0, exact_double(rows[std::size_t(r)][n]));
  }
  if (rows.empty()) glp_set_row_bnds(lp.get(), 1, GLP_UP, 0.0, 1.0);  // 0 <= 1
  for (std::size_t j = 0; j < n; ++j) {
    const int col = int(j) + 1;
    glp_set_obj_coef(lp.get(), col, exact_double(c[j]));
    const bool hl = lo[j].has_value(), hu = up[j].has_value();
    const double l = hl ? exact_double(lo[j]->get_num()) : 0.0, u = hu ? exact_double(up[j]->get_num()) : 0.0;
    int type = GLP_FR;
    if (hl && hu) type = (*lo[j] == *up[j]) ? GLP_FX : GLP_DB;
    else if (hl) type = GLP_LO;
    else if (hu) type = GLP_UP;
    if (hl && hu && *lo[j] > *up[j]) {  // GLPK rejects l > u: the problem is infeasible
      Solution s;
      s.status = Status::infeasible;
      s.info.backend = "glpk";
      return s;
    }
    glp_set_col_bnds(lp.get(), col, type, l, u);
  }
  glp_smcp parm;
  glp_init_smcp(&parm);
  parm.msg_lev = GLP_MSG_OFF;
  const int rc = glp_exact(lp.get(), &parm);
  if (rc != 0) throw std::runtime_error("glpk backend: glp_exact failed with code " + std::to_string(rc));
  Solution s;
  s.info.backend = "glpk";
  const int status = glp_get_status(lp.get());
  if (status == GLP_NOFEAS || glp_get_prim_stat(lp.get()) == GLP_NOFEAS) {
    s.status = Status::infeasible;
    return s;
  }
  if (status == GLP_UNBND) {
    s.status = Status::unbounded;
    return s;
  }
  if (status != GLP_OPT) throw std::runtime_error("glpk backend: unexpected status " + std::to_string(status));
  Basis basis;
  for (int r = 0; r < int(rows.size()); ++r)
    if (glp_get_row_stat(lp.get(), r + 1) != GLP_BS) basis.tight.push_back(row_ids[std::size_t(r)]);
  for (std::size_t j = 0; j < n; ++j) {
    switch (glp_get_col_stat(lp.get(), int(j) + 1)) {
      case GLP_BS: break;
      case GLP_NL: basis.tight.push_back(lower_bound_id(p, j)); break;
      case GLP_NS:  // fixed column: the bound whose multiplier has the right sign (dj > 0 means
                    // the objective pushes x_j up, against its upper bound)
        basis.tight.push_back(glp_get_col_dual(lp.get(), int(j) + 1) > 0 ? upper_bound_id(p, j) : lower_bound_id(p, j));
        break;
      case GLP_NU: basis.tight.push_back(upper_bound_id(p, j)); break;
      case GLP_NF: basis.zero_vars.push_back(j); break;
      default: break;
    }
  }
  Certificate cert = certify_basis(p, basis);
  if (cert.verdict != Certificate::Verdict::optimal)
    throw std::logic_error("glpk backend: GLPK's optimal basis fails the exact certificate");
  s.status = Status::optimal;
  s.x = std::move(cert.x);
  s.value = std::move(cert.value);
  s.basis = std::move(basis);
  return s;
}

void register_glpk_backend() { register_backend("glpk", &glpk_solve); }

}  // namespace cmx::lp
