#pragma once
// The Chebyshev centre of a polytope: the centre of the largest ball inside the intersection of
// half-spaces, solved as a linear program in exact rational arithmetic (a float simplex whose
// basis is then certified exactly; the exact centre and radius are the LP's exact optimum).
//
//   // the unit cube 0 <= x, y, z <= 1 as rows (a, b, c, d) meaning a x + b y + c z <= d
//   std::vector<std::array<double, 4>> rows = {{-1, 0, 0, 0}, {1, 0, 0, 1}, {0, -1, 0, 0},
//                                              {0, 1, 0, 1}, {0, 0, -1, 0}, {0, 0, 1, 1}};
//   cmx::ChebyshevCentre r = cmx::chebyshev_centre(rows);
//   // r.status == cmx::CentreStatus::interior, r.centre_exact == {"1/2", "1/2", "1/2"}, r.radius == 0.5
//
// Sign convention (the same as `cmx chebyshev` and the lp layer): a row (a, b, c, d) is the
// closed half-space  a x + b y + c z <= d.  To pass a x + b y + c z + d >= 0, give (-a, -b, -c, d).
// A row with a = b = c = 0 is all of space when d >= 0 (dropped) and makes the set infeasible
// when d < 0.
//
// This header includes only the standard library and <cmx/types.hpp>.
#include <array>
#include <cstdint>
#include <span>
#include <string>

#include "cmx/types.hpp"

namespace cmx {

// How the LP ended (the lp layer's ChebyshevStatus).
enum class CentreStatus : std::uint8_t {
  interior,        // radius > 0: the centre lies strictly inside every half-space, exactly
  empty_interior,  // the set is non-empty but flat (radius 0); the centre is a point of the set
  infeasible,      // the set is empty; centre and radius are 0 and meaningless
  unbounded,       // the set contains arbitrarily large balls (e.g. fewer than 4 independent normals
                   // pointing all ways); centre and radius are 0 and meaningless
};
// "interior", "empty_interior", "infeasible" or "unbounded".
const char* to_string(CentreStatus status);

// Options; the text values are those of the `cmx chebyshev` option of the same name. A value that
// does not parse makes chebyshev_centre throw cmx::Error naming the field.
struct ChebyshevCentreOptions {
  std::string lp = "certified";  // LP backend: certified (float simplex, exact certificate) or exact
  // Row weights w (the LP maximises r subject to n.x + w r <= d for each row with normal n):
  //   l2-upper: w = a rigorous upper bound of |n|_2 with weight_bits significant bits (exact
  //             |n|_2 for normals of a Pythagorean norm, e.g. axis normals): r is the radius of
  //             a Euclidean ball about the centre inside the set, below the largest such radius by a relative
  //             2^(1-bits) at most (a little more for normals that are not doubles);
  //   l1:       w = |n|_1: r is the half-side of the largest axis-parallel cube about the centre
  //             inside the set (its inscribed ball of radius r is inside too).
  std::string norm = "l2-upper";
  unsigned weight_bits = 53;  // 2..53, l2-upper only
};

struct ChebyshevCentre {
  CentreStatus status = CentreStatus::infeasible;
  ExactPoint3 centre_exact{"0", "0", "0"};  // the exact optimum, canonical "p/q" or "p"
  Point3d centre{};                         // centre_exact rounded to the nearest doubles
  std::string radius_exact = "0";           // the exact optimal r (see ChebyshevCentreOptions::norm)
  double radius = 0;                        // radius_exact rounded to the nearest double
  bool ok() const { return status == CentreStatus::interior; }
};

// The Chebyshev centre of { p : a x + b y + c z <= d for every row (a, b, c, d) }. The doubles
// are taken as the exact rationals they are. When the optimal centre is not unique (e.g. a long
// box), it is one optimal point, the same on every run.
// Errors: throws cmx::Error when a value is NaN or infinite (naming the row and column) or an
// option does not parse. An empty set, a flat set or an unbounded one is a status, not an error.
// Time: a few simplex pivots per row in doubles plus one exact certification, O(rows) rational
// operations on the input's bit sizes; the exact backend is markedly slower on large inputs.
ChebyshevCentre chebyshev_centre(std::span<const std::array<double, 4>> halfspaces,
                                 const ChebyshevCentreOptions& options = {});
// The same with exact rows: each value "p/q", "p" or a finite decimal (cmx/types.hpp).
// Errors: as above, and a value that does not parse (naming the row, the column and the text).
ChebyshevCentre chebyshev_centre(std::span<const std::array<std::string, 4>> halfspaces,
                                 const ChebyshevCentreOptions& options = {});

}  // namespace cmx
