#pragma once
// Integer forms of constraints: g.x <= h multiplied by a positive rational so that every entry is
// an integer and their gcd is 1. A positive multiple has the same solutions and the same sign of
// its dual multiplier, which is all the exact solvers and certificates need.
#include <cstddef>
#include <vector>

#include "arith/rational.hpp"
#include "lp/lp_problem.hpp"

namespace cmx::lp {

// g (num_vars entries) followed by h: n + 1 integers.
struct IntegerRow {
  std::vector<Integer> v;
  const Integer& rhs() const { return v.back(); }
};

// Scales the rationals q[0..k) to coprime integers out[0..k) (a positive multiple; all zero stays zero).
void integerise(const Rational* q, std::size_t k, Integer* out);

// Constraint `id` of p (see lp_problem.hpp for ids) in integer form.
IntegerRow integer_row(const Problem& p, std::size_t id);
// The objective in integer form (n entries, a positive multiple of c).
std::vector<Integer> integer_objective(const Problem& p);

}  // namespace cmx::lp
