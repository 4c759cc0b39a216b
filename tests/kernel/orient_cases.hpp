#pragma once
// Shared by the orientation tests: the hard quadruples of orient_quads.hpp, an independent exact
// oracle for double inputs, and (when built with CMX_HAVE_TETGEN) TetGen's Shewchuk code.
#include <gmpxx.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "arith/number_traits.hpp"
#include "kernel/determinant.hpp"
#include "orient_quads.hpp"

#ifdef CMX_HAVE_TETGEN
// libtet exports Shewchuk's predicates with C++ linkage and non-const pointers.
double orient3d(double* pa, double* pb, double* pc, double* pd);
double orient2d(double* pa, double* pb, double* pc);
void exactinit(int verbose, int noexact, int nofilter, double maxx, double maxy, double maxz);
#endif

namespace cmx::test {

// Exact sign of det[b-a, c-a, d-a] for finite doubles, independent of the kernel's code paths:
// every coordinate becomes an integer multiple of the smallest ulp present, then the determinant
// template runs on GMP integers.
inline int exact_sign(const Quad& q) {
  const double* src[4] = {q.a.data(), q.b.data(), q.c.data(), q.d.data()};
  long emin = 1L << 30;
  for (auto* p : src)
    for (int k = 0; k < 3; ++k)
      if (p[k] != 0) {
        int e;
        std::frexp(p[k], &e);
        emin = std::min(emin, long(e) - 53);
      }
  if (emin == (1L << 30)) return 0;
  Integer v[4][3];
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) {
      int e;
      const double m = std::frexp(src[i][k], &e);  // src = m 2^e, |m| in [0.5, 1)
      mpz_set_d(v[i][k].get_mpz_t(), std::ldexp(m, 53));
      mpz_mul_2exp(v[i][k].get_mpz_t(), v[i][k].get_mpz_t(), (unsigned long)(long(e) - 53 - emin));
    }
  return sgn(orient3d_det(v[0], v[1], v[2], v[3]));
}

inline double naive_det(const Quad& q) { return orient3d_det(q.a.data(), q.b.data(), q.c.data(), q.d.data()); }

#ifdef CMX_HAVE_TETGEN
// TetGen's sign in OUR convention: Shewchuk's orient3d(a, b, c, d) = -det[b-a, c-a, d-a].
inline int tetgen_sign(Quad q) {
  static const bool initialised = [] {
    exactinit(0, 0, 1, 1.0, 1.0, 1.0);  // nofilter = 1: the pure adaptive path
    return true;
  }();
  (void)initialised;
  const double v = ::orient3d(q.a.data(), q.b.data(), q.c.data(), q.d.data());
  return v > 0 ? -1 : v < 0 ? 1 : 0;
}
#endif

}  // namespace cmx::test
