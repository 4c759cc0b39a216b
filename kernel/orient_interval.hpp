#pragma once
// Tiers 2 and 3 of the cascade: interval evaluations of the orientation determinants.
// Each returns the certain sign or nullopt (then a more precise tier must decide).
//
// Double interval: evaluated on the cached per-coordinate enclosures of HPoint (no GMP), in one
// upward-rounding scope (arith/interval.hpp); returns nullopt when an enclosure is not finite
// (a coordinate beyond the double range). MPFR interval: evaluated on the exact coordinates
// rounded outward to `bits` bits (GMP/MPFR; slow, for precision studies).
#include "arith/sign.hpp"
#include "kernel/homogeneous_point.hpp"

namespace cmx {

UncertainSign orient3d_interval(const HPoint& a, const HPoint& b, const HPoint& c, const HPoint& d);
UncertainSign orient2d_interval(const HPoint& a, const HPoint& b, const HPoint& c);
// On finite doubles taken as point intervals (nullopt for NaN or infinity).
UncertainSign orient3d_interval(const double* a, const double* b, const double* c, const double* d);
UncertainSign orient2d_interval(const double* a, const double* b, const double* c);

// bits >= 2.
UncertainSign orient3d_mpfr(const HPoint& a, const HPoint& b, const HPoint& c, const HPoint& d, long bits);
UncertainSign orient2d_mpfr(const HPoint& a, const HPoint& b, const HPoint& c, long bits);

}  // namespace cmx
