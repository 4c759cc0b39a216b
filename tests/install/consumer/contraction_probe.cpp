// Built without any cmx target, so with the consumer's own flags only.
#include "contraction_probe.hpp"

namespace {
// Read afresh at every use, so the two products below are not merged into one.
volatile double factor = 1.0 + 0x1p-30;
volatile double rounded_square;
}  // namespace

bool consumer_flags_contract() {
  rounded_square = factor * factor;
  const double a = factor, b = factor, p = rounded_square;
  // (1 + 2^-30)^2 = 1 + 2^-29 + 2^-60 rounds to 1 + 2^-29; fused, a*b - p is the 2^-60 lost.
  return a * b - p != 0.0;
}
