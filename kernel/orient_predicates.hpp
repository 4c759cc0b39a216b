#pragma once
// The orientation predicates as descriptions for the filtered-predicate template
// (kernel/filtered_predicate.hpp), and the same determinants on a number type of the caller's
// choice.
//
// Orient3d: the sign of det[b-a, c-a, d-a] (positive for the unit tetrahedron, the opposite of
// Shewchuk's orient3d). Orient2d: the sign of det[b-a, c-a] on x and y.
//
// For research on number types: orient3d_in<T> and orient2d_in<T> evaluate the determinant in T
// through NumberTraits<T> (arith/number_traits.hpp; Boost.Multiprecision's cpp_rational and
// mpfr_float in arith/number_traits_boost.hpp) and return NumberTraits<T>::sign of it:
//   - on HPoints the exact coordinates enter as NumberTraits<T>::from_rational (T = Integer has
//     none: use the coordinate overload on integer-valued doubles);
//   - on double coordinates (3 or 2 per point) they enter as NumberTraits<T>::from_double.
// The sign is exact for exact T, certain or nullopt for intervals, and for floating-point T
// (double, mpfr_float) whatever the rounded determinant says.
//
//   #include "arith/number_traits_boost.hpp"
//   #include "kernel/orient_predicates.hpp"
//   UncertainSign s = orient3d_in<boost::multiprecision::cpp_rational>(a, b, c, d);
#include <array>

#include "arith/number_traits.hpp"
#include "kernel/determinant.hpp"
#include "kernel/filtered_predicate.hpp"
#include "kernel/orient_adaptive.hpp"
#include "kernel/orient_exact.hpp"
#include "kernel/orient_semistatic.hpp"

namespace cmx {

struct Orient3d {
  static constexpr int points = 4, dims = 3;
  template <class T>
  static T determinant(const T (&p)[4][3]) {
    return orient3d_det(p[0], p[1], p[2], p[3]);
  }
  static UncertainSign semi_static(const std::array<const double*, 4>& p) {
    return semistatic::orient3d(p[0], p[1], p[2], p[3]);
  }
  static Sign adaptive(const std::array<const double*, 4>& p, int* stage) {
    return adaptive::orient3d(p[0], p[1], p[2], p[3], stage);
  }
  static Sign exact(const HPoint* const* h) { return orient3d_exact(*h[0], *h[1], *h[2], *h[3]); }
};

struct Orient2d {
  static constexpr int points = 3, dims = 2;
  template <class T>
  static T determinant(const T (&p)[3][2]) {
    return orient2d_det(p[0], p[1], p[2]);
  }
  static UncertainSign semi_static(const std::array<const double*, 3>& p) {
    return semistatic::orient2d(p[0], p[1], p[2]);
  }
  static Sign adaptive(const std::array<const double*, 3>& p, int* stage) {
    return adaptive::orient2d(p[0], p[1], p[2], stage);
  }
  static Sign exact(const HPoint* const* h) { return orient2d_exact(*h[0], *h[1], *h[2]); }
};

template <class T>
UncertainSign orient3d_in(const HPoint& a, const HPoint& b, const HPoint& c, const HPoint& d) {
  const HPoint* p[4] = {&a, &b, &c, &d};
  return sign_in<T, Orient3d>(
      [&](int i, int k) { return NumberTraits<T>::from_rational(p[i]->coordinate(k)); });
}
template <class T>
UncertainSign orient3d_in(const double* a, const double* b, const double* c, const double* d) {
  const double* p[4] = {a, b, c, d};
  return sign_in<T, Orient3d>([&](int i, int k) { return NumberTraits<T>::from_double(p[i][k]); });
}
template <class T>
UncertainSign orient2d_in(const HPoint& a, const HPoint& b, const HPoint& c) {
  const HPoint* p[3] = {&a, &b, &c};
  return sign_in<T, Orient2d>(
      [&](int i, int k) { return NumberTraits<T>::from_rational(p[i]->coordinate(k)); });
}
template <class T>
UncertainSign orient2d_in(const double* a, const double* b, const double* c) {
  const double* p[3] = {a, b, c};
  return sign_in<T, Orient2d>([&](int i, int k) { return NumberTraits<T>::from_double(p[i][k]); });
}

}  // namespace cmx
