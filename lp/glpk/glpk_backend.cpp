#include "lp/glpk/glpk_backend.hpp"

#include <glpk.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

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

// The problem scaled to integers for GLPK: column j scaled by 2^e_j, rows g.x' <= h (A's rows,
// then every bound that is not an integer after scaling), integral column bounds, objective c.
struct IntegerLp {
  std::vector<std::vector<Integer>> rows;  // n coefficients, then h
  std::vector<std::size_t> row_ids;        // the constraint of p each row is
  std::vector<std::optional<Rational>> lo, up;
  std::vector<Integer> c;
};

// Column scales 2^e_j: the largest power of two in a denominator of column j of A.
std::vector<unsigned> column_scales(const Problem& p) {
  std::vector<unsigned> e(p.num_vars, 0);
  for (std::size_t i = 0; i < p.num_rows(); ++i)
    for (std::size_t j = 0; j < p.num_vars; ++j) e[j] = std::max(e[j], two_adic(p.a(i, j)));
  return e;
}

// Bound `side` (0 lower, 1 upper) of column j: an integral column bound, or a row.
void add_bound(const Problem& p, std::size_t j, int side, unsigned ej, IntegerLp& lp) {
  const std::size_t n = p.num_vars;
  const std::optional<Rational>* b = side == 0 ? p.lower_bound(j) : p.upper_bound(j);
  if (!b || !*b) return;
  Rational s = **b;
  mpq_div_2exp(s.get_mpq_t(), s.get_mpq_t(), ej);
  if (s.get_den() == 1) {
    (side == 0 ? lp.lo : lp.up)[j] = s;
    return;
  }
  // -x'_j <= -s or x'_j <= s, integerised
  std::vector<Rational> q(n + 1, Rational(0));
  std::vector<Integer> v(n + 1);
  q[j] = side == 0 ? -1 : 1;
  q[n] = side == 0 ? Rational(-s) : s;
  integerise(q.data(), n + 1, v.data());
  lp.rows.push_back(v);
  lp.row_ids.push_back(side == 0 ? lower_bound_id(p, j) : upper_bound_id(p, j));
}

IntegerLp integer_lp(const Problem& p) {
  const std::size_t m = p.num_rows(), n = p.num_vars;
  const std::vector<unsigned> e = column_scales(p);
  const auto scaled = [&](const Rational& q, std::size_t j) {
    Rational r = q;
    mpq_mul_2exp(r.get_mpq_t(), r.get_mpq_t(), e[j]);
    return r;
  };
  IntegerLp lp;
  std::vector<Rational> q(n + 1);
  std::vector<Integer> v(n + 1);
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t j = 0; j < n; ++j) q[j] = scaled(p.a(i, j), j);
    q[n] = p.rhs[i];
    integerise(q.data(), n + 1, v.data());
    lp.rows.push_back(v);
    lp.row_ids.push_back(i);
  }
  lp.lo.resize(n);
  lp.up.resize(n);
  for (std::size_t j = 0; j < n; ++j)
    for (int side = 0; side < 2; ++side) add_bound(p, j, side, e[j], lp);
  std::vector<Rational> cs(n);
  for (std::size_t j = 0; j < n; ++j) cs[j] = scaled(p.objective[j], j);
  lp.c.resize(n);
  integerise(cs.data(), n, lp.c.data());
  return lp;
}

void set_rows(glp_prob* g, const IntegerLp& lp, std::size_t n) {
  const int R = int(lp.rows.size()) == 0 ? 1 : int(lp.rows.size());  // glp_exact refuses 0 rows
  glp_add_rows(g, R);
  glp_add_cols(g, int(n));
  std::vector<int> ind(n + 1);
  std::vector<double> val(n + 1);
  for (int r = 0; r < int(lp.rows.size()); ++r) {
    const std::vector<Integer>& row = lp.rows[std::size_t(r)];
    int len = 0;
    for (std::size_t j = 0; j < n; ++j)
      if (sgn(row[j]) != 0) {
        ++len;
        ind[std::size_t(len)] = int(j) + 1;
        val[std::size_t(len)] = exact_double(row[j]);
      }
    glp_set_mat_row(g, r + 1, len, ind.data(), val.data());
    glp_set_row_bnds(g, r + 1, GLP_UP, 0.0, exact_double(row[n]));
  }
  if (lp.rows.empty()) glp_set_row_bnds(g, 1, GLP_UP, 0.0, 1.0);  // 0 <= 1
}

