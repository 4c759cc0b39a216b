#pragma once
// A double interval [lo, hi] for filters, evaluated inside ONE upward-rounding scope.
//
// Design (the CGAL "advanced" interval, not Boost.Interval's per-operation mode switching, which
// was measured 30x slower): the caller opens an UpwardRoundingScope once around a whole
// expression; every operation then rounds its upper bound up directly and gets its lower bound
// by the opposite trick, lo(a op b) = -((-a) op' b) evaluated upward, i.e. rounded down.
//
// Contract: Interval arithmetic is only valid while an UpwardRoundingScope is alive on this
// thread. Values entering the scope must pass through fp_barrier() after the scope opened, and
// results through fp_barrier() before it closes (see opaque()), so the optimiser cannot move the
// arithmetic across the fesetround calls (GCC does not treat fesetround as an FP barrier even
// with -frounding-math, GCC bug 34678).
//
// Enclosure property: for finite inputs, if x in a and y in b then x op y in a op b. Overflow
// gives an infinite bound (still an enclosure); inf - inf or 0 * inf gives NaN, and sign() then
// reports "uncertain". Underflow is harmless: directed rounding stays directed for subnormals.
#include <algorithm>
#include <cfenv>

#include "arith/ieee_semantics.hpp"
#include "arith/sign.hpp"

namespace cmx {

// An optimisation barrier on one double: the compiler must assume v was read and rewritten
// here, so it can neither fold expressions through it nor move its computation across it.
inline void fp_barrier(double& v) {
#if defined(__x86_64__) || defined(__i386__)
  asm volatile("" : "+x"(v));
#else
  asm volatile("" : "+m"(v));
#endif
}
inline double opaque(double v) {
  fp_barrier(v);
  return v;
}

// Sets round-upward for double arithmetic for its lifetime and restores the previous mode
// exactly. The mode is per thread; nested scopes are allowed.
// On x86-64 double arithmetic is SSE2, so only the MXCSR rounding field (bits 13-14) is switched,
// directly: glibc's fesetround also rewrites the x87 control word and measured about 3x slower
// per filtered predicate. (fegetround() reads the x87 word there, so it does not see this
// scope; arithmetic does.) Elsewhere fesetround is used.
class UpwardRoundingScope {
 public:
#if defined(__x86_64__) && defined(__SSE2_MATH__)
  UpwardRoundingScope() : saved_(__builtin_ia32_stmxcsr()) {
    __builtin_ia32_ldmxcsr((saved_ & ~rounding_bits) | upward_bits);
  }
  ~UpwardRoundingScope() { __builtin_ia32_ldmxcsr(saved_); }
#else
  UpwardRoundingScope() : saved_(unsigned(std::fegetround())) {
    if (int(saved_) != FE_UPWARD) std::fesetround(FE_UPWARD);
  }
  ~UpwardRoundingScope() {
    if (int(saved_) != FE_UPWARD) std::fesetround(int(saved_));
  }
#endif
  UpwardRoundingScope(const UpwardRoundingScope&) = delete;
  UpwardRoundingScope& operator=(const UpwardRoundingScope&) = delete;

 private:
  static constexpr unsigned rounding_bits = 0x6000u, upward_bits = 0x4000u;
  unsigned saved_;
};

struct Interval {
  double lo = 0.0, hi = 0.0;

  constexpr Interval() = default;
  constexpr Interval(double point) : lo(point), hi(point) {}  // NOLINT: implicit by design
  constexpr Interval(double l, double h) : lo(l), hi(h) {}

  // Certain sign: positive if lo > 0, negative if hi < 0, zero if [0, 0]; otherwise (including
  // NaN bounds) uncertain.
  UncertainSign sign() const {
    if (lo > 0.0 && hi >= lo) return Sign::positive;
    if (hi < 0.0 && lo <= hi) return Sign::negative;
    if (lo == 0.0 && hi == 0.0) return Sign::zero;
    return std::nullopt;
  }
  bool contains(double x) const { return lo <= x && x <= hi; }
};

// -x is exact; the barrier keeps -((-a) op b) from being folded back to a op b.
inline double negated(double x) {
  double n = -x;
  fp_barrier(n);
  return n;
}

// All operators: precondition, an UpwardRoundingScope is active.
inline Interval operator-(const Interval& a) { return {-a.hi, -a.lo}; }

// -t for a t computed upward; the barrier keeps -(x - y) from becoming y - x (which rounds the
// other way).
inline double flipped(double t) {
  fp_barrier(t);
  return -t;
}

inline Interval operator+(const Interval& a, const Interval& b) {
  return {flipped(negated(a.lo) - b.lo), a.hi + b.hi};  // lo = a.lo + b.lo rounded down
}

inline Interval operator-(const Interval& a, const Interval& b) {
  return {flipped(b.hi - a.lo), a.hi - b.lo};  // lo = a.lo - b.hi rounded down
}

inline Interval operator*(const Interval& a, const Interval& b) {
  // Upper bound: the largest of the four corner products, each rounded up. Lower bound: the
  // smallest corner product rounded down = -(largest of (-x) * y rounded up).
  const double na_lo = negated(a.lo), na_hi = negated(a.hi);
  const double hi = std::max(std::max(a.lo * b.lo, a.lo * b.hi), std::max(a.hi * b.lo, a.hi * b.hi));
  const double nlo = std::max(std::max(na_lo * b.lo, na_lo * b.hi), std::max(na_hi * b.lo, na_hi * b.hi));
  return {flipped(nlo), hi};
}

inline Interval& operator+=(Interval& a, const Interval& b) { return a = a + b; }
inline Interval& operator-=(Interval& a, const Interval& b) { return a = a - b; }
inline Interval& operator*=(Interval& a, const Interval& b) { return a = a * b; }

// Makes both bounds opaque (see the header contract).
inline Interval opaque(Interval v) {
  fp_barrier(v.lo);
  fp_barrier(v.hi);
  return v;
}

}  // namespace cmx
