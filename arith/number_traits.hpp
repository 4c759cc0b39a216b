#pragma once
// NumberTraits<T>: the small interface through which kernel code is written once for every
// arithmetic (CGAL's number-type traits, reduced to what the predicates need).
//
//   is_exact                      arithmetic on T never rounds (sign() is never uncertain);
//   from_double(double)           T enclosing (or equal to) a finite double;
//   from_rational(q)              T enclosing (or equal to) an exact rational;
//   is_certified                  sign() never returns a wrong sign (exact types and intervals);
//                                 false for floating-point types (double, mpfr_float), whose
//                                 sign of a rounded result is trusted although it may be wrong;
//   Scope                         a guard that must be alive while T's arithmetic runs
//                                 (UpwardRoundingScope for Interval, nothing for the others);
//   fence(const T&) -> T          passes a value into or out of the Scope so the optimiser cannot
//                                 move arithmetic across it (opaque() for Interval, identity else).
//
// T must provide +, - and * (the determinant templates in kernel/determinant.hpp use nothing
// else). double is the naive arithmetic, for demonstrations only. The kernel's generic
// predicate on any such T is kernel/filtered_predicate.hpp (orient3d_in<T>). Boost.Multiprecision
// types are in arith/number_traits_boost.hpp, so that this header does not include Boost.
#include <stdexcept>

#include "arith/interval.hpp"
#include "arith/mpfr_interval.hpp"
#include "arith/rational.hpp"
#include "arith/rounding.hpp"
#include "arith/sign.hpp"

namespace cmx {

template <class T>
struct NumberTraits;  // no default: an unsupported type is a compile error

// The Scope of every arithmetic that needs none.
struct NoScope {};

template <>
struct NumberTraits<double> {
  static constexpr bool is_exact = false, is_certified = false;
  using Scope = NoScope;
  static double fence(double x) { return x; }
  static double from_double(double x) { return x; }
  static double from_rational(const Rational& q) { return to_double(q); }
  static UncertainSign sign(double x) { return sign_of(x); }  // naive: trusts rounding
};

template <>
struct NumberTraits<Interval> {
  static constexpr bool is_exact = false, is_certified = true;
  using Scope = UpwardRoundingScope;
  static Interval fence(const Interval& x) { return opaque(x); }
  static Interval from_double(double x) { return Interval(x); }
  static Interval from_rational(const Rational& q) {
    const DoubleEnclosure e = enclose(q);
    return Interval(e.lo, e.hi);
  }
  static UncertainSign sign(const Interval& x) { return x.sign(); }
};

template <>
struct NumberTraits<MpfrInterval> {
  static constexpr bool is_exact = false, is_certified = true;
  using Scope = NoScope;  // MPFR rounds each bound in its own direction
  static const MpfrInterval& fence(const MpfrInterval& x) { return x; }
  static MpfrInterval from_double(double x, mpfr_prec_t bits = MpfrInterval::default_precision) {
    return MpfrInterval(x, bits < 53 ? 53 : bits);
  }
  static MpfrInterval from_rational(const Rational& q, mpfr_prec_t bits = MpfrInterval::default_precision) {
    return MpfrInterval(q, bits);
  }
  static UncertainSign sign(const MpfrInterval& x) { return x.sign(); }
};

template <>
struct NumberTraits<Integer> {
  static constexpr bool is_exact = true, is_certified = true;
  using Scope = NoScope;
  static const Integer& fence(const Integer& x) { return x; }
  // Precondition: x is an integer-valued double (throws std::domain_error otherwise).
  static Integer from_double(double x) {
    Rational q = rational_from_double(x);
    if (q.get_den() != 1) throw std::domain_error("NumberTraits<Integer>: not an integer");
    return q.get_num();
  }
  static UncertainSign sign(const Integer& x) { return cmx::sign(x); }
};

template <>
struct NumberTraits<Rational> {
  static constexpr bool is_exact = true, is_certified = true;
  using Scope = NoScope;
  static const Rational& fence(const Rational& x) { return x; }
  static Rational from_double(double x) { return rational_from_double(x); }
  static Rational from_rational(const Rational& q) { return q; }
  static UncertainSign sign(const Rational& x) { return cmx::sign(x); }
};

}  // namespace cmx
