#pragma once
// The float simplex of the `certified` backend: a dense double dictionary simplex (see
// simplex_engine.hpp) on rows scaled to unit Euclidean norm of their coefficient part. For the
// Chebyshev LP that is the recommended normalisation (unit normal, equal r coefficients up to a
// common factor): without it, float bases of 40-bit data fail the exact certificate half of the
// time (measured). Its answer is only a guess: certify_basis decides.
#include <cstddef>
#include <vector>

#include "lp/lp_problem.hpp"

namespace cmx::lp {

// The problem in doubles, every constraint (rows and bounds) as g.x <= h with |g|_2 = 1.
struct FloatForm {
  std::size_t n = 0;
  std::vector<std::size_t> ids;  // constraint ids, in order
  std::vector<double> g;         // ids.size() x n, row-major, normalised
  std::vector<double> h;         // normalised bounds
  std::vector<double> c;         // objective scaled to max |c_j| = 1
  // Per constraint: every nonzero entry converted with relative error <= 2^-52 into
  // [2^-900, 2^900] before normalisation, so certify_basis may filter its sign with doubles.
  std::vector<char> filterable;
  bool finite = true;  // all entries finite (else the float simplex is skipped)
};
FloatForm float_form(const Problem& p);

struct FloatResult {
  enum class Kind { optimal, infeasible, unbounded, failed } kind = Kind::failed;
  Basis basis;       // the final basis (meaningful for optimal)
  double value = 0;  // objective value of that basis (optimal only), for the scaled objective c
  int pivots = 0;
};
FloatResult float_simplex(const FloatForm& form);

// The point of a basis in doubles: its square system (tight constraints of `form`, zero_vars = 0)
// solved with partial pivoting. Empty when the doubles see it singular. A guess, like the rest.
std::vector<double> float_basic_point(const FloatForm& form, const Basis& basis);

}  // namespace cmx::lp
