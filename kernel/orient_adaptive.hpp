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
//
// Header-only (inline), so that kernel/orient_standalone.hpp can offer the double predicates with
// no compiled library.
#include <cmath>

#include "arith/expansion.hpp"
#include "arith/sign.hpp"

namespace cmx::adaptive {

inline constexpr double min_magnitude = 0x1p-250, max_magnitude = 0x1p250;

namespace detail {

using namespace cmx::expansion;  // NOLINT: the error-free transforms, read as in the paper
constexpr double eps = epsilon;
// Shewchuk's error-bound coefficients (DCG 1997, section 4.3), in units of the permanent.
constexpr double o3d_bound_a = (7.0 + 56.0 * eps) * eps;
constexpr double o3d_bound_b = (3.0 + 28.0 * eps) * eps;
constexpr double o3d_bound_c = (26.0 + 288.0 * eps) * eps * eps;
constexpr double o2d_bound_a = (3.0 + 16.0 * eps) * eps;
constexpr double o2d_bound_b = (2.0 + 12.0 * eps) * eps;
constexpr double o2d_bound_c = (9.0 + 64.0 * eps) * eps * eps;
// Relative error of an expansion's estimate, charged in stage C.
constexpr double result_bound = (3.0 + 8.0 * eps) * eps;

inline Sign sign_of_double(double x) {
  return x > 0 ? Sign::positive : x < 0 ? Sign::negative : Sign::zero;
}

// Reports the deciding stage (0..3 for A..D) to the caller, which counts it.
inline void report(int* decided_by, int stage) {
  if (decided_by) *decided_by = stage;
}

// The sign of det when |det| >= bound, the stage's certificate (reported as `stage`); else none.
inline UncertainSign certified(double det, double bound, int* stage_out, int stage) {
  if (!(det >= bound || -det >= bound)) return std::nullopt;
  report(stage_out, stage);
  return sign_of_double(det);
}

// The exact difference head + tail as a zero-eliminated expansion of length 1 or 2.
inline int exact_difference(double head, double tail, double* e) {
  if (tail == 0.0) {
    e[0] = head;
    return 1;
  }
  e[0] = tail;
  e[1] = head;
  return 2;
}

// p * q - r * s exactly, for expansions of length <= 2. h: room for 16.
inline int minor2(const double* p, int pn, const double* q, int qn, const double* r, int rn, const double* s,
                  int sn, double* h) {
  double pq[8], rs[8], scratch[8];
  const int n1 = multiply_by_short(pn, p, qn, q, pq, scratch);
  const int n2 = multiply_by_short(rn, r, sn, s, rs, scratch);
  negate(n2, rs);
  return fast_expansion_sum_zeroelim(n1, pq, n2, rs, h);
}

// Stage D of orient3d: the exact determinant of the exact differences U, V, W.
inline Sign orient3d_exact_stage(const double* ux, int uxn, const double* uy, int uyn, const double* uz,
                                 int uzn, const double* vx, int vxn, const double* vy, int vyn,
                                 const double* vz, int vzn, const double* wx, int wxn, const double* wy,
                                 int wyn, const double* wz, int wzn) {
  double m[16], scratch[64], tx[64], ty[64], tz[64], txy[128], all[192];
  int mn = minor2(vy, vyn, wz, wzn, vz, vzn, wy, wyn, m);
  const int nx = multiply_by_short(mn, m, uxn, ux, tx, scratch);
  mn = minor2(vz, vzn, wx, wxn, vx, vxn, wz, wzn, m);
  const int ny = multiply_by_short(mn, m, uyn, uy, ty, scratch);
  mn = minor2(vx, vxn, wy, wyn, vy, vyn, wx, wxn, m);
  const int nz = multiply_by_short(mn, m, uzn, uz, tz, scratch);
  const int nxy = fast_expansion_sum_zeroelim(nx, tx, ny, ty, txy);
  const int n = fast_expansion_sum_zeroelim(nxy, txy, nz, tz, all);
  return Sign(expansion::sign(n, all));
}

// Stages B, C and D, entered when stage A could not decide.
inline Sign orient3d_stages_bcd(const double* a, const double* b, const double* c, const double* d,
                                double permanent, int* stage_out) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];

