// Fuzz target: decodes bytes into four points and asserts that every tier that decides agrees
// with the exact homogeneous determinant, under every policy, on raw doubles and on HPoints, and
// that odd permutations flip the sign; the header-only kernel (kernel/orient_standalone.hpp) too.
// NaN/Inf must throw std::domain_error (never a sign).
//
// Input layout: byte 0 selects the mode; then 12 coordinates.
//   mode even: 12 doubles, each from 9 bytes: a selector byte picks a special value
//              (0, +-1, +-min subnormal, +-DBL_MIN, +-DBL_MAX, +-epsilon, NaN, Inf, nextafter of
//              the previous coordinate) or the raw 8-byte bit pattern; coplanarity is encouraged by
//              optionally copying coordinates of earlier points.
//   mode odd:  12 small rationals p/q from 2+2 bytes (HPoints with W > 1).
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "kernel/orient.hpp"
#include "kernel/orient_adaptive.hpp"
#include "kernel/orient_exact.hpp"
#include "kernel/orient_predicates.hpp"
#include "kernel/orient_semistatic.hpp"
#include "kernel/orient_standalone.hpp"

using namespace cmx;

namespace {

struct Reader {
  const std::uint8_t* data;
  std::size_t size, pos = 0;
  std::uint8_t byte() { return pos < size ? data[pos++] : 0; }
  std::uint64_t word() {
    std::uint64_t w = 0;
    for (int i = 0; i < 8; ++i) w = (w << 8) | byte();
    return w;
  }
};

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "fuzz_orient3d: disagreement: %s\n", what);
  std::abort();
}

double decode_double(Reader& r, const double* previous, int index) {
  const std::uint8_t sel = r.byte();
  switch (sel % 16) {
    case 0: return 0.0;
    case 1: return (sel & 16) ? -1.0 : 1.0;
    case 2: return (sel & 16) ? -std::numeric_limits<double>::denorm_min() : std::numeric_limits<double>::denorm_min();
    case 3: return (sel & 16) ? -DBL_MIN : DBL_MIN;
    case 4: return (sel & 16) ? -DBL_MAX : DBL_MAX;
    case 5: return (sel & 16) ? -DBL_EPSILON : DBL_EPSILON;
    case 6: return (sel & 16) ? std::numeric_limits<double>::quiet_NaN() : std::numeric_limits<double>::infinity();
    case 7:  // a copy of an earlier coordinate, possibly moved by one ulp
    case 8:
      if (index >= 3) {
        const double v = previous[index - 3 * (1 + r.byte() % (index / 3))];
        return sel % 16 == 7 ? v : std::nextafter(v, (sel & 16) ? -INFINITY : INFINITY);
      }
      return 0.5;
    case 9: return double(std::int8_t(r.byte())) / 8;  // small dyadic grid
    default: {
      double d;
      const std::uint64_t w = r.word();
      std::memcpy(&d, &w, sizeof d);
      return d;
    }
  }
}

