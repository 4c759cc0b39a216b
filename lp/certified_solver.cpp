#include "lp/certified_solver.hpp"

#include "lp/certify_basis.hpp"
#include "lp/exact_simplex.hpp"
#include "lp/float_simplex.hpp"
#include "lp/row_generation.hpp"

namespace cmx::lp {

// Below row_generation_from rows the exact simplex on every row is as quick as a few subproblems.
Solution certified_solve(const Problem& p) {
  return certified_solve(p, row_generation_from);
}

Solution certified_solve(const Problem& p, std::size_t row_generation_from_rows) {
  p.validate();
  const FloatForm form = float_form(p);
  const FloatResult fr = float_simplex(form);
  if (fr.kind == FloatResult::Kind::optimal) {
    Certificate cert = certify_basis(p, fr.basis, &form);
    if (cert.verdict == Certificate::Verdict::optimal) {
      Solution s;
      s.status = Status::optimal;
      s.x = std::move(cert.x);
      s.value = std::move(cert.value);
      s.basis = fr.basis;
      s.info.backend = "certified";
      s.info.certified = true;
      s.info.float_pivots = fr.pivots;
      return s;
    }
    if (p.num_rows() >= row_generation_from_rows) {
      if (std::optional<Solution> s = solve_by_row_generation(p, form, fr)) {
        s->info.backend = "certified";
        s->info.fell_back = true;
        s->info.float_pivots = fr.pivots;
        return std::move(*s);
      }
    }
  }
  // Infeasible and unbounded float verdicts are not certified here (they are rare for the
  // Chebyshev LP); the exact simplex decides them, starting from the float basis.
  Solution s = exact_simplex(p, fr.kind == FloatResult::Kind::failed ? nullptr : &fr.basis);
  s.info.backend = "certified";
  s.info.fell_back = true;
  s.info.float_pivots = fr.pivots;
  return s;
}

}  // namespace cmx::lp
