#pragma once
// The dictionary simplex shared by the float and the exact solver (internal header).
//
// Problem form: maximise c.x subject to rows g_k.x <= h_k, x free (bounds are rows; see
// lp_problem.hpp). The dictionary expresses every basic variable as an affine function of the
// nonbasic ones:  basic_i = (T[i][0] + sum_j T[i][j] * nonbasic_j) / den.
//
// Variable ids: x_j is j (0 <= j < n, free), the phase-1 artificial t >= 0 is n, and the slack
// s_k = h_k - g_k.x + t >= 0 of row k is n + 1 + k. Tableau rows: 0 is the objective c.x, 1 is
// the phase-1 objective -t, 2 + k starts as slack k. Columns: 0 is the constant, 1 + j starts as
// x_j, n + 1 is t.
//
// Steps: (A) pivot every free x_j into the basis (on the rows of a warm-start basis when given,
// else by a ratio test that keeps a feasible start feasible); (B) if some slack is negative,
// pivot t in at the most negative row and run phase 1 on -t; (C) phase 2 on c.x. Free variables
// never leave the basis. Pricing is Dantzig's rule; after two consecutive degenerate pivots it is
// Bland's rule (smallest variable id enters, smallest id leaves among ties) until a pivot makes
// progress. Every infinite run would contain an infinite run of degenerate Bland pivots, which
// Bland's theorem excludes, so the simplex terminates.
//
// The Field supplies the arithmetic: signs (with tolerances for doubles, exact for integers),
// the value 1 in the current dictionary (unit), ratio comparison and the pivot update (plain for doubles, fraction-free for integers).
#include <cstddef>
#include <vector>

#include "lp/lp_problem.hpp"

namespace cmx::lp::detail {

enum class EngineStatus { optimal, infeasible, unbounded, failed };

template <class Field>
class SimplexEngine {
 public:
  using T = typename Field::value_type;

  // rows: R rows of n + 1 entries (g then h); c: n entries. `field` is moved in.
  SimplexEngine(std::size_t n, std::size_t R, Field field)
      : n_(n), R_(R), cols_(n + 2), f_(std::move(field)), tab_((R + 2) * (n + 2)) {
    basic_.resize(R + 2);
    for (std::size_t k = 0; k < R; ++k) basic_[2 + k] = int(n + 1 + k);
    nonbasic_.resize(n + 2);
    for (std::size_t j = 0; j < n + 1; ++j) nonbasic_[1 + j] = int(j);
    flipped_.assign(n, 0);
    row_active_.assign(R + 2, 1);
    col_active_.assign(n + 2, 1);
    col_active_[0] = 0;  // the constant column is never priced
  }

  T& at(std::size_t i, std::size_t j) { return tab_[i * cols_ + j]; }
  const T& at(std::size_t i, std::size_t j) const { return tab_[i * cols_ + j]; }
  Field& field() { return f_; }
  // Fills constraint row k: s_k = h - g.x + t.
  template <class G>
  void set_row(std::size_t k, G g_of, const T& h) {
    const std::size_t i = 2 + k;
    at(i, 0) = h;
    for (std::size_t j = 0; j < n_; ++j) at(i, 1 + j) = -g_of(j);
    at(i, n_ + 1) = f_.one();
  }
  void set_objective(std::size_t j, const T& cj) { at(0, 1 + j) = cj; }
  void init_phase1_row() { at(1, n_ + 1) = -f_.one(); }

  // Runs steps A to C. `warm_rows`: tableau row indices (k of constraint k) to make tight first.
  EngineStatus solve(const std::vector<std::size_t>& warm_rows, int max_pivots) {
    max_pivots_ = max_pivots;
    for (std::size_t k : warm_rows) {  // (A) warm start
      const std::size_t i = 2 + k;
      if (!is_slack(basic_[i])) continue;
      std::size_t best = 0;
      for (std::size_t j = 1; j <= n_; ++j)
        if (is_free(nonbasic_[j]) && f_.sign_coef(at(i, j)) != 0 && (best == 0 || f_.abs_less(at(i, best), at(i, j)))) best = j;
      if (best != 0 && !pivot(i, best)) return EngineStatus::failed;
    }
    for (std::size_t j = 1; j <= n_; ++j) {  // (A) cold drive-in of the remaining free variables
      if (!is_free(nonbasic_[j])) continue;
      if (f_.sign_cost(at(0, j)) < 0) flip(j);
      std::size_t r = ratio_row(j, true);
      if (r == 0) {
        flip(j);
        r = ratio_row(j, true);
      }
      if (r == 0) r = any_row(j);
      if (r != 0 && !pivot(r, j)) return EngineStatus::failed;
    }
    // (B) phase 1 when the start is infeasible.
    std::size_t worst = 0;
    for (std::size_t i = 2; i < R_ + 2; ++i)
      if (!is_free(basic_[i]) && f_.sign_value(at(i, 0)) < 0 && (worst == 0 || f_.less(at(i, 0), at(worst, 0)))) worst = i;
    const std::size_t tcol = column_of(int(n_));
    if (worst != 0) {
      // Re-seed the artificial column: t with coefficient 1 in every bounded basic row of the
      // CURRENT dictionary (step A has transformed the original one), so that pivoting t in at
      // the most negative row makes every row feasible. In terms of the original system this is
      // the integer column B * 1 (B the current basis matrix), so integer pivoting stays exact.
      for (std::size_t i = 2; i < R_ + 2; ++i) at(i, tcol) = is_free(basic_[i]) ? f_.zero() : f_.unit();
      for (std::size_t j = 0; j < cols_; ++j) at(1, j) = f_.zero();
      at(0, tcol) = f_.zero();
      at(1, tcol) = -f_.unit();
      if (!pivot(worst, tcol)) return EngineStatus::failed;
      const EngineStatus s1 = run(1);
      if (s1 == EngineStatus::failed) return s1;
      if (f_.sign_value(at(1, 0)) < 0) return EngineStatus::infeasible;
      // t = 0 now. If it is still basic, pivot it out (its row cannot vanish: the dictionary is
      // an invertible change of variables, so t depends on some nonbasic variable).
      const std::size_t trow = row_of(int(n_));
      if (trow != 0) {
        std::size_t best = 0;
        for (std::size_t j = 1; j < cols_; ++j)
          if (col_active_[j] && f_.sign_coef(at(trow, j)) != 0 && (best == 0 || f_.abs_less(at(trow, best), at(trow, j)))) best = j;
        if (best == 0 || !pivot(trow, best)) return EngineStatus::failed;
      }
    }
    col_active_[column_of(int(n_))] = 0;  // t stays nonbasic at 0 from now on
    row_active_[1] = 0;
    return run(0);  // (C)
  }

