#pragma once
// An interval [lo, hi] of MPFR floating-point numbers with a precision chosen at run time: lower
// bounds are rounded with MPFR_RNDD, upper bounds with MPFR_RNDU, so no hardware rounding mode is
// involved. Used as an optional middle tier for precision studies (policy "mpfr:BITS"); measured
// slower than the exact homogeneous determinant below ~512-bit data.
//
// Enclosure property: if x in a and y in b then x op y in a op b (exact reals). Operation results
// get the larger precision of the two operands. Bounds are never NaN for finite inputs.
#include <mpfr.h>

#include "arith/rational.hpp"
#include "arith/sign.hpp"

namespace cmx {

class MpfrInterval {
 public:
  static constexpr mpfr_prec_t default_precision = 53;

  explicit MpfrInterval(mpfr_prec_t bits = default_precision);
  MpfrInterval(double point, mpfr_prec_t bits);          // exact when bits >= 53
  MpfrInterval(const Rational& q, mpfr_prec_t bits);     // tightest enclosure at `bits`
  MpfrInterval(const MpfrInterval& other);
  MpfrInterval(MpfrInterval&& other) noexcept;
  MpfrInterval& operator=(const MpfrInterval& other);
  MpfrInterval& operator=(MpfrInterval&& other) noexcept;
  ~MpfrInterval();

  mpfr_prec_t precision() const { return mpfr_get_prec(lo_); }
  const __mpfr_struct* lo() const { return lo_; }
  const __mpfr_struct* hi() const { return hi_; }
  double lo_double() const { return mpfr_get_d(lo_, MPFR_RNDD); }
  double hi_double() const { return mpfr_get_d(hi_, MPFR_RNDU); }

  // Certain sign, or nullopt when the interval contains 0 without being [0, 0].
  UncertainSign sign() const;
  // True when the exact rational q lies in [lo, hi].
  bool contains(const Rational& q) const;

  friend MpfrInterval operator+(const MpfrInterval& a, const MpfrInterval& b);
  friend MpfrInterval operator-(const MpfrInterval& a, const MpfrInterval& b);
  friend MpfrInterval operator*(const MpfrInterval& a, const MpfrInterval& b);
  friend MpfrInterval operator-(const MpfrInterval& a);

 private:
  bool valid() const { return lo_->_mpfr_d != nullptr; }
  mpfr_t lo_, hi_;
};

}  // namespace cmx
