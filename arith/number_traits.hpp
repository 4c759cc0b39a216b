#pragma once
// NumberTraits<T>: the small interface through which kernel code is written once for every
// arithmetic (CGAL's number-type traits, reduced to what the predicates need).
//
//   is_exact                      arithmetic on T never rounds (sign() is never uncertain);
//   from_double(double)           T enclosing (or equal to) a finite double;
//   from_rational(q)              T enclosing (or equal to) an exact rational;
//   sign(const T&) -> UncertainSign  the certain sign, or nullopt.
//
// T must provide +, - and * (the determinant templates in kernel/determinant.hpp use nothing
// else). Interval is valid only inside an UpwardRoundingScope (arith/interval.hpp). double is
// the naive arithmetic: its "sign" is reported as certain although it may be wrong; it exists
// for demonstrations only and its is_exact is false.
#include <stdexcept>

#include "arith/interval.hpp"
#include "arith/mpfr_interval.hpp"
#include "arith/rational.hpp"
#include "arith/rounding.hpp"
#include "arith/sign.hpp"

namespace cmx {

template <class T>
struct NumberTraits;  // no default: an unsupported type is a compile error

template <>
struct NumberTraits<double> {
  static constexpr bool is_exact = false;
  static double from_double(double x) { return x; }
  static double from_rational(const Rational& q) { return to_double(q); }
  static UncertainSign sign(double x) { return sign_of(x); }  // naive: trusts rounding
};

template <>
struct NumberTraits<Interval> {
  static constexpr bool is_exact = false;
  static Interval from_double(double x) { return Interval(x); }
  static Interval from_rational(const Rational& q) {
    const DoubleEnclosure e = enclose(q);
    return Interval(e.lo, e.hi);
  }
  static UncertainSign sign(const Interval& x) { return x.sign(); }
};

template <>
struct NumberTraits<MpfrInterval> {
  static constexpr bool is_exact = false;
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
  static constexpr bool is_exact = true;
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
  static constexpr bool is_exact = true;
  static Rational from_double(double x) { return rational_from_double(x); }
  static Rational from_rational(const Rational& q) { return q; }
  static UncertainSign sign(const Rational& x) { return cmx::sign(x); }
};

}  // namespace cmx
