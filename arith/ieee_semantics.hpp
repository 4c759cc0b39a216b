#pragma once
// Included by every header whose inline floating-point code is correct only under IEEE 754
// semantics: the error-free transforms (arith/expansion.hpp), the filters' error bounds
// (kernel/orient_semistatic.hpp) and directed rounding (arith/interval.hpp).
//
// The cmx targets bring -ffp-contract=off -frounding-math to everything that links them
// (cmake/CmxFlags.cmake), after the consumer's own flags, so those are taken care of. What such
// flags cannot undo is refused here: reassociation rewrites Two-Sum's (a + b) - a into b, and
// finite-only arithmetic drops the checks that keep NaN and overflow from yielding a sign.
#if defined(__FAST_MATH__) || defined(__ASSOCIATIVE_MATH__) || (defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__)
#error "cmx needs IEEE 754 floating-point semantics: compile without -ffast-math, -funsafe-math-optimizations, -fassociative-math and -ffinite-math-only"
#endif
