// Build-flag canary: fused multiply-add contraction (-ffp-contract=fast, the GCC default whenever
// the target has FMA, e.g. -march=native) silently breaks Two-Product and every error bound of
// the filters. These tests fail if the flag is lost.
#include <doctest/doctest.h>

#include "arith/expansion.hpp"

namespace {
// Opaque inputs so nothing is folded at compile time.
volatile double va = 1.0 + 0x1p-30, vb = 1.0 + 0x1p-30;

double product_minus_rounded(double a, double b) {
  const double p = a * b;
  return a * b - p;  // fused, this is the exact error 2^-60; contracted off, it is 0
}
}  // namespace

TEST_CASE("no FMA contraction: a*b - fl(a*b) evaluates to 0") {
  const double a = va, b = vb;
  // (1 + 2^-30)^2 = 1 + 2^-29 + 2^-60: the 2^-60 is below half an ulp of 1 and is rounded off.
  CHECK(product_minus_rounded(a, b) == 0.0);
}

TEST_CASE("Two-Product returns the exact rounding error") {
  const double a = va, b = vb;
  double x, y;
  cmx::expansion::two_product(a, b, x, y);
  CHECK(x == 1.0 + 0x1p-29);
  CHECK(y == 0x1p-60);
  // A product whose error is negative: (2^53 - 1)(2^53 - 1) = 2^106 - 2^54 + 1.
  volatile double m = 0x1p53 - 1;
  cmx::expansion::two_product(m, m, x, y);
  CHECK(x == 0x1p106 - 0x1p54);
  CHECK(y == 1.0);
}
