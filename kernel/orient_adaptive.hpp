#pragma once
// Tier 1b of the cascade: Shewchuk's adaptive orientation predicates on double inputs, written
// from his paper (DCG 18(3), 1997, section 4) on the expansion arithmetic of arith/expansion.hpp.
// Sign convention: det[b-a, c-a, d-a] (the opposite of Shewchuk's orient3d(a, b, c, d)).
//
// Stages: A, the double determinant with an a-priori bound relative to the permanent; B, the
// exact determinant of the rounded differences (exact outright when no difference was rounded);
// C, B's estimate plus the first-order effect of the difference round-off; D, fully exact.
// Each stage decides only when its proven bound certifies the sign, so the result is always exact.
//
// Precondition (in_adaptive_range): every coordinate is 0 or has magnitude in [2^-250, 2^250].
// Then every nonzero coordinate, difference, round-off tail and product of up to three of them is
// a multiple of 2^-906 and below 2^760, so no operation overflows or underflows and the bounds
// hold. Outside the range the caller must use another tier (the cascade uses the exact one).
#include "arith/sign.hpp"
#include "kernel/filter_policy.hpp"

namespace cmx::adaptive {

inline constexpr double min_magnitude = 0x1p-250, max_magnitude = 0x1p250;

// True when all `count` coordinates satisfy the precondition above (false for NaN or infinity).
bool in_adaptive_range(const double* coordinates, int count);

// Exact sign of det[b-a, c-a, d-a]; counts the deciding stage in stats->adaptive[0..3].
Sign orient3d(const double* a, const double* b, const double* c, const double* d, FilterStats* stats);
// Exact sign of det[b-a, c-a] on x and y.
Sign orient2d(const double* a, const double* b, const double* c, FilterStats* stats);

}  // namespace cmx::adaptive
