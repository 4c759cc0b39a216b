#pragma once
// Tier 1a of the cascade: semi-static orientation filters on double inputs (after CGAL's
// Static_filters/Orientation_3; Melquiond & Pion 2007). Inline: this is the hot path.
//
// Error bound for orient3d, derived here (u = 2^-53 the unit roundoff, gamma_k = k u/(1 - k u)):
// evaluate det[b-a, c-a, d-a] as in kernel/determinant.hpp. Each difference is rounded once
// (relative error <= u; exact under gradual underflow). The determinant is a signed sum of six
// triple products x_i y_j z_k, one coordinate per axis. Following one triple product through the
// evaluation: 3 difference roundings, the 2x2 minor's product and subtraction (2), the product
// with u_* (1), and the final two additions (2 for the terms of u_x m_x and u_y m_y, 1 for
// u_z m_z). So four terms carry 8 roundings and two carry 7, and the standard bound on products of
// (1 + delta_i) gives
//     |det_computed - det_exact| <= (4 gamma_8 + 2 gamma_7) * Mx*My*Mz / (1 - u)^3,
// where Mx (My, Mz) is the largest |computed difference| along x (y, z); the (1 - u)^-3 converts
// true differences to computed ones. That is 46 u (1 + O(u)) = 5.1070259e-15 * Mx*My*Mz.
// We use CGAL's published constant 5.1107127829973299e-15 (also TetGen's and geogram's), which
// exceeds our bound by a relative 7.2e-4: far more than the O(u) terms, the three roundings when
// computing eps itself, and the absolute underflow errors allowed by the guards below
// (each <= 2^-1074 times at most one factor Mx: negligible because all of Mx, My, Mz >= 1e-97).
// The static_assert below checks the inequality with the O(u) terms included.
//
// Guards: the filter only decides when every max is in [1e-97, 1e102] (no overflow of the triple
// products, eps normal), or when one axis has all differences zero (the determinant then has a
// zero row and is exactly 0: fl(p - q) == 0 iff p == q). NaN or infinite inputs never yield a
// decision (NaN/inf differences make det non-finite or a guard fail).
//
// orient2d: two products x_i y_j; each carries 2 difference roundings, 1 product
// and 1 subtraction: 2 gamma_4 = 8 u (1 + O(u)); CGAL's 8.8872057372592798e-16 exceeds it by 9e-4
// relative. Guards [1e-146, 1e153] keep the product and eps normal and finite.
#include <algorithm>
#include <cmath>

#include "arith/ieee_semantics.hpp"
#include "arith/sign.hpp"

namespace cmx::semistatic {

inline constexpr double u = 0x1p-53;
constexpr double gamma(int k) { return k * u / (1 - k * u); }
inline constexpr double orient3d_eps = 5.1107127829973299e-15;
inline constexpr double orient2d_eps = 8.8872057372592798e-16;
// Our derived bounds, with slack (1 + 8u) for computing eps = C * Mx * My * Mz in doubles.
static_assert(orient3d_eps >= (4 * gamma(8) + 2 * gamma(7)) / ((1 - u) * (1 - u) * (1 - u)) * (1 + 8 * u));
static_assert(orient2d_eps >= 2 * gamma(4) / ((1 - u) * (1 - u)) * (1 + 8 * u));

// Sign of det[b-a, c-a, d-a] if the filter can certify it, else nullopt.
inline UncertainSign orient3d(const double* a, const double* b, const double* c, const double* d) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
  const double mx = vy * wz - vz * wy;
  const double my = vz * wx - vx * wz;
  const double mz = vx * wy - vy * wx;
  const double det = ux * mx + uy * my + uz * mz;

  // Branch-free maxima (maxsd/minsd). std::max(x, y) returns x when y is NaN, so NaN may be
  // dropped here; a NaN input still makes det NaN, and NaN never passes the tests below.
  const double maxx = std::max(std::max(std::fabs(ux), std::fabs(vx)), std::fabs(wx));
  const double maxy = std::max(std::max(std::fabs(uy), std::fabs(vy)), std::fabs(wy));
  const double maxz = std::max(std::max(std::fabs(uz), std::fabs(vz)), std::fabs(wz));
  const double lo = std::min(std::min(maxx, maxy), maxz), hi = std::max(std::max(maxx, maxy), maxz);
  if (lo < 1e-97 || !(hi < 1e102)) {  // !(hi < ...) also rejects infinity
    // An all-zero axis: a zero column, det = 0 exactly. isfinite(det) rejects NaN/inf inputs,
    // which the maxima may hide.
    if (lo == 0 && hi < 1e102 && std::isfinite(det)) return Sign::zero;
    return std::nullopt;
  }
  const double eps = orient3d_eps * maxx * maxy * maxz;
  if (det > eps) return Sign::positive;
  if (det < -eps) return Sign::negative;
  return std::nullopt;
}

// Sign of det[b-a, c-a] (x and y only) if the filter can certify it, else nullopt.
inline UncertainSign orient2d(const double* a, const double* b, const double* c) {
  const double ux = b[0] - a[0], uy = b[1] - a[1];
  const double vx = c[0] - a[0], vy = c[1] - a[1];
  const double det = ux * vy - uy * vx;
  const double maxx = std::fmax(std::fabs(ux), std::fabs(vx));
  const double maxy = std::fmax(std::fabs(uy), std::fabs(vy));
  const double lo = std::fmin(maxx, maxy), hi = std::fmax(maxx, maxy);
  if (!std::isfinite(det)) return std::nullopt;
  if (lo < 1e-146) {
    if (lo == 0 && hi < 1e153) return Sign::zero;
    return std::nullopt;
  }
  if (!(hi < 1e153)) return std::nullopt;
  const double eps = orient2d_eps * maxx * maxy;
  if (det > eps) return Sign::positive;
  if (det < -eps) return Sign::negative;
  return std::nullopt;
}

}  // namespace cmx::semistatic
