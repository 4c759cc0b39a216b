#pragma once
// Random Chebyshev instances for the lp tests (seeded, deterministic) and backend helpers.
#include <random>
#include <string>
#include <vector>

#include "lp/backend_registry.hpp"
#include "lp/chebyshev_center.hpp"
#ifdef CMX_HAVE_GLPK
#include "lp/glpk/glpk_backend.hpp"
#endif

namespace cmx::lp::test {

// Every backend built into this test binary (glpk registered when linked).
inline std::vector<std::string> all_backends() {
#ifdef CMX_HAVE_GLPK
  register_glpk_backend();
#endif
  return backend_names();
}

// Uniform integer with |z| < 2^bits.
inline Integer random_int(std::mt19937_64& rng, unsigned bits) {
  Integer z = 0;
  for (unsigned done = 0; done < bits; done += 32) {
    const unsigned take = std::min(32u, bits - done);
    z <<= take;
    z += Integer(static_cast<unsigned long>(rng() & ((1ull << take) - 1)));
  }
  return (rng() & 1) ? Integer(-z) : z;
}

// Random rational p/q with |p| < 2^bits and 0 < q < 2^bits.
inline Rational random_rational(std::mt19937_64& rng, unsigned bits) {
  Integer den = abs(random_int(rng, bits));
  if (den == 0) den = 1;
  Rational r(random_int(rng, bits), den);
  r.canonicalize();
  return r;
}

// Tangent planes of a random polytope around a known interior point c (the kind of kernel an
// expansion cone produces): normal n with `bits`-bit integer or rational entries, d = n.c + h
// with h > 0. rational = true uses p/q entries.
inline std::vector<HalfSpace> random_kernel(std::mt19937_64& rng, std::size_t m, unsigned bits, bool rational = false) {
  std::array<Rational, 3> c;
  for (auto& x : c) x = rational ? random_rational(rng, bits) : Rational(random_int(rng, std::min(bits, 8u)));
  std::vector<HalfSpace> h;
  while (h.size() < m) {
    HalfSpace s;
    s.a = rational ? random_rational(rng, bits) : Rational(random_int(rng, bits));
    s.b = rational ? random_rational(rng, bits) : Rational(random_int(rng, bits));
    s.c = rational ? random_rational(rng, bits) : Rational(random_int(rng, bits));
    if (sgn(s.a) == 0 && sgn(s.b) == 0 && sgn(s.c) == 0) continue;
    const Rational scale = abs(s.a) + abs(s.b) + abs(s.c);
    Rational off = abs(rational ? random_rational(rng, bits) : Rational(random_int(rng, bits)));
    off = scale * (1 + off / (off + 1));  // h in [|n|_1, 2 |n|_1)
    if (!rational) off = Rational(Integer(off.get_num() / off.get_den()) + 1);
    s.d = s.a * c[0] + s.b * c[1] + s.c * c[2] + off;
    h.push_back(s);
  }
  return h;
}

inline Rational dot(const HalfSpace& s, const std::array<Rational, 3>& p) { return s.a * p[0] + s.b * p[1] + s.c * p[2]; }

}  // namespace cmx::lp::test