  // Stage B: the 2x2 minors of the rounded differences as exact 4-expansions, then
  // B = ux mx + uy my + uz mz exactly (<= 24 components).
  double mx[4], my[4], mz[4], p1, p0, q1, q0;
  two_product(vy, wz, p1, p0);
  two_product(vz, wy, q1, q0);
  two_two_diff(p1, p0, q1, q0, mx);
  two_product(vz, wx, p1, p0);
  two_product(vx, wz, q1, q0);
  two_two_diff(p1, p0, q1, q0, my);
  two_product(vx, wy, p1, p0);
  two_product(vy, wx, q1, q0);
  two_two_diff(p1, p0, q1, q0, mz);
  double tx[8], ty[8], tz[8], txy[16], bexp[24];
  const int nx = scale_expansion_zeroelim(4, mx, ux, tx);
  const int ny = scale_expansion_zeroelim(4, my, uy, ty);
  const int nz = scale_expansion_zeroelim(4, mz, uz, tz);
  const int nxy = fast_expansion_sum_zeroelim(nx, tx, ny, ty, txy);
  const int nb = fast_expansion_sum_zeroelim(nxy, txy, nz, tz, bexp);
  double det = estimate(nb, bexp);
  const double bound_b = o3d_bound_b * permanent;
  if (const UncertainSign s = certified(det, bound_b, stage_out, 1)) return *s;

  const double uxt = two_diff_tail(b[0], a[0], ux), uyt = two_diff_tail(b[1], a[1], uy);
  const double uzt = two_diff_tail(b[2], a[2], uz), vxt = two_diff_tail(c[0], a[0], vx);
  const double vyt = two_diff_tail(c[1], a[1], vy), vzt = two_diff_tail(c[2], a[2], vz);
  const double wxt = two_diff_tail(d[0], a[0], wx), wyt = two_diff_tail(d[1], a[1], wy);
  const double wzt = two_diff_tail(d[2], a[2], wz);
  if (uxt == 0.0 && uyt == 0.0 && uzt == 0.0 && vxt == 0.0 && vyt == 0.0 && vzt == 0.0 && wxt == 0.0 &&
      wyt == 0.0 && wzt == 0.0) {
    // No difference was rounded: B is the exact determinant.
    report(stage_out, 1);
    return Sign(expansion::sign(nb, bexp));
  }

  // Stage C: add the first-order effect of the tails, d(u . (v x w)), in doubles.
  const double bound_c = o3d_bound_c * permanent + result_bound * std::fabs(det);
  det += (ux * ((vy * wzt + wz * vyt) - (vz * wyt + wy * vzt)) + uxt * (vy * wz - vz * wy)) +
         (uy * ((vz * wxt + wx * vzt) - (vx * wzt + wz * vxt)) + uyt * (vz * wx - vx * wz)) +
         (uz * ((vx * wyt + wy * vxt) - (vy * wxt + wx * vyt)) + uzt * (vx * wy - vy * wx));
  if (const UncertainSign s = certified(det, bound_c, stage_out, 2)) return *s;

  // Stage D: exact, on the exact differences head + tail.
  double eux[2], euy[2], euz[2], evx[2], evy[2], evz[2], ewx[2], ewy[2], ewz[2];
  const int nux = exact_difference(ux, uxt, eux), nuy = exact_difference(uy, uyt, euy);
  const int nuz = exact_difference(uz, uzt, euz), nvx = exact_difference(vx, vxt, evx);
  const int nvy = exact_difference(vy, vyt, evy), nvz = exact_difference(vz, vzt, evz);
  const int nwx = exact_difference(wx, wxt, ewx), nwy = exact_difference(wy, wyt, ewy);
  const int nwz = exact_difference(wz, wzt, ewz);
  report(stage_out, 3);
  return orient3d_exact_stage(eux, nux, euy, nuy, euz, nuz, evx, nvx, evy, nvy, evz, nvz, ewx, nwx, ewy, nwy,
                              ewz, nwz);
}

