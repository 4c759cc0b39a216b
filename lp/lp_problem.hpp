#pragma once
// Small dense linear programs with exact rational data, and what every backend returns.
//
//   maximise c.x  subject to  A x <= b  and  lower_j <= x_j <= upper_j  (absent bound: no limit)
//
// Constraint ids, shared by Basis and every backend: the m rows of A are ids 0..m-1; the lower
// bound of x_j is id m + j and its upper bound id m + n + j (only when that bound is present).
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "arith/rational.hpp"

namespace cmx::lp {

enum class Status { optimal, infeasible, unbounded };
std::string_view to_string(Status s);

struct Problem {
  std::size_t num_vars = 0;
  std::vector<Rational> objective;  // c, num_vars entries (maximised)
  std::vector<Rational> matrix;     // A, row-major, num_rows() * num_vars entries
  std::vector<Rational> rhs;        // b, one per row
  // num_vars entries each, or empty meaning "no such bounds at all".
  std::vector<std::optional<Rational>> lower, upper;

  explicit Problem(std::size_t n = 0) : num_vars(n), objective(n) {}
  std::size_t num_rows() const { return rhs.size(); }
  const Rational& a(std::size_t i, std::size_t j) const { return matrix[i * num_vars + j]; }
  // Appends the row coefficients . x <= bound (coefficients.size() must be num_vars).
  void add_row(const std::vector<Rational>& coefficients, const Rational& bound);
  void set_lower(std::size_t j, const Rational& v);
  void set_upper(std::size_t j, const Rational& v);
  const std::optional<Rational>* lower_bound(std::size_t j) const { return lower.empty() ? nullptr : &lower[j]; }
  const std::optional<Rational>* upper_bound(std::size_t j) const { return upper.empty() ? nullptr : &upper[j]; }
  // Throws std::invalid_argument when the sizes disagree. (A lower bound above an upper one is
  // not an error: the problem is then infeasible.)
  void validate() const;
};

std::size_t lower_bound_id(const Problem& p, std::size_t j);
std::size_t upper_bound_id(const Problem& p, std::size_t j);
// Every constraint id present in p, increasing: rows, then existing lower, then upper bounds.
std::vector<std::size_t> constraint_ids(const Problem& p);
// Constraint `id` as coefficients g (num_vars entries) and bound h, meaning g.x <= h.
void constraint(const Problem& p, std::size_t id, std::vector<Rational>& g, Rational& h);

// A basis of the optimum: `tight` constraints hold with equality and `zero_vars` are variables
// fixed at 0 without a constraint (only when the feasible set contains a line along which the
// objective is constant, so no vertex is optimal). tight.size() + zero_vars.size() == num_vars,
// and the square system "tight rows = bounds, zero_vars = 0" is nonsingular.
struct Basis {
  std::vector<std::size_t> tight;
  std::vector<std::size_t> zero_vars;
  bool operator==(const Basis&) const = default;
};

// What a backend did (for reports, tests and benchmarks; no effect on the answer).
struct SolveInfo {
  std::string backend;          // backend that produced the answer
  bool certified = false;       // the float basis was certified optimal (no exact pivoting)
  bool fell_back = false;       // certification failed and the exact simplex ran
  int float_pivots = 0;
  int exact_pivots = 0;
  int row_rounds = 0;           // subproblems of row generation (row_generation.hpp); 0: not used
};

struct Solution {
  Status status = Status::infeasible;
  std::vector<Rational> x;  // an optimal point (status optimal only)
  Rational value;           // c.x (status optimal only)
  Basis basis;              // its basis (status optimal only)
  SolveInfo info;
};

// Exact check that x satisfies every constraint of p (ties allowed).
bool is_feasible(const Problem& p, const std::vector<Rational>& x);
Rational objective_value(const Problem& p, const std::vector<Rational>& x);

}  // namespace cmx::lp
