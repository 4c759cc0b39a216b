#pragma once
// Exact orientation predicates on plain arrays: the sign of a determinant, exactly, for every
// finite input (no tolerance, no epsilon), whichever arithmetic decides it.
//
//   cmx::Point3d a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0, 0, 1};
//   int s = cmx::orient3d(a, b, c, d);  // +1: (a, b, c, d) is right-handed
//
// Sign convention: orient3d(a, b, c, d) is the sign of det[b-a, c-a, d-a], positive for the unit
// tetrahedron above (cmx's tet orientation, the one cmx::Tet means). This is the OPPOSITE of
// Shewchuk's, TetGen's and geogram's orient3d(a, b, c, d); swap two arguments to port code.
// orient2d(a, b, c) is the sign of det[b-a, c-a]: +1 when a, b, c turn counterclockwise.
//
// This header includes only the standard library and <cmx/types.hpp>. The functions are
// thread-safe (no shared state).
#include <array>
#include <cstdint>

#include "cmx/types.hpp"

namespace cmx {

// Which arithmetic cascade decides a sign (`cmx orient3d --filter NAME` takes the same names).
// Every choice returns the same, exact sign; only the speed differs.
//   cascade  (default) semi-static filter, then Shewchuk-style adaptive expansions on doubles;
//            exact rationals: a double interval, then the exact integer determinant.
//   interval a double interval first (also on doubles), then the exact determinant.
//   exact    the exact integer determinant only (GMP; the slowest, for cross-checks).
enum class PredicateArithmetic : std::uint8_t { cascade, interval, exact };
// "cascade", "interval" or "exact".
const char* to_string(PredicateArithmetic arithmetic);

// The sign of det[b-a, c-a, d-a]: +1, 0 (coplanar) or -1. Exact for all finite doubles,
// including subnormals and points whose determinant underflows in doubles.
// Errors: throws cmx::Error naming the point and coordinate when a coordinate is NaN or infinite.
// Time: O(1); typically a few nanoseconds (the filter decides), at most microseconds.
int orient3d(const Point3d& a, const Point3d& b, const Point3d& c, const Point3d& d,
             PredicateArithmetic arithmetic = PredicateArithmetic::cascade);

// The same on exact rational coordinates given as text: "p/q", "p" or a finite decimal such as
// "-0.25" or "1e-3" (cmx/types.hpp).
// Errors: throws cmx::Error naming the point, the coordinate and the text when a coordinate does
// not parse (or is NaN/inf text, or has a zero denominator).
// Time: parsing is linear in the text; the sign costs a filter on cached double enclosures, and
// the exact determinant (polynomial in the bit sizes) only when the filter cannot decide.
int orient3d(const ExactPoint3& a, const ExactPoint3& b, const ExactPoint3& c, const ExactPoint3& d,
             PredicateArithmetic arithmetic = PredicateArithmetic::cascade);

// The sign of det[b-a, c-a] in the plane: +1 (counterclockwise), 0 (collinear) or -1 (clockwise).
// Exact for all finite doubles. Errors: throws cmx::Error naming the point and coordinate when a
// coordinate is NaN or infinite. Time: O(1).
int orient2d(const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& c,
             PredicateArithmetic arithmetic = PredicateArithmetic::cascade);

}  // namespace cmx
