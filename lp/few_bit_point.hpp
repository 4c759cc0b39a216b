#pragma once
// Few-bit interior points for the method's precision reduction (paper 4.2.3, Shrink-and-Expand
// notes section 6). Each search takes half-spaces and a point p strictly inside them (checked:
// std::invalid_argument otherwise), returns a point certified strictly inside (exact test
// a x + b y + c z < d for every half-space) and never more bits than p: if it finds nothing
// smaller it returns p itself.
//
// Bits of a point: the maximum over its coordinates of bit_size(numerator) + bit_size(denominator)
// (cmx::bit_size of a Rational); a double such as 0.75 = 3/4 counts 2 + 3 = 5.
#include <array>
#include <cstddef>
#include <vector>

#include "arith/rational.hpp"
#include "lp/chebyshev_center.hpp"

namespace cmx::lp {

std::size_t point_bits(const Point3& p);

struct FewBitResult {
  Point3 point;
  std::size_t bits = 0;  // point_bits(point)
  bool reduced = false;  // point != the input interior point
  int checks = 0;        // candidates tested against the half-spaces
};

// Each coordinate rounded to the nearest double.
FewBitResult few_bits_by_doubles(const std::vector<HalfSpace>& h, const Point3& interior);

// Each coordinate rounded to the nearest dyadic with k significant bits, k = 1, 2, 4, 8, ... up to
// `max_k`, then a bisection between the last failing and the first succeeding k for the smallest
// k that succeeds (the smallest found; success is not monotone in k, so not always minimal).
FewBitResult few_bits_by_dyadics(const std::vector<HalfSpace>& h, const Point3& interior, unsigned max_k = 4096);

// Binary search on the segment from the interior point p toward `other` (any point, e.g. a
// witness vertex on the boundary), as paper 4.2.3: candidates p + t (other - p) with dyadic t,
// starting at t = 1/2; a candidate strictly inside ends the search, one outside halves the step
// toward p; at most `max_steps` candidates, and the search stops once a candidate has more bits
// than p. Pays off when p is a low-bit point that the caller wants pushed toward `other`, and
// returns p when every candidate is longer.
FewBitResult few_bits_by_segment(const std::vector<HalfSpace>& h, const Point3& interior, const Point3& other,
                                 int max_steps = 64);

// Shrink-and-Expand's right-shift bisection: the double rounding first; then for a shift s every
// coordinate whose min(bits(num), bits(den)) exceeds s gets num >> s and den >> s (truncation),
// and a bisection over s in [0, s_max] (s_max: largest s keeping every shifted denominator > 10)
// keeps the largest s whose point is strictly inside, within `max_steps` bisection steps.
FewBitResult few_bits_by_shift(const std::vector<HalfSpace>& h, const Point3& interior, int max_steps = 20);

}  // namespace cmx::lp
