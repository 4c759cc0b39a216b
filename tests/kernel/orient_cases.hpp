#pragma once
// Shared by the orientation tests: a seeded PRNG, generators of hard quadruples, an independent
// exact oracle for double inputs, and (when built with CMX_HAVE_TETGEN) TetGen's Shewchuk code.
#include <gmpxx.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "arith/number_traits.hpp"
#include "kernel/determinant.hpp"

#ifdef CMX_HAVE_TETGEN
// libtet exports Shewchuk's predicates with C++ linkage and non-const pointers (kernel-notes B).
double orient3d(double* pa, double* pb, double* pc, double* pd);
double orient2d(double* pa, double* pb, double* pc);
void exactinit(int verbose, int noexact, int nofilter, double maxx, double maxy, double maxz);
#endif

namespace cmx::test {

// SplitMix64: tiny, fixed-seed, identical on every platform.
struct Rng {
  std::uint64_t state;
  explicit Rng(std::uint64_t seed) : state(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return double(next() >> 11) * 0x1p-53; }  // [0, 1), 53 random bits
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  int below(int n) { return int(next() % std::uint64_t(n)); }
};

using P3 = std::array<double, 3>;
struct Quad {
  P3 a, b, c, d;
};

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

// d rounded onto the plane through a, b, c: d = a + s (b - a) + t (c - a) in doubles.
inline Quad on_plane(Rng& r, double scale = 1.0) {
  Quad q;
  for (auto* p : {&q.a, &q.b, &q.c})
    for (auto& x : *p) x = r.uniform(-scale, scale);
  const double s = r.uniform(-1, 2), t = r.uniform(-1, 2);
  for (int k = 0; k < 3; ++k) q.d[k] = q.a[k] + s * (q.b[k] - q.a[k]) + t * (q.c[k] - q.a[k]);
  return q;
}

// Four points exactly on the plane x + 2y + 4z = c with coordinates on a dyadic grid: det = 0.
inline Quad dyadic_coplanar(Rng& r) {
  const double c = double(r.below(2001) - 1000) / 64;
  auto point = [&]() {
    const double x = double(r.below(1 << 20) - (1 << 19)) / 1024, y = double(r.below(1 << 20) - (1 << 19)) / 2048;
    return P3{x, y, (c - x - 2 * y) / 4};  // exact: few bits, division by 4
  };
  return Quad{point(), point(), point(), point()};
}

// Four points exactly on the plane z = x with x of wildly mixed magnitudes (2^-30 .. 2^60), so the
// differences round although det = 0 exactly: stages B and C cannot decide, stage D must.
inline Quad mixed_coplanar(Rng& r) {
  auto point = [&]() {
    const double x = std::ldexp(double(r.below(1 << 20) + 1), r.below(91) - 50) * (r.below(2) ? 1 : -1);
    return P3{x, r.uniform(-1, 1), x};
  };
  return Quad{point(), point(), point(), point()};
}

// Moves one coordinate of d by k ulps (k in -3..3).
inline void perturb_ulps(Rng& r, Quad& q) {
  double& x = q.d[r.below(3)];
  const int k = r.below(7) - 3;
  for (int i = 0; i < (k < 0 ? -k : k); ++i) x = std::nextafter(x, k < 0 ? -INFINITY : INFINITY);
}

inline Quad scaled(const Quad& q, int exponent) {
  Quad s = q;
  for (auto* p : {&s.a, &s.b, &s.c, &s.d})
    for (auto& x : *p) x = std::ldexp(x, exponent);
  return s;
}

#ifdef CMX_HAVE_TETGEN
// TetGen's sign in OUR convention: Shewchuk's orient3d(a, b, c, d) = -det[b-a, c-a, d-a].
inline int tetgen_sign(Quad q) {
  static const bool initialised = [] {
    exactinit(0, 0, 1, 1.0, 1.0, 1.0);  // nofilter = 1: the pure adaptive path (kernel-notes B)
    return true;
  }();
  (void)initialised;
  const double v = ::orient3d(q.a.data(), q.b.data(), q.c.data(), q.d.data());
  return v > 0 ? -1 : v < 0 ? 1 : 0;
}
#endif

}  // namespace cmx::test
