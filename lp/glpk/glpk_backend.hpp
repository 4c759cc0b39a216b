#pragma once
// Backend `glpk`: GLPK's exact simplex (glp_exact) as an independent reference (GPL; tests,
// fuzzers and benchmarks only; the core never links it). Define CMX_HAVE_GLPK where linked.
//
// glp_exact is exact inside but not at its interface: non-integer doubles are
// replaced by nearby simple fractions and results come back as doubles. So the problem is fed
// as integers: each column is scaled by a power of two that clears the 2-adic part of its
// denominators (x_j = 2^e x'_j; this absorbs dyadic weights such as l2-upper), each row by the
// positive factor that makes it coprime integers, and every value must stay below 2^53
// (otherwise UnsupportedProblem is thrown). Only GLPK's status and final basis are used; the
// exact optimum is rebuilt from that basis on the original data (certify_basis), which also
// re-checks GLPK's claim.
#include "lp/lp_problem.hpp"

namespace cmx::lp {

Solution glpk_solve(const Problem& p);
// Registers glpk_solve under the name "glpk" (idempotent).
void register_glpk_backend();

}  // namespace cmx::lp
