#pragma once
// Weights w of the Chebyshev LP rows n.x + w r <= d. Any w > 0 makes an optimum with r > 0 a
// strictly interior point; w >= |n|_2 additionally puts the Euclidean ball B(x, r) inside.
//
//   l2-upper : the exact dyadic value of an upper bound u >= |n|_2 with at most `bits`
//              significant bits (53 = a double rounded up). Relative slack < 2^(1 - bits) (plus
//              one ulp per component when a component is not a double). Rigour: either every
//              component is converted to a double upper bound of its magnitude and the sum of
//              squares and the square root are evaluated with the rounding mode set upward (each
//              rounding can only increase the result), or, outside [2^-500, 2^500], MPFR
//              evaluates sqrt(n.n) from the exact rational n.n rounding up at `bits` bits.
//              Normals with double components of a Pythagorean norm (e.g. axis normals) get
//              their exact norm.
//   l1       : |n|_1, exact; >= |n|_2, so the ball is inside too, and the optimum is the centre
//              of the largest inscribed axis-parallel cube of half-side r.
#include <optional>
#include <string_view>

#include "arith/rational.hpp"

namespace cmx::lp {

enum class Norm { l2_upper, l1 };
std::optional<Norm> parse_norm(std::string_view name);  // "l2-upper" or "l1"
std::string_view to_string(Norm norm);

// Requires 2 <= bits <= 53 for the fast path; larger values use MPFR throughout.
Rational l2_upper_weight(const Rational& a, const Rational& b, const Rational& c, unsigned bits = 53);
Rational l1_weight(const Rational& a, const Rational& b, const Rational& c);
Rational row_weight(Norm norm, const Rational& a, const Rational& b, const Rational& c, unsigned bits = 53);

}  // namespace cmx::lp
