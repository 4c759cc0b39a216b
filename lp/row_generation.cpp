#include "lp/row_generation.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "lp/certify_basis.hpp"
#include "lp/exact_simplex.hpp"

namespace cmx::lp {

namespace {

double float_slack(const FloatForm& form, std::size_t k, const std::vector<double>& x) {
  double s = form.h[k];
  for (std::size_t j = 0; j < form.n; ++j) s -= form.g[k * form.n + j] * x[j];
  return s;
}

// Rows of p (ids < m) in `form` order with their float slack at x, smallest first.
std::vector<std::pair<double, std::size_t>> rows_by_slack(const Problem& p, const FloatForm& form,
                                                          const std::vector<double>& x) {
  std::vector<std::pair<double, std::size_t>> out;
  for (std::size_t k = 0; k < form.ids.size(); ++k)
    if (form.ids[k] < p.num_rows()) out.emplace_back(float_slack(form, k, x), form.ids[k]);
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return out;
}

// The rows of `rows` (increasing ids) with every variable bound of p.
Problem subproblem(const Problem& p, const std::vector<std::size_t>& rows) {
  Problem s(p.num_vars);
  s.objective = p.objective;
  s.lower = p.lower;
  s.upper = p.upper;
  s.matrix.reserve(rows.size() * p.num_vars);
  for (std::size_t i : rows) {
    for (std::size_t j = 0; j < p.num_vars; ++j) s.matrix.push_back(p.a(i, j));
    s.rhs.push_back(p.rhs[i]);
  }
  return s;
}

// Constraint id of the subproblem -> id in p, and back (nullopt for a row not in the subset).
std::size_t to_full(const Problem& p, const std::vector<std::size_t>& rows, std::size_t id) {
  return id < rows.size() ? rows[id] : id - rows.size() + p.num_rows();
}
std::optional<std::size_t> to_sub(const Problem& p, const std::vector<std::size_t>& rows, std::size_t id) {
  if (id >= p.num_rows()) return id - p.num_rows() + rows.size();
  const auto it = std::lower_bound(rows.begin(), rows.end(), id);
  if (it == rows.end() || *it != id) return std::nullopt;
  return std::size_t(it - rows.begin());
}

Basis map_basis(const Basis& b, const std::function<std::optional<std::size_t>(std::size_t)>& f) {
  Basis out;
  out.zero_vars = b.zero_vars;
  for (std::size_t id : b.tight)
    if (const auto m = f(id)) out.tight.push_back(*m);
  return out;
}

// Rows outside `in` that x violates, most violated first (float slack; exact where it cannot
// decide), at most `limit`.
std::vector<std::size_t> violated_rows(const Problem& p, const FloatForm& form,
                                       const std::vector<Rational>& x, const std::vector<char>& in,
                                       std::size_t limit) {
  std::vector<double> xd(x.size());
  for (std::size_t j = 0; j < x.size(); ++j) xd[j] = x[j].get_d();
  bool filter_ok = true;  // the error bound below assumes magnitudes in [2^-300, 2^300]
  for (double v : xd)
    if (!std::isfinite(v) || (v != 0 && (std::fabs(v) < 0x1p-300 || std::fabs(v) > 0x1p300)))
      filter_ok = false;
  std::vector<std::pair<double, std::size_t>> bad;
  std::vector<Rational> g;
  Rational h, s;
  for (std::size_t k = 0; k < form.ids.size(); ++k) {
    const std::size_t id = form.ids[k];
    if (id >= p.num_rows() || in[id]) continue;
    double S = std::fabs(form.h[k]);
    for (std::size_t j = 0; j < form.n; ++j) S += std::fabs(form.g[k * form.n + j] * xd[j]);
    const double slack = float_slack(form, k, xd);
    if (filter_ok && form.filterable[k] && std::isfinite(S)) {
      // The error bound of certify_basis's filter (same form, x rounded the same way).
      const double E = (8.0 + double(form.n)) * 0x1p-48 * S * (1 + 0x1p-40);
      if (slack > E) continue;
      if (slack < -E) {
        bad.emplace_back(slack, id);
        continue;
      }
    }
    constraint(p, id, g, h);
    s = h;
    for (std::size_t j = 0; j < p.num_vars; ++j) s -= g[j] * x[j];
    if (sgn(s) < 0) bad.emplace_back(slack, id);
  }
  std::stable_sort(bad.begin(), bad.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < bad.size() && i < limit; ++i) out.push_back(bad[i].second);
  return out;
}

}  // namespace

std::optional<Solution> solve_by_row_generation(const Problem& p, const FloatForm& form,
                                                const FloatResult& fr, const RowGenerationOptions& options) {
  const std::vector<double> x0 = float_basic_point(form, fr.basis);
  if (x0.empty()) return std::nullopt;
  std::vector<char> in(p.num_rows(), 0);
  for (std::size_t id : fr.basis.tight)
    if (id < p.num_rows()) in[id] = 1;
  const auto nearest = rows_by_slack(p, form, x0);
  for (std::size_t i = 0; i < nearest.size() && i < options.initial_rows; ++i) in[nearest[i].second] = 1;
  Basis warm = fr.basis;  // ids of p
  int pivots = 0;
  for (int round = 0; round < options.max_rounds; ++round) {
    std::vector<std::size_t> rows;
    for (std::size_t i = 0; i < p.num_rows(); ++i)
      if (in[i]) rows.push_back(i);
    const Problem sub = subproblem(p, rows);
    const Basis sub_warm = map_basis(warm, [&](std::size_t id) { return to_sub(p, rows, id); });
    Solution s = exact_simplex(sub, &sub_warm);
    pivots += s.info.exact_pivots;
    if (s.status == Status::unbounded) return std::nullopt;
    if (s.status == Status::infeasible) {
      s.info.exact_pivots = pivots;
      s.info.row_rounds = round + 1;
      return s;
    }
    warm =
        map_basis(s.basis, [&](std::size_t id) { return std::optional<std::size_t>(to_full(p, rows, id)); });
    const std::vector<std::size_t> add = violated_rows(p, form, s.x, in, options.added_per_round);
    if (!add.empty()) {
      for (std::size_t id : add) in[id] = 1;
      continue;
    }
    Certificate cert = certify_basis(p, warm, &form);
    if (cert.verdict != Certificate::Verdict::optimal) return std::nullopt;
    Solution out;
    out.status = Status::optimal;
    out.x = std::move(cert.x);
    out.value = std::move(cert.value);
    out.basis = warm;
    out.info.exact_pivots = pivots;
    out.info.row_rounds = round + 1;
    return out;
  }
  return std::nullopt;
}

}  // namespace cmx::lp