void check_doubles(Reader& r) {
  double p[12];
  for (int i = 0; i < 12; ++i) p[i] = decode_double(r, p, i);
  bool finite = true;
  for (double x : p) finite = finite && std::isfinite(x);
  const double *a = p, *b = p + 3, *c = p + 6, *d = p + 9;
  if (!finite) {
    for (const char* name : {"cascade", "interval", "exact", "naive"}) {
      try {
        (void)cmx::orient3d(a, b, c, d, {*parse_filter_policy(name), nullptr});
        fail("NaN/Inf input returned a sign");
      } catch (const std::domain_error&) {
      }
    }
    try {
      (void)standalone::orient3d(a, b, c, d);
      fail("NaN/Inf input returned a sign (header-only orient3d)");
    } catch (const std::domain_error&) {
    }
    return;
  }
  const HPoint ha = HPoint::from_doubles(a[0], a[1], a[2]), hb = HPoint::from_doubles(b[0], b[1], b[2]);
  const HPoint hc = HPoint::from_doubles(c[0], c[1], c[2]), hd = HPoint::from_doubles(d[0], d[1], d[2]);
  const Sign exact = orient3d_exact(ha, hb, hc, hd);
  if (cmx::orient3d(a, b, c, d, cmx::PredicateContext::certain()) != exact) fail("cascade (doubles)");
  if (cmx::orient3d(ha, hb, hc, hd, cmx::PredicateContext::certain()) != exact) fail("cascade (HPoints)");
  if (cmx::orient3d(a, b, c, d, {*parse_filter_policy("interval"), nullptr}) != exact)
    fail("interval policy");
  if (cmx::orient3d(a, b, c, d, {*parse_filter_policy("exact"), nullptr}) != exact) fail("exact policy");
  if (cmx::orient3d(b, a, c, d, cmx::PredicateContext::certain()) != -exact) fail("antisymmetry");
  if (cmx::orient3d(b, c, a, d, cmx::PredicateContext::certain()) != exact) fail("cyclic symmetry");
  if (auto s = semistatic::orient3d(a, b, c, d); s && *s != exact) fail("semi-static filter");
  if (auto s = try_tier<Orient3d, IntervalTier>(DoubleArgs<4>{{a, b, c, d}}, FilterPolicy{});
      s && *s != exact)
    fail("interval tier");
  if (adaptive::in_adaptive_range(p, 12) && adaptive::orient3d(a, b, c, d, nullptr) != exact) fail("adaptive");
  if (standalone::orient3d(a, b, c, d) != exact) fail("header-only orient3d");
  const Sign e2 = orient2d_exact(ha, hb, hc);
  if (cmx::orient2d(ha, hb, hc, cmx::PredicateContext::certain()) != e2) fail("orient2d cascade");
  const double a2[2] = {a[0], a[1]}, b2[2] = {b[0], b[1]}, c2[2] = {c[0], c[1]};
  if (cmx::orient2d(a2, b2, c2, cmx::PredicateContext::certain()) != e2) fail("orient2d cascade (doubles)");
  if (standalone::orient2d(a2, b2, c2) != e2) fail("header-only orient2d");
}

void check_rationals(Reader& r) {
  Rational q[12];
  for (auto& x : q) {
    const int num = std::int16_t(r.byte() << 8 | r.byte());
    const int den = 1 + (r.byte() << 8 | r.byte());
    x = Rational(num, den);
    x.canonicalize();
  }
  const HPoint a(q[0], q[1], q[2]), b(q[3], q[4], q[5]), c(q[6], q[7], q[8]), d(q[9], q[10], q[11]);
  const Sign exact = orient3d_exact(a, b, c, d);
  if (cmx::orient3d(a, b, c, d, cmx::PredicateContext::certain()) != exact) fail("cascade (rationals)");
  if (cmx::orient3d(a, b, c, d, {*parse_filter_policy("mpfr:40"), nullptr}) != exact) fail("mpfr policy");
  const PointArgs<4> args{{&a, &b, &c, &d}};
  if (auto s = try_tier<Orient3d, IntervalTier>(args, FilterPolicy{}); s && *s != exact)
    fail("interval tier (rationals)");
  const FilterPolicy mpfr24{FilterPolicy::Kind::mpfr, 24};
  if (auto s = try_tier<Orient3d, MpfrTier>(args, mpfr24); s && *s != exact) fail("mpfr tier (rationals)");
  if (cmx::orient3d(a, b, d, c, cmx::PredicateContext::certain()) != -exact) fail("antisymmetry (rationals)");
  if (cmx::orient2d(a, b, c, cmx::PredicateContext::certain()) != orient2d_exact(a, b, c))
    fail("orient2d (rationals)");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  Reader r{data, size, 1};
  if (data[0] % 2 == 0) check_doubles(r);
  else check_rationals(r);
  return 0;
}
