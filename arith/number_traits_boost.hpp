#pragma once
// NumberTraits (arith/number_traits.hpp) for two Boost.Multiprecision types, so that the kernel's
// generic predicates (orient3d_in<T> in kernel/filtered_predicate.hpp) run on them. Kept out of
// arith/number_traits.hpp so that only a user who includes this header pulls Boost.Multiprecision
// in (Boost headers only; mpfr_float links the MPFR library the kernel links already).
//
//   cpp_rational  exact rationals on Boost's own integers: exact and certified, like Rational.
//   mpfr_float    an MPFR float of the thread's default precision (mpfr_float::default_precision(),
//                 in decimal digits), rounded to nearest: like double, its sign of a rounded result
//                 is trusted although it may be wrong, so it is not certified.
#include <boost/multiprecision/cpp_int.hpp>
#include <boost/multiprecision/mpfr.hpp>

#include "arith/number_traits.hpp"

namespace cmx {

template <>
struct NumberTraits<boost::multiprecision::cpp_rational> {
  using T = boost::multiprecision::cpp_rational;
  static constexpr bool is_exact = true, is_certified = true;
  using Scope = NoScope;
  static const T& fence(const T& x) { return x; }
  static T from_double(double x) { return T(x); }  // exact: a finite double is a dyadic rational
  // Through decimal text: GMP and Boost share no limb layout that both document.
  static T from_rational(const Rational& q) {
    using boost::multiprecision::cpp_int;
    return T(cpp_int(q.get_num().get_str()), cpp_int(q.get_den().get_str()));
  }
  static UncertainSign sign(const T& x) { return Sign(x.sign()); }
};

template <>
struct NumberTraits<boost::multiprecision::mpfr_float> {
  using T = boost::multiprecision::mpfr_float;
  static constexpr bool is_exact = false, is_certified = false;
  using Scope = NoScope;
  static const T& fence(const T& x) { return x; }
  static T from_double(double x) { return T(x); }  // exact when the precision has >= 53 bits
  static T from_rational(const Rational& q) { return T(q.get_mpq_t()); }  // rounded to nearest
  static UncertainSign sign(const T& x) { return Sign(x.sign()); }
};

}  // namespace cmx
