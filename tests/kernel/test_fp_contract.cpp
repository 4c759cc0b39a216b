// Build-flag canary: fused multiply-add contraction (-ffp-contract=fast, the GCC default whenever
// the target has FMA, e.g. -march=native) silently breaks Two-Product and everything built on it.
// These tests fail if the flag is lost (checked: both fail when built with -O2 -march=native
// -ffp-contract=fast on a machine with FMA).
#include <doctest/doctest.h>

#include "arith/expansion.hpp"

namespace {
// Read afresh at every use, so nothing is folded at compile time and two products of the same
// factors are not merged into one before the compiler decides what to fuse.
volatile double va = 1.0 + 0x1p-30, vb = 1.0 + 0x1p-30;
volatile double rounded_product;

double product_minus_rounded() {
  rounded_product = va * vb;
  const double a = va, b = vb, p = rounded_product;
  return a * b - p;  // fused, this is the exact error 2^-60; contracted off, it is 0
}

// Two-Product's error term alone: with the rounded product unused, a compiler allowed to
// contract folds it into the first error step, which then loses it.
double two_product_error(double a, double b) {
  double x, y;
  cmx::expansion::two_product(a, b, x, y);
  return y;
}
}  // namespace

TEST_CASE("no FMA contraction: a*b - fl(a*b) evaluates to 0") {
  // (1 + 2^-30)^2 = 1 + 2^-29 + 2^-60: the 2^-60 is below half an ulp of 1 and is rounded off.
  CHECK(product_minus_rounded() == 0.0);
}

TEST_CASE("Two-Product returns the exact rounding error") {
  const double a = va, b = vb;
  double x, y;
  cmx::expansion::two_product(a, b, x, y);
  CHECK(x == 1.0 + 0x1p-29);
  CHECK(y == 0x1p-60);
  CHECK(two_product_error(va, vb) == 0x1p-60);
  // A product whose error is negative: (2^53 - 1)(2^53 - 1) = 2^106 - 2^54 + 1.
  volatile double m = 0x1p53 - 1;
  cmx::expansion::two_product(m, m, x, y);
  CHECK(x == 0x1p106 - 0x1p54);
  CHECK(y == 1.0);
  CHECK(two_product_error(m, m) == 1.0);
}