// Objective and column bounds; false when some column has l > u (GLPK rejects it: infeasible).
bool set_columns(glp_prob* g, const IntegerLp& lp, std::size_t n) {
  for (std::size_t j = 0; j < n; ++j) {
    const int col = int(j) + 1;
    glp_set_obj_coef(g, col, exact_double(lp.c[j]));
    const bool hl = lp.lo[j].has_value(), hu = lp.up[j].has_value();
    const double l = hl ? exact_double(lp.lo[j]->get_num()) : 0.0, u = hu ? exact_double(lp.up[j]->get_num()) : 0.0;
    int type = GLP_FR;
    if (hl && hu) type = (*lp.lo[j] == *lp.up[j]) ? GLP_FX : GLP_DB;
    else if (hl) type = GLP_LO;
    else if (hu) type = GLP_UP;
    if (hl && hu && *lp.lo[j] > *lp.up[j]) return false;
    glp_set_col_bnds(g, col, type, l, u);
  }
  return true;
}

// GLPK's optimal basis in cmx's terms: tight constraints and zero (free, non-basic) variables.
Basis basis_of(glp_prob* g, const Problem& p, const IntegerLp& lp) {
  Basis basis;
  for (int r = 0; r < int(lp.rows.size()); ++r)
    if (glp_get_row_stat(g, r + 1) != GLP_BS) basis.tight.push_back(lp.row_ids[std::size_t(r)]);
  for (std::size_t j = 0; j < p.num_vars; ++j) {
    switch (glp_get_col_stat(g, int(j) + 1)) {
      case GLP_BS: break;
      case GLP_NL: basis.tight.push_back(lower_bound_id(p, j)); break;
      case GLP_NS:  // fixed column: the bound whose multiplier has the right sign (dj > 0 means
                    // the objective pushes x_j up, against its upper bound)
        basis.tight.push_back(glp_get_col_dual(g, int(j) + 1) > 0 ? upper_bound_id(p, j) : lower_bound_id(p, j));
        break;
      case GLP_NU: basis.tight.push_back(upper_bound_id(p, j)); break;
      case GLP_NF: basis.zero_vars.push_back(j); break;
      default: break;
    }
  }
  return basis;
}

Solution with_status(Status status) {
  Solution s;
  s.status = status;
  s.info.backend = "glpk";
  return s;
}

}  // namespace

Solution glpk_solve(const Problem& p) {
  p.validate();
  const std::size_t n = p.num_vars;
  const IntegerLp ilp = integer_lp(p);
  glp_term_out(GLP_OFF);
  std::unique_ptr<glp_prob, Deleter> lp(glp_create_prob());
  glp_set_obj_dir(lp.get(), GLP_MAX);
  set_rows(lp.get(), ilp, n);
  if (!set_columns(lp.get(), ilp, n)) return with_status(Status::infeasible);
  glp_smcp parm;
  glp_init_smcp(&parm);
  parm.msg_lev = GLP_MSG_OFF;
  const int rc = glp_exact(lp.get(), &parm);
  if (rc != 0) throw std::runtime_error("glpk backend: glp_exact failed with code " + std::to_string(rc));
  const int status = glp_get_status(lp.get());
  if (status == GLP_NOFEAS || glp_get_prim_stat(lp.get()) == GLP_NOFEAS) return with_status(Status::infeasible);
  if (status == GLP_UNBND) return with_status(Status::unbounded);
  if (status != GLP_OPT) throw std::runtime_error("glpk backend: unexpected status " + std::to_string(status));
  Basis basis = basis_of(lp.get(), p, ilp);
  Certificate cert = certify_basis(p, basis);
  if (cert.verdict != Certificate::Verdict::optimal)
    throw std::logic_error("glpk backend: GLPK's optimal basis fails the exact certificate");
  Solution s = with_status(Status::optimal);
  s.x = std::move(cert.x);
  s.value = std::move(cert.value);
  s.basis = std::move(basis);
  return s;
}

void register_glpk_backend() { register_backend("glpk", &glpk_solve); }

}  // namespace cmx::lp