inline Sign orient2d_stages_bcd(const double* a, const double* b, const double* c, double detsum,
                                int* stage_out) {
  const double ux = b[0] - a[0], uy = b[1] - a[1];
  const double vx = c[0] - a[0], vy = c[1] - a[1];
  double p1, p0, q1, q0, bexp4[4], bexp[5];
  two_product(ux, vy, p1, p0);
  two_product(uy, vx, q1, q0);
  two_two_diff(p1, p0, q1, q0, bexp4);
  const int nb = grow_expansion_zeroelim(4, bexp4, 0.0, bexp);  // drop zeros for sign()
  double det = estimate(nb, bexp);
  const double bound_b = o2d_bound_b * detsum;
  if (const UncertainSign s = certified(det, bound_b, stage_out, 1)) return *s;
  const double uxt = two_diff_tail(b[0], a[0], ux), uyt = two_diff_tail(b[1], a[1], uy);
  const double vxt = two_diff_tail(c[0], a[0], vx), vyt = two_diff_tail(c[1], a[1], vy);
  if (uxt == 0.0 && uyt == 0.0 && vxt == 0.0 && vyt == 0.0) {
    report(stage_out, 1);
    return Sign(expansion::sign(nb, bexp));
  }
  const double bound_c = o2d_bound_c * detsum + result_bound * std::fabs(det);
  det += (ux * vyt + vy * uxt) - (uy * vxt + vx * uyt);
  if (const UncertainSign s = certified(det, bound_c, stage_out, 2)) return *s;
  double eux[2], euy[2], evx[2], evy[2], h[16];
  const int nux = exact_difference(ux, uxt, eux), nuy = exact_difference(uy, uyt, euy);
  const int nvx = exact_difference(vx, vxt, evx), nvy = exact_difference(vy, vyt, evy);
  const int n = minor2(eux, nux, evy, nvy, euy, nuy, evx, nvx, h);
  report(stage_out, 3);
  return Sign(expansion::sign(n, h));
}

}  // namespace detail

// True when all `count` coordinates satisfy the precondition above (false for NaN or infinity).
inline bool in_adaptive_range(const double* coordinates, int count) {
  for (int i = 0; i < count; ++i) {
    const double m = std::fabs(coordinates[i]);
    if (m == 0.0) continue;
    if (!(m >= min_magnitude && m <= max_magnitude)) return false;  // also NaN and infinity
  }
  return true;
}

// Exact sign of det[b-a, c-a, d-a]; stores the deciding stage (0..3 for A..D) in *stage_out unless
// stage_out is null.
inline Sign orient3d(const double* a, const double* b, const double* c, const double* d, int* stage_out) {
  // Stage A.
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
  const double vywz = vy * wz, vzwy = vz * wy, vzwx = vz * wx, vxwz = vx * wz, vxwy = vx * wy, vywx = vy * wx;
  const double det = ux * (vywz - vzwy) + uy * (vzwx - vxwz) + uz * (vxwy - vywx);
  const double permanent = (std::fabs(vywz) + std::fabs(vzwy)) * std::fabs(ux) +
                           (std::fabs(vzwx) + std::fabs(vxwz)) * std::fabs(uy) +
                           (std::fabs(vxwy) + std::fabs(vywx)) * std::fabs(uz);
  const double bound_a = detail::o3d_bound_a * permanent;
  if (det > bound_a || -det > bound_a) {
    detail::report(stage_out, 0);
    return detail::sign_of_double(det);
  }
  return detail::orient3d_stages_bcd(a, b, c, d, permanent, stage_out);
}

// Exact sign of det[b-a, c-a] on x and y; the deciding stage as for orient3d.
inline Sign orient2d(const double* a, const double* b, const double* c, int* stage_out) {
  const double ux = b[0] - a[0], uy = b[1] - a[1];
  const double vx = c[0] - a[0], vy = c[1] - a[1];
  const double left = ux * vy, right = uy * vx;
  const double det = left - right;
  const double detsum = std::fabs(left) + std::fabs(right);
  const double bound_a = detail::o2d_bound_a * detsum;
  if (det > bound_a || -det > bound_a) {
    detail::report(stage_out, 0);
    return detail::sign_of_double(det);
  }
  return detail::orient2d_stages_bcd(a, b, c, detsum, stage_out);
}

}  // namespace cmx::adaptive
