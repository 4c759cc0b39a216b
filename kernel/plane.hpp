#pragma once
// Oriented planes through three exact points, in homogeneous integer form, for building the
// half-spaces of linear programs (expansion cones, boundary kernels) without forming rationals.
//
// For points p, q, r (homogeneous rows (X, Y, Z, W), W > 0) the linear form
//   L(x) = det4[p; q; r; x] = a X + b Y + c Z + d W
// has orient3d(p, q, r, x) = -sign(L(x)) (kernel/orient_exact.cpp). So the open half-space
//   { x : orient3d(p, q, r, x) < 0 }  =  { x : -a x - b y - c z < d }
// is the "inner" side: when (p, q, r) is a face of a positively oriented tetrahedron listed with
// its normal pointing outward (topology::tet_face), the opposite vertex lies there.
#include <array>
#include <vector>

#include "arith/rational.hpp"
#include "kernel/homogeneous_point.hpp"

namespace cmx {

// Integer coefficients (u, w): the inner open half-space of the oriented triangle (p, q, r) is
// u . (x, y, z) < w. All four are zero exactly when p, q, r are collinear (no plane).
struct InnerHalfSpace {
  std::array<Integer, 3> u;
  Integer w;
  bool is_degenerate() const { return sgn(u[0]) == 0 && sgn(u[1]) == 0 && sgn(u[2]) == 0; }
};

InnerHalfSpace inner_halfspace(const HPoint& p, const HPoint& q, const HPoint& r);

// Sign of u . x - w at an exact point: negative = strictly inside.
Sign side_of(const InnerHalfSpace& h, const HPoint& x);

// Exact proof that two to four open half-spaces have no common point, by a Motzkin certificate:
// y >= 0, y != 0 with sum y_i u_i = 0 and sum y_i w_i <= 0 (a common x would give
// 0 = sum y_i u_i . x < sum y_i w_i <= 0). The candidate y is the nullspace vector of the normals
// (cofactors for four, the triple-product identity for three coplanar ones, the ratio for two
// opposite ones), and every condition is then checked exactly. False means "not proved": the
// half-spaces may still have no common point (e.g. when the normals have a larger nullspace).
bool proves_no_common_point(const std::vector<InnerHalfSpace>& hs);

}  // namespace cmx
