#pragma once
// Floating-point expansion arithmetic after J. R. Shewchuk, "Adaptive Precision Floating-Point
// Arithmetic and Fast Robust Geometric Predicates", DCG 18(3), 1997 (written from the paper).
//
// An expansion is an array e[0..n) of doubles whose exact sum is the value it represents, stored
// in increasing order of magnitude and nonoverlapping (the lowest set bit of a larger component is
// above the highest set bit of a smaller one). Zero components are allowed anywhere unless a
// routine says "zeroelim", which promises none except a single 0 for the value zero.
//
// Global preconditions of every routine here (the caller must ensure them):
//  * binary64 arithmetic rounding to nearest, ties to even, no extended precision (x86-64 SSE2);
//  * no fused multiply-add contraction (the project compiles with -ffp-contract=off, and the
//    cmx targets give it to their consumers; tests/kernel/test_fp_contract.cpp and the consumer
//    in tests/install/ fail otherwise), no reassociation (refused by arith/ieee_semantics.hpp);
//  * no overflow, and no underflow in any product (sums are exact under gradual underflow).
// Output buffers must not alias inputs.

#include "arith/ieee_semantics.hpp"

namespace cmx::expansion {

// 2^ceil(53/2) + 1: splits a double into two halves of at most 26 significant bits each.
inline constexpr double splitter = 134217729.0;
// Half an ulp of 1: the unit roundoff of round-to-nearest binary64.
inline constexpr double epsilon = 0x1p-53;

// Fast-Two-Sum (Dekker). Precondition: |a| >= |b| (or a == 0). Then x = fl(a + b) and
// x + y = a + b exactly, |y| <= ulp(x)/2.
inline void fast_two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double b_virtual = x - a;
  y = b - b_virtual;
}

// Two-Sum (Knuth/Møller). No ordering precondition. x = fl(a + b) and x + y = a + b exactly.
inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double b_virtual = x - a;
  const double a_virtual = x - b_virtual;
  const double b_round = b - b_virtual;
  const double a_round = a - a_virtual;
  y = a_round + b_round;
}

// Two-Diff: x = fl(a - b) and x + y = a - b exactly.
inline void two_diff(double a, double b, double& x, double& y) {
  x = a - b;
  const double b_virtual = a - x;
  const double a_virtual = x + b_virtual;
  const double b_round = b_virtual - b;
  const double a_round = a - a_virtual;
  y = a_round + b_round;
}

// The exact error of x = fl(a - b): a - b - x (Two-Diff without recomputing x).
inline double two_diff_tail(double a, double b, double x) {
  const double b_virtual = a - x;
  const double a_virtual = x + b_virtual;
  const double b_round = b_virtual - b;
  const double a_round = a - a_virtual;
  return a_round + b_round;
}

// Split (Dekker/Veltkamp): a = hi + lo exactly, each half with at most 26 significant bits, so
// products of halves are exact. Precondition: |a| * splitter does not overflow (|a| < 2^996).
inline void split(double a, double& hi, double& lo) {
  const double c = splitter * a;
  const double a_big = c - a;
  hi = c - a_big;
  lo = a - hi;
}

// Two-Product with b already split into (b_hi, b_lo). x = fl(a * b), x + y = a * b exactly.
inline void two_product_presplit(double a, double b, double b_hi, double b_lo, double& x, double& y) {
  x = a * b;
  double a_hi, a_lo;
  split(a, a_hi, a_lo);
  const double err1 = x - (a_hi * b_hi);
  const double err2 = err1 - (a_lo * b_hi);
  const double err3 = err2 - (a_hi * b_lo);
  y = (a_lo * b_lo) - err3;
}

// Two-Product (Dekker): x = fl(a * b) and x + y = a * b exactly. Breaks silently if the
// compiler fuses a multiply and a subtraction, hence -ffp-contract=off.
inline void two_product(double a, double b, double& x, double& y) {
  double b_hi, b_lo;
  split(b, b_hi, b_lo);
  two_product_presplit(a, b, b_hi, b_lo, x, y);
}

// (a1 + a0) - b = x2 + x1 + x0 exactly, a nonoverlapping 3-expansion (zeros possible).
// Precondition: a1 + a0 nonoverlapping with |a1| >= |a0|.
inline void two_one_diff(double a1, double a0, double b, double& x2, double& x1, double& x0) {
  double i;
  two_diff(a0, b, i, x0);
  two_sum(a1, i, x2, x1);
}

// (a1 + a0) - (b1 + b0) = x[3] + ... + x[0] exactly (increasing magnitude, zeros possible).
// Preconditions: both inputs nonoverlapping 2-expansions (e.g. outputs of two_product).
inline void two_two_diff(double a1, double a0, double b1, double b0, double x[4]) {
  double j, k;
  two_one_diff(a1, a0, b0, j, k, x[0]);
  two_one_diff(j, k, b1, x[3], x[2], x[1]);
}

