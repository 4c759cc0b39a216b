#include "lp/lp_problem.hpp"

#include <stdexcept>

namespace cmx::lp {

std::string_view to_string(Status s) {
  switch (s) {
    case Status::optimal: return "optimal";
    case Status::infeasible: return "infeasible";
    case Status::unbounded: return "unbounded";
  }
  return "?";
}

void Problem::add_row(const std::vector<Rational>& coefficients, const Rational& bound) {
  if (coefficients.size() != num_vars) throw std::invalid_argument("lp::Problem::add_row: wrong row length");
  matrix.insert(matrix.end(), coefficients.begin(), coefficients.end());
  rhs.push_back(bound);
}

void Problem::set_lower(std::size_t j, const Rational& v) {
  if (lower.empty()) lower.resize(num_vars);
  lower.at(j) = v;
}

void Problem::set_upper(std::size_t j, const Rational& v) {
  if (upper.empty()) upper.resize(num_vars);
  upper.at(j) = v;
}

void Problem::validate() const {
  if (objective.size() != num_vars) throw std::invalid_argument("lp::Problem: objective size != num_vars");
  if (matrix.size() != rhs.size() * num_vars) throw std::invalid_argument("lp::Problem: matrix size != rows * num_vars");
  if (!lower.empty() && lower.size() != num_vars) throw std::invalid_argument("lp::Problem: lower size != num_vars");
  if (!upper.empty() && upper.size() != num_vars) throw std::invalid_argument("lp::Problem: upper size != num_vars");
}

std::size_t lower_bound_id(const Problem& p, std::size_t j) { return p.num_rows() + j; }
std::size_t upper_bound_id(const Problem& p, std::size_t j) { return p.num_rows() + p.num_vars + j; }

std::vector<std::size_t> constraint_ids(const Problem& p) {
  std::vector<std::size_t> ids;
  ids.reserve(p.num_rows() + 2 * p.num_vars);
  for (std::size_t i = 0; i < p.num_rows(); ++i) ids.push_back(i);
  for (std::size_t j = 0; j < p.num_vars; ++j)
    if (!p.lower.empty() && p.lower[j]) ids.push_back(lower_bound_id(p, j));
  for (std::size_t j = 0; j < p.num_vars; ++j)
    if (!p.upper.empty() && p.upper[j]) ids.push_back(upper_bound_id(p, j));
  return ids;
}

void constraint(const Problem& p, std::size_t id, std::vector<Rational>& g, Rational& h) {
  const std::size_t m = p.num_rows(), n = p.num_vars;
  g.assign(n, Rational(0));
  if (id < m) {
    for (std::size_t j = 0; j < n; ++j) g[j] = p.a(id, j);
    h = p.rhs[id];
  } else if (id < m + n) {  // -x_j <= -lower_j
    g[id - m] = -1;
    h = -*p.lower.at(id - m);
  } else if (id < m + 2 * n) {  // x_j <= upper_j
    g[id - m - n] = 1;
    h = *p.upper.at(id - m - n);
  } else {
    throw std::out_of_range("lp::constraint: bad constraint id");
  }
}

bool is_feasible(const Problem& p, const std::vector<Rational>& x) {
  if (x.size() != p.num_vars) return false;
  Rational s;
  for (std::size_t i = 0; i < p.num_rows(); ++i) {
    s = 0;
    for (std::size_t j = 0; j < p.num_vars; ++j) s += p.a(i, j) * x[j];
    if (s > p.rhs[i]) return false;
  }
  for (std::size_t j = 0; j < p.num_vars; ++j) {
    if (!p.lower.empty() && p.lower[j] && x[j] < *p.lower[j]) return false;
    if (!p.upper.empty() && p.upper[j] && x[j] > *p.upper[j]) return false;
  }
  return true;
}

Rational objective_value(const Problem& p, const std::vector<Rational>& x) {
  Rational v = 0;
  for (std::size_t j = 0; j < p.num_vars; ++j)
    if (sgn(p.objective[j]) != 0) v += p.objective[j] * x[j];
  return v;
}

}  // namespace cmx::lp
