#pragma once
// Exact orientation of double points for embedders: header-only, nothing to link (no GMP, no
// MPFR, no cmx library), only Boost's headers. The tiers are the double path of the cascade of
// kernel/orient.hpp: the semi-static filter, then Shewchuk's adaptive stages, and for
// coordinates outside their range ([2^-250, 2^250] in magnitude) an exact determinant on
// Boost.Multiprecision's cpp_int (the coordinates scaled to integers) where the compiled kernel
// uses GMP. Every sign is exact: tests/kernel/test_orient_standalone.cpp checks that they equal
// the GMP build's on the kernel's differential data (fuzz/fuzz_orient3d.cpp against the exact
// determinant), and bench/kernel/bench_standalone.cpp measures what the exact tier costs.
//
//   #include "kernel/orient_standalone.hpp"
//   const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0}, d[3] = {0, 0, 1};
//   cmx::standalone::orient3d(a, b, c, d) == cmx::Sign::positive;
//
// Same sign convention as kernel/orient.hpp: orient3d(a, b, c, d) is the sign of
// det[b-a, c-a, d-a] (positive for the unit tetrahedron, the opposite of Shewchuk's), orient2d
// of det[b-a, c-a] on x and y. Pre: none; a NaN or infinite coordinate throws
// std::domain_error. Cost: a few nanoseconds when the filter decides (almost always); the exact
// tier allocates. Build flags: as for every cmx header with inline floating-point code
// (arith/ieee_semantics.hpp), compile with -ffp-contract=off and without -ffast-math; the cmx
// CMake targets add the first, a user of this header alone must.
#include <algorithm>
#include <boost/multiprecision/cpp_int.hpp>
#include <climits>
#include <cmath>
#include <stdexcept>

#include "arith/sign.hpp"
#include "kernel/determinant.hpp"
#include "kernel/orient_adaptive.hpp"
#include "kernel/orient_semistatic.hpp"

namespace cmx::standalone {

namespace detail {

using Integer = boost::multiprecision::cpp_int;

inline void require_finite(const double* p, int dims) {
  for (int k = 0; k < dims; ++k)
    if (!std::isfinite(p[k])) throw std::domain_error("orientation predicate: NaN or infinite coordinate");
}

// The points' coordinates as integers, each the coordinate divided by 2^emin, the smallest ulp
// among them (of a 53-bit significand): exact, and the determinant's sign is unchanged.
template <int Points, int Dims>
void to_integers(const double* const (&p)[Points], Integer (&out)[Points][Dims]) {
  int emin = INT_MAX;
  for (const double* q : p)
    for (int k = 0; k < Dims; ++k)
      if (q[k] != 0) {
        int e = 0;
        std::frexp(q[k], &e);
        emin = std::min(emin, e - 53);
      }
  for (int i = 0; i < Points; ++i)
    for (int k = 0; k < Dims; ++k) {
      int e = 0;
      const double m = std::frexp(p[i][k], &e);  // p = m 2^e, |m| in [0.5, 1), or m = 0
      out[i][k] = static_cast<long long>(std::ldexp(m, 53));
      if (m != 0) out[i][k] <<= static_cast<unsigned>(e - 53 - emin);
    }
}

template <class T>
Sign sign_of(const T& x) {
  return x > 0 ? Sign::positive : x < 0 ? Sign::negative : Sign::zero;
}

}  // namespace detail

inline Sign orient3d(const double* a, const double* b, const double* c, const double* d) {
  if (const UncertainSign s = semistatic::orient3d(a, b, c, d)) return *s;
  for (const double* p : {a, b, c, d}) detail::require_finite(p, 3);
  const double all[12] = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2]};
  if (adaptive::in_adaptive_range(all, 12)) return adaptive::orient3d(a, b, c, d, nullptr);
  detail::Integer p[4][3];
  detail::to_integers<4, 3>({a, b, c, d}, p);
  return detail::sign_of(orient3d_det(p[0], p[1], p[2], p[3]));
}

inline Sign orient2d(const double* a, const double* b, const double* c) {
  if (const UncertainSign s = semistatic::orient2d(a, b, c)) return *s;
  for (const double* p : {a, b, c}) detail::require_finite(p, 2);
  const double all[6] = {a[0], a[1], b[0], b[1], c[0], c[1]};
  if (adaptive::in_adaptive_range(all, 6)) return adaptive::orient2d(a, b, c, nullptr);
  detail::Integer p[3][2];
  detail::to_integers<3, 2>({a, b, c}, p);
  return detail::sign_of(orient2d_det(p[0], p[1], p[2]));
}

}  // namespace cmx::standalone