// h = e + b (Shewchuk's Grow-Expansion with zero elimination). e: elen >= 0 components,
// nonoverlapping, increasing magnitude. h: room for elen + 1. Returns the length of h (>= 1).
inline int grow_expansion_zeroelim(int elen, const double* e, double b, double* h) {
  double q = b;
  int hlen = 0;
  for (int i = 0; i < elen; ++i) {
    double sum, err;
    two_sum(q, e[i], sum, err);
    q = sum;
    if (err != 0.0) h[hlen++] = err;
  }
  if (q != 0.0 || hlen == 0) h[hlen++] = q;
  return hlen;
}

// h = e + f (Shewchuk's Fast-Expansion-Sum with zero elimination). Merges e and f by magnitude
// and accumulates with Two-Sum. Preconditions: elen + flen >= 1; e and f strongly nonoverlapping
// with increasing magnitude (every output of this file is); h has room for elen + flen and does
// not alias e or f. Returns the length of h (>= 1).
// Unlike the classic code, an input is read only while its index is in range: the published
// version loads e[elen] or f[flen] once one input is exhausted (an ASan error).
inline int fast_expansion_sum_zeroelim(int elen, const double* e, int flen, const double* f, double* h) {
  int ei = 0, fi = 0, hlen = 0;
  // The next input component in order of increasing magnitude.
  auto next = [&]() -> double {
    if (fi >= flen) return e[ei++];
    if (ei >= elen) return f[fi++];
    const double en = e[ei], fn = f[fi];
    if ((fn > en) == (fn > -en)) {  // |fn| > |en|, or a tie resolved towards e
      ++ei;
      return en;
    }
    ++fi;
    return fn;
  };
  const int total = elen + flen;
  double q = next();
  int taken = 1;
  if (taken < total) {
    // The second smallest is at least as large as q, so Fast-Two-Sum is valid.
    const double n = next();
    ++taken;
    double sum, err;
    fast_two_sum(n, q, sum, err);
    q = sum;
    if (err != 0.0) h[hlen++] = err;
  }
  while (taken < total) {
    const double n = next();
    ++taken;
    double sum, err;
    two_sum(q, n, sum, err);
    q = sum;
    if (err != 0.0) h[hlen++] = err;
  }
  if (q != 0.0 || hlen == 0) h[hlen++] = q;
  return hlen;
}

// h = b * e (Shewchuk's Scale-Expansion with zero elimination). e: elen >= 1 components,
// nonoverlapping, increasing magnitude. h: room for 2 * elen. Returns the length of h (>= 1).
inline int scale_expansion_zeroelim(int elen, const double* e, double b, double* h) {
  double b_hi, b_lo;
  split(b, b_hi, b_lo);
  double q, low;
  two_product_presplit(e[0], b, b_hi, b_lo, q, low);
  int hlen = 0;
  if (low != 0.0) h[hlen++] = low;
  for (int i = 1; i < elen; ++i) {
    double p1, p0, sum, err;
    two_product_presplit(e[i], b, b_hi, b_lo, p1, p0);
    two_sum(q, p0, sum, err);
    if (err != 0.0) h[hlen++] = err;
    fast_two_sum(p1, sum, q, err);  // |p1| >= |sum| by nonoverlap of e
    if (err != 0.0) h[hlen++] = err;
  }
  if (q != 0.0 || hlen == 0) h[hlen++] = q;
  return hlen;
}

// h = e * f for a 1- or 2-component f (exact). h: room for 4 * elen; scratch: room for 4 * elen.
inline int multiply_by_short(int elen, const double* e, int flen, const double* f, double* h, double* scratch) {
  if (flen == 1) return scale_expansion_zeroelim(elen, e, f[0], h);
  double* t0 = scratch;
  double* t1 = scratch + 2 * elen;
  const int n0 = scale_expansion_zeroelim(elen, e, f[0], t0);
  const int n1 = scale_expansion_zeroelim(elen, e, f[1], t1);
  return fast_expansion_sum_zeroelim(n0, t0, n1, t1, h);
}

// Negates an expansion in place (exact).
inline void negate(int elen, double* e) {
  for (int i = 0; i < elen; ++i) e[i] = -e[i];
}

// An approximation of the value of e (relative error about elen * epsilon).
inline double estimate(int elen, const double* e) {
  double q = e[0];
  for (int i = 1; i < elen; ++i) q += e[i];
  return q;
}

// The exact sign of a zero-eliminated expansion: that of its largest (last) component.
inline int sign(int elen, const double* e) {
  const double top = e[elen - 1];
  return (top > 0.0) - (top < 0.0);
}

}  // namespace cmx::expansion