  int pivots() const { return pivots_; }
  // Tableau row of basic variable v, or 0 when v is nonbasic.
  std::size_t row_of(int v) const {
    for (std::size_t i = 2; i < R_ + 2; ++i)
      if (basic_[i] == v) return i;
    return 0;
  }
  bool is_flipped(std::size_t j) const { return flipped_[j] != 0; }
  // The basis in constraint-row terms: nonbasic slacks (row indices k) and nonbasic free x_j.
  void basis(std::vector<std::size_t>& tight_rows, std::vector<std::size_t>& zero_vars) const {
    tight_rows.clear();
    zero_vars.clear();
    for (std::size_t j = 1; j < cols_; ++j) {
      const int v = nonbasic_[j];
      if (is_free(v)) zero_vars.push_back(std::size_t(v));
      else if (is_slack(v)) tight_rows.push_back(std::size_t(v) - n_ - 1);
    }
  }

 private:
  bool is_free(int v) const { return v < int(n_); }
  bool is_slack(int v) const { return v > int(n_); }
  std::size_t column_of(int v) const {
    for (std::size_t j = 1; j < cols_; ++j)
      if (nonbasic_[j] == v) return j;
    return 0;
  }
  // Replaces nonbasic x_j of column j by -x_j.
  void flip(std::size_t j) {
    for (std::size_t i = 0; i < R_ + 2; ++i) f_.negate(at(i, j));
    flipped_[std::size_t(nonbasic_[j])] ^= 1;
  }
  // Leaving row for entering column s: min ratio value / (-coef) over rows with coef < 0 whose
  // basic variable is bounded (slack or t); ties to the smallest variable id. 0 when none.
  std::size_t ratio_row(std::size_t s, bool skip_negative_values = false) const {
    std::size_t best = 0;
    for (std::size_t i = 2; i < R_ + 2; ++i) {
      if (!row_active_[i] || is_free(basic_[i]) || f_.sign_coef(at(i, s)) >= 0) continue;
      if (skip_negative_values && f_.sign_value(at(i, 0)) < 0) continue;
      if (best == 0) {
        best = i;
        continue;
      }
      const int c = f_.compare_ratio(at(i, 0), at(i, s), at(best, 0), at(best, s));
      if (c < 0 || (c == 0 && basic_[i] < basic_[best])) best = i;
    }
    return best;
  }
  std::size_t any_row(std::size_t s) const {
    for (std::size_t i = 2; i < R_ + 2; ++i)
      if (row_active_[i] && !is_free(basic_[i]) && f_.sign_coef(at(i, s)) != 0) return i;
    return 0;
  }
  bool pivot(std::size_t r, std::size_t s) {
    if (++pivots_ > max_pivots_) return false;
    f_.pivot(tab_.data(), R_ + 2, cols_, r, s, row_active_, col_active_);
    std::swap(basic_[r], nonbasic_[s]);
    return true;
  }
  // Simplex on objective row o until optimal or unbounded.
  EngineStatus run(std::size_t o) {
    int degenerate = 0;
    for (;;) {
      const bool bland = degenerate >= 2;
      std::size_t s = 0;
      for (std::size_t j = 1; j < cols_; ++j) {
        if (!col_active_[j]) continue;
        const int v = nonbasic_[j];
        const int sg = f_.sign_cost(at(o, j));
        if (sg == 0 || (sg < 0 && !is_free(v))) continue;
        if (s == 0) {
          s = j;
        } else if (bland ? v < nonbasic_[s] : f_.abs_less(at(o, s), at(o, j))) {
          s = j;
        }
      }
      if (s == 0) return EngineStatus::optimal;
      if (f_.sign_cost(at(o, s)) < 0) flip(s);
      const std::size_t r = ratio_row(s);
      if (r == 0) return o == 1 ? EngineStatus::failed : EngineStatus::unbounded;
      degenerate = f_.sign_value(at(r, 0)) == 0 ? degenerate + 1 : 0;
      if (!pivot(r, s)) return EngineStatus::failed;
    }
  }

  std::size_t n_, R_, cols_;
  Field f_;
  std::vector<T> tab_;
  std::vector<int> basic_, nonbasic_;
  std::vector<char> flipped_, row_active_, col_active_;
  int pivots_ = 0, max_pivots_ = 0;
};

}  // namespace cmx::lp::detail
