#pragma once
// Exact certificate of an optimal basis (the heart of the `certified` backend).
//
// A basis B (n tight constraints and variables fixed at 0, see lp_problem.hpp) defines the square
// system M x = h_B. The basis is optimal exactly when
//   (1) M is nonsingular,
//   (2) x = M^-1 h_B satisfies every other constraint (primal feasibility), and
//   (3) y = M^-T c has y_k >= 0 for every tight constraint and y_j = 0 for every variable fixed
//       at 0 (dual feasibility: c is a nonnegative combination of the tight rows).
// Then for any feasible z, c.z = sum_k y_k g_k.z <= sum_k y_k h_k = c.x (weak duality), so x is
// an exact optimum. All three checks run on integer rows (integer_rows.hpp), the solves by
// fraction-free Gauss-Jordan elimination; (2) first tries a double evaluation with a rigorous
// error bound (FloatForm) and falls back to integers only when that cannot decide.
#include <vector>

#include "lp/float_simplex.hpp"
#include "lp/lp_problem.hpp"

namespace cmx::lp {

struct Certificate {
  enum class Verdict { optimal, singular, primal_infeasible, dual_infeasible } verdict = Verdict::singular;
  std::vector<Rational> x;  // the basic solution (empty when singular)
  Rational value;           // c.x when optimal
};

// `filter`: float_form(p), used to decide most primal checks in doubles; nullptr for exact only.
Certificate certify_basis(const Problem& p, const Basis& basis, const FloatForm* filter = nullptr);

// Solves the square integer system M x = rhs (M is k x k, row-major) without fractions:
// returns det(M) > 0 and X with x = X / det, or det = 0 when M is singular.
Integer solve_integer_system(std::vector<Integer> M, std::vector<Integer> rhs, std::size_t k,
                             std::vector<Integer>& X);

}  // namespace cmx::lp
