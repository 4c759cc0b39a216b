#pragma once
// Correctly rounded conversions of exact rationals to binary floating point.
#include <cstdint>

#include "arith/rational.hpp"

namespace cmx {

// The four IEEE 754 rounding directions.
enum class Round { nearest_even, toward_zero, upward, downward };

// The double nearest to q in direction `dir` (correct rounding, including subnormals).
// Overflow gives +-infinity or +-DBL_MAX as IEEE 754 prescribes for the direction.
double to_double(const Rational& q, Round dir = Round::nearest_even);

// A dyadic number m * 2^e with |m| < 2^k (at most k significant bits), exact.
struct Dyadic {
  Integer mantissa;
  long exponent = 0;
  Rational value() const;
};

// q rounded to at most k significant bits (k >= 1) in direction `dir`, with unbounded exponent.
Dyadic round_to_dyadic(const Rational& q, unsigned k, Round dir = Round::nearest_even);

// Encloses q: lo <= q <= hi with lo, hi adjacent doubles (or lo == hi when q is a double).
struct DoubleEnclosure {
  double lo, hi;
  bool is_point() const { return lo == hi; }
};
DoubleEnclosure enclose(const Rational& q);

}  // namespace cmx
