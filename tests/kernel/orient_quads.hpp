#pragma once
// Hard quadruples of double points for the orientation tests, and the differential set that the
// GMP build and the header-only kernel (kernel/orient_standalone.hpp) are compared on. Standard
// library only: the standalone consumer includes it without GMP.
#include <array>
#include <cmath>
#include <cstdint>

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
    const double x = double(r.below(1 << 20) - (1 << 19)) / 1024,
                 y = double(r.below(1 << 20) - (1 << 19)) / 2048;
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

// The set the header-only kernel is checked on, in a fixed order for `seed`: uniform points,
// points rounded onto planes (scales 1 and 1000), coplanar points moved by 1-3 ulps, exactly
// coplanar dyadic points, and the same scaled by 2^k for k from -996 to 996 (beyond the filter's
// guards and the adaptive range, where the exact tier decides). f(quad) for each.
template <class F>
void for_each_differential_quad(std::uint64_t seed, F&& f) {
  Rng rng(seed);
  for (int i = 0; i < 20000; ++i) {
    Quad q;
    for (auto* p : {&q.a, &q.b, &q.c, &q.d})
      for (auto& x : *p) x = rng.uniform(-1, 1);
    f(q);
  }
  for (int i = 0; i < 30000; ++i) f(on_plane(rng, i % 2 ? 1.0 : 1000.0));
  for (int i = 0; i < 15000; ++i) {
    Quad q = i % 3 == 0 ? dyadic_coplanar(rng) : i % 3 == 1 ? mixed_coplanar(rng) : on_plane(rng);
    perturb_ulps(rng, q);
    f(q);
  }
  for (int i = 0; i < 10000; ++i) f(dyadic_coplanar(rng));
  for (int e : {-996, -700, -330, -250, -200, 200, 250, 330, 700, 996})
    for (int i = 0; i < 800; ++i) {
      Quad q = i % 2 ? on_plane(rng) : dyadic_coplanar(rng);
      if (i % 4 == 1) perturb_ulps(rng, q);
      f(scaled(q, e));
    }
}

}  // namespace cmx::test
