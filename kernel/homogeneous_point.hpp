#pragma once
// Exact points in homogeneous integer coordinates (X, Y, Z, W): the point (X/W, Y/W, Z/W).
// Canonical: W > 0 and gcd(X, Y, Z, W) = 1, so equal points have equal representations.
// Each coordinate carries a cached double enclosure [lo, hi] (a single double when the
// coordinate is exactly a double), so filters run without touching GMP.
#include <array>

#include "arith/rational.hpp"
#include "arith/rounding.hpp"

namespace cmx {

class HPoint {
 public:
  HPoint();  // the origin
  // From exact rationals (any denominators).
  HPoint(const Rational& x, const Rational& y, const Rational& z);
  // From finite doubles; throws std::domain_error on NaN or infinity.
  static HPoint from_doubles(double x, double y, double z);
  // From homogeneous integers with w != 0 (normalised to canonical form).
  static HPoint from_homogeneous(Integer x, Integer y, Integer z, Integer w);

  const Integer& X() const { return c_[0]; }
  const Integer& Y() const { return c_[1]; }
  const Integer& Z() const { return c_[2]; }
  const Integer& W() const { return c_[3]; }
  const Integer& h(int i) const { return c_[i]; }  // i in 0..3

  Rational coordinate(int axis) const;  // exact X/W, Y/W or Z/W
  const DoubleEnclosure& enclosure(int axis) const { return box_[axis]; }
  // True when all three coordinates are doubles (enclosures are points).
  bool is_double() const { return is_double_; }
  // The nearest doubles (only meaningful as an approximation unless is_double()).
  std::array<double, 3> approx() const;

  // Bits of the largest of X, Y, Z, W: the size measure used in precision studies.
  std::size_t bit_size() const;

  friend bool operator==(const HPoint& a, const HPoint& b) { return a.c_ == b.c_; }

 private:
  void canonicalize_and_cache();
  std::array<Integer, 4> c_;
  std::array<DoubleEnclosure, 3> box_{};
  bool is_double_ = true;
};

// Convex combination sum_i weights[i] * points[i] (2 to 4 points); the weights must be
// non-negative and sum to 1 (throws std::invalid_argument otherwise). Exact.
HPoint convex_combination(const HPoint* points, const Rational* weights, int count);
HPoint midpoint(const HPoint& a, const HPoint& b);

}  // namespace cmx
