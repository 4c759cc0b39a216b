#pragma once
// Exact simplex (backend `exact`, and the fallback of `certified`).
//
// Fraction-free dictionary simplex over integers (simplex_engine.hpp with integer pivoting,
// Edmonds/Bareiss): every row is first scaled to coprime integers; the tableau then holds
// integers T with one common positive denominator D, and a pivot on T[r][s] computes
//   T'[i][j] = (T[i][j] * T[r][s] - T[i][s] * T[r][j]) / D      (an exact division)
// with D' = |T[r][s]|. Entries stay minors of the integer input, so they grow linearly in the
// input size instead of the gcd-bound fractions of a rational tableau. Anti-cycling: Dantzig's
// rule with a switch to Bland's rule during degenerate stalls (see simplex_engine.hpp).
#include "lp/lp_problem.hpp"

namespace cmx::lp {

// Solves p exactly. `warm`: a basis to start from (e.g. a float simplex's); any basis, even an
// infeasible or singular one, is accepted: rows that cannot be made tight are skipped and phase 1
// repairs feasibility. On `optimal`, x, value and basis are exact.
Solution exact_simplex(const Problem& p, const Basis* warm = nullptr);

}  // namespace cmx::lp
