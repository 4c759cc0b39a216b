#pragma once
// The exact tier of the predicate cascade: orientation signs on homogeneous integers.
#include "arith/sign.hpp"
#include "kernel/homogeneous_point.hpp"

namespace cmx {

// Sign of det[b-a, c-a, d-a]: positive when (a, b, c, d) is a positively oriented tetrahedron
// (d on the side of plane abc that the right-hand normal (b-a) x (c-a) points to). Exact.
Sign orient3d_exact(const HPoint& a, const HPoint& b, const HPoint& c, const HPoint& d);

// Sign of det[b-a, c-a] on the x and y coordinates (z ignored). Exact.
Sign orient2d_exact(const HPoint& a, const HPoint& b, const HPoint& c);

}  // namespace cmx
