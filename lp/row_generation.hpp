#pragma once
// Row generation for tall LPs whose float basis fails certification (part of the `certified`
// backend). A flat boundary rounded to doubles gives the Chebyshev LP thousands of rows that are
// nearly, not exactly, parallel: the float simplex ends on a basis one of those rows violates by
// a hair, and the exact simplex over every row then pivots through all of them with large
// integers. Here the exact simplex runs on a few rows instead (the float basis's and those
// nearest to tight at the float optimum), and the rows its optimum violates are added until it
// violates none.
//
// Why the answer is exact: a subset of the rows bounds a larger set, so its optimum value is an
// upper bound; an optimum of the subset that satisfies every row is feasible for the whole
// problem, hence optimal, and its basis is certified again on the whole problem (certify_basis)
// before it is returned. A subset that is infeasible makes the whole problem infeasible.
#include <optional>

#include "lp/float_simplex.hpp"
#include "lp/lp_problem.hpp"

namespace cmx::lp {

struct RowGenerationOptions {
  std::size_t initial_rows = 16;  // rows nearest to tight at the float optimum, besides the basis
  std::size_t added_per_round = 8;
  int max_rounds = 12;
};

// An exact answer, or nullopt when the rounds run out or a subset is unbounded (the caller then
// runs the exact simplex on every row). `fr` must be an optimal float result for `form` =
// float_form(p).
std::optional<Solution> solve_by_row_generation(const Problem& p, const FloatForm& form,
                                                const FloatResult& fr,
                                                const RowGenerationOptions& options = {});

}  // namespace cmx::lp
