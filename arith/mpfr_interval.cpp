#include "arith/mpfr_interval.hpp"

#include <algorithm>
#include <utility>

namespace cmx {

MpfrInterval::MpfrInterval(mpfr_prec_t bits) {
  mpfr_init2(lo_, bits);
  mpfr_init2(hi_, bits);
  mpfr_set_zero(lo_, 1);
  mpfr_set_zero(hi_, 1);
}

MpfrInterval::MpfrInterval(double point, mpfr_prec_t bits) {
  mpfr_init2(lo_, bits);
  mpfr_init2(hi_, bits);
  mpfr_set_d(lo_, point, MPFR_RNDD);
  mpfr_set_d(hi_, point, MPFR_RNDU);
}

MpfrInterval::MpfrInterval(const Rational& q, mpfr_prec_t bits) {
  mpfr_init2(lo_, bits);
  mpfr_init2(hi_, bits);
  mpfr_set_q(lo_, q.get_mpq_t(), MPFR_RNDD);
  mpfr_set_q(hi_, q.get_mpq_t(), MPFR_RNDU);
}

MpfrInterval::MpfrInterval(const MpfrInterval& other) {
  mpfr_init2(lo_, other.precision());
  mpfr_init2(hi_, other.precision());
  mpfr_set(lo_, other.lo_, MPFR_RNDD);
  mpfr_set(hi_, other.hi_, MPFR_RNDU);
}

// A moved-from interval keeps no limbs (its _mpfr_d is null): it may only be destroyed or
// assigned to.
MpfrInterval::MpfrInterval(MpfrInterval&& other) noexcept {
  *lo_ = *other.lo_;
  *hi_ = *other.hi_;
  other.lo_->_mpfr_d = nullptr;
  other.hi_->_mpfr_d = nullptr;
}

MpfrInterval& MpfrInterval::operator=(const MpfrInterval& other) {
  if (this != &other) {
    if (valid()) {
      mpfr_set_prec(lo_, other.precision());
      mpfr_set_prec(hi_, other.precision());
    } else {
      mpfr_init2(lo_, other.precision());
      mpfr_init2(hi_, other.precision());
    }
    mpfr_set(lo_, other.lo_, MPFR_RNDD);
    mpfr_set(hi_, other.hi_, MPFR_RNDU);
  }
  return *this;
}

MpfrInterval& MpfrInterval::operator=(MpfrInterval&& other) noexcept {
  std::swap(*lo_, *other.lo_);
  std::swap(*hi_, *other.hi_);
  return *this;
}

MpfrInterval::~MpfrInterval() {
  if (valid()) {
    mpfr_clear(lo_);
    mpfr_clear(hi_);
  }
}

UncertainSign MpfrInterval::sign() const {
  if (mpfr_nan_p(lo_) || mpfr_nan_p(hi_)) return std::nullopt;
  if (mpfr_sgn(lo_) > 0) return Sign::positive;
  if (mpfr_sgn(hi_) < 0) return Sign::negative;
  if (mpfr_zero_p(lo_) && mpfr_zero_p(hi_)) return Sign::zero;
  return std::nullopt;
}

bool MpfrInterval::contains(const Rational& q) const {
  return mpfr_cmp_q(lo_, q.get_mpq_t()) <= 0 && mpfr_cmp_q(hi_, q.get_mpq_t()) >= 0;
}

static mpfr_prec_t joint_precision(const MpfrInterval& a, const MpfrInterval& b) {
  return std::max(a.precision(), b.precision());
}

MpfrInterval operator+(const MpfrInterval& a, const MpfrInterval& b) {
  MpfrInterval r(joint_precision(a, b));
  mpfr_add(r.lo_, a.lo_, b.lo_, MPFR_RNDD);
  mpfr_add(r.hi_, a.hi_, b.hi_, MPFR_RNDU);
  return r;
}

MpfrInterval operator-(const MpfrInterval& a, const MpfrInterval& b) {
  MpfrInterval r(joint_precision(a, b));
  mpfr_sub(r.lo_, a.lo_, b.hi_, MPFR_RNDD);
  mpfr_sub(r.hi_, a.hi_, b.lo_, MPFR_RNDU);
  return r;
}

MpfrInterval operator-(const MpfrInterval& a) {
  MpfrInterval r(a.precision());
  mpfr_neg(r.lo_, a.hi_, MPFR_RNDD);  // exact at equal precision
  mpfr_neg(r.hi_, a.lo_, MPFR_RNDU);
  return r;
}

MpfrInterval operator*(const MpfrInterval& a, const MpfrInterval& b) {
  // The extremes are among the four corner products; each is rounded both ways.
  const mpfr_prec_t p = joint_precision(a, b);
  MpfrInterval r(p);
  mpfr_t t;
  mpfr_init2(t, p);
  const __mpfr_struct* as[2] = {a.lo_, a.hi_};
  const __mpfr_struct* bs[2] = {b.lo_, b.hi_};
  bool first = true;
  for (const auto* x : as)
    for (const auto* y : bs) {
      mpfr_mul(t, x, y, MPFR_RNDD);
      if (first || mpfr_less_p(t, r.lo_)) mpfr_set(r.lo_, t, MPFR_RNDD);
      mpfr_mul(t, x, y, MPFR_RNDU);
      if (first || mpfr_greater_p(t, r.hi_)) mpfr_set(r.hi_, t, MPFR_RNDU);
      first = false;
    }
  mpfr_clear(t);
  return r;
}

}  // namespace cmx
