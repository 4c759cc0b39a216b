#pragma once
// Chebyshev centre of {p : a x + b y + c z <= d for every half-space}: the LP
//   maximise r  subject to  a x + b y + c z + w r <= d (every nonzero row),  r >= 0,
// over x, y, z free, with w the row weight (row_weights.hpp). Variables are (x, y, z, r); the
// bound r >= 0 is constraint id m' + 3 of the LP (m' = rows kept).
//
// Statuses: interior (r > 0: the centre is strictly inside every half-space, exactly, and the
// ball of radius r fits when w >= |n|_2), empty_interior (r = 0: the set is nonempty but has no
// interior; the centre is a point of it), infeasible (empty set), unbounded (r unbounded: the
// set contains arbitrarily large balls, e.g. fewer than four independent normals pointing all
// ways). Zero rows 0 <= d are dropped when d >= 0 and make the set infeasible when d < 0. For
// infeasible and unbounded results centre and radius are 0 and meaningless.
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "arith/rational.hpp"
#include "lp/lp_problem.hpp"
#include "lp/row_weights.hpp"

namespace cmx::lp {

struct HalfSpace {
  Rational a, b, c, d;  // a x + b y + c z <= d
};

enum class ChebyshevStatus { interior, empty_interior, infeasible, unbounded };
std::string_view to_string(ChebyshevStatus s);

struct ChebyshevOptions {
  std::string backend = "certified";  // any name of backend_registry.hpp
  Norm norm = Norm::l2_upper;
  unsigned weight_bits = 53;          // significant bits of l2-upper weights
};

struct ChebyshevResult {
  ChebyshevStatus status = ChebyshevStatus::infeasible;
  std::array<Rational, 3> center;
  Rational radius;
  Solution lp;  // the LP answer behind it (basis, backend information)
};

// The LP above (rows in input order, zero rows omitted). `kept[i]` = input index of LP row i.
// Sets `zero_row_infeasible` when some zero row has d < 0.
Problem chebyshev_problem(const std::vector<HalfSpace>& halfspaces, const ChebyshevOptions& options,
                          std::vector<std::size_t>* kept = nullptr, bool* zero_row_infeasible = nullptr);

// Throws std::invalid_argument for an unknown backend, UnsupportedProblem when a reference
// backend cannot take the data.
ChebyshevResult chebyshev_center(const std::vector<HalfSpace>& halfspaces, const ChebyshevOptions& options = {});

// A guess from the float simplex alone, no certificate: the Chebyshev radius of the half-spaces
// a x + b y + c z <= d given in doubles (weights |(a, b, c)|_2 in doubles), up to rounding, and
// the largest |d| / |(a, b, c, |(a, b, c)|)| (the scale against which the radius means something).
// For cheap classification only: positions always come from chebyshev_center.
struct FloatChebyshev {
  bool optimal = false;  // the float simplex reached an optimum
  double radius = 0, scale = 0;
  std::array<double, 3> centre{};  // the float optimum's centre (optimal only; NaN if its basis is singular in doubles)
  std::vector<std::size_t> tight_rows;  // input rows tight in the optimal float basis (optimal only)
};
FloatChebyshev float_chebyshev(const std::vector<std::array<double, 4>>& halfspaces);

// Exact test: a x + b y + c z < d for every half-space (zero rows with d >= 0, being all of
// space, count as strictly satisfied).
bool strictly_inside(const std::vector<HalfSpace>& halfspaces, const std::array<Rational, 3>& p);
// Exact test: a x + b y + c z <= d for every half-space.
bool inside(const std::vector<HalfSpace>& halfspaces, const std::array<Rational, 3>& p);

}  // namespace cmx::lp
