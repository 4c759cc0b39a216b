// Differential tests of the orientation cascade: at least 10^6 quadruples per run (Release),
// cascade == exact everywhere, == TetGen's Shewchuk orient3d on double inputs within its range
// (when CMX_HAVE_TETGEN), and the naive double formula provably wrong on a share of the cases.
#include <doctest/doctest.h>

#include <cinttypes>
#include <cstdlib>
#include <string>

#include "kernel/orient.hpp"
#include "kernel/orient_exact.hpp"
#include "orient_cases.hpp"

using namespace cmx;
using namespace cmx::test;

namespace {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_UNDEFINED__)
constexpr int scale_down = 4;  // sanitizers: ~10x slower, keep the suite within a minute or two
#else
constexpr int scale_down = 1;
#endif

std::uint64_t test_seed() {
  if (const char* s = std::getenv("CMX_TEST_SEED")) return std::strtoull(s, nullptr, 0);
  return 0x5eed2024cafe0001ull;
}

struct Tally {
  const char* name;
  long cases = 0, naive_wrong = 0, disagreements = 0, tetgen_checked = 0, hpoint_checked = 0;
};

std::string hex(const Quad& q) {
  std::string out;
  char buf[40];
  for (auto* p : {&q.a, &q.b, &q.c, &q.d})
    for (double x : *p) {
      std::snprintf(buf, sizeof buf, "%a ", x);
      out += buf;
    }
  return out;
}

struct Checker {
  FilterStats stats;
  long total = 0;

  // with_tetgen: inputs within the range where Shewchuk's code is valid (no under/overflow).
  void operator()(const Quad& q, Tally& t, bool with_tetgen, int expected_or_unknown = 2) {
    ++t.cases;
    ++total;
    const int exact = expected_or_unknown != 2 ? expected_or_unknown : exact_sign(q);
    const int cascade =
        int(cmx::orient3d(q.a.data(), q.b.data(), q.c.data(), q.d.data(), {FilterPolicy{}, &stats}));
    int naive = int(sign_of(naive_det(q)));
    if (naive != exact) ++t.naive_wrong;
    bool ok = cascade == exact;
#ifdef CMX_HAVE_TETGEN
    if (with_tetgen) {
      ++t.tetgen_checked;
      ok = ok && tetgen_sign(q) == exact;
    }
#else
    (void)with_tetgen;
#endif
    // A sample also goes through HPoints (GMP) and the other exact policies.
    if (total % 97 == 0) {
      ++t.hpoint_checked;
      const HPoint a = HPoint::from_doubles(q.a[0], q.a[1], q.a[2]),
                   b = HPoint::from_doubles(q.b[0], q.b[1], q.b[2]);
      const HPoint c = HPoint::from_doubles(q.c[0], q.c[1], q.c[2]),
                   d = HPoint::from_doubles(q.d[0], q.d[1], q.d[2]);
      ok = ok && int(cmx::orient3d(a, b, c, d, cmx::PredicateContext::certain())) == exact &&
           int(orient3d_exact(a, b, c, d)) == exact &&
           int(cmx::orient3d(q.a.data(), q.b.data(), q.c.data(), q.d.data(),
                             {*parse_filter_policy("interval"), nullptr})) == exact &&
           int(cmx::orient3d(a, b, c, d, {*parse_filter_policy("interval"), nullptr})) == exact;
    }
    if (!ok) {
      if (++t.disagreements <= 5)
        MESSAGE(std::string(t.name), ": disagreement (exact ", exact, ") on ", hex(q));
    }
  }
};

void report(const Tally& t) {
  MESSAGE(std::string(t.name), ": ", t.cases, " cases, naive wrong ", t.naive_wrong, " (",
          100.0 * double(t.naive_wrong) / double(t.cases ? t.cases : 1), " %), TetGen-checked ",
          t.tetgen_checked, ", via HPoint ", t.hpoint_checked, ", disagreements ", t.disagreements);
  CHECK_MESSAGE(t.disagreements == 0, std::string(t.name));
}

// Random quadruples: uniform, rounded onto a plane, moved off it by ulps, exactly coplanar.
void check_random_families(Rng& rng, Checker& check) {
  Tally uniform{"uniform random in [-1,1)^3"};
  for (int i = 0; i < 200000 / scale_down; ++i) {
    Quad q;
    for (auto* p : {&q.a, &q.b, &q.c, &q.d})
      for (auto& x : *p) x = rng.uniform(-1, 1);
    check(q, uniform, true);
  }
  report(uniform);

  Tally plane{"d rounded onto plane abc"};
  for (int i = 0; i < 300000 / scale_down; ++i) check(on_plane(rng, i % 2 ? 1.0 : 1000.0), plane, true);
  report(plane);
  CHECK(plane.naive_wrong > 0);  // measured: about 10 %

  Tally ulps{"coplanar points moved by 1-3 ulps"};
  for (int i = 0; i < 150000 / scale_down; ++i) {
    Quad q = i % 3 == 0 ? dyadic_coplanar(rng) : i % 3 == 1 ? mixed_coplanar(rng) : on_plane(rng);
    perturb_ulps(rng, q);
    check(q, ulps, true);
  }
  report(ulps);
  CHECK(ulps.naive_wrong > 0);

  Tally zero{"exactly coplanar dyadic grid (det = 0)"};
  for (int i = 0; i < 100000 / scale_down; ++i) {
    const Quad q = dyadic_coplanar(rng);
    REQUIRE(exact_sign(q) == 0);
    check(q, zero, true, 0);
  }
  report(zero);
}

// Kettner et al. 2004: p steps over a 256x256 grid of successive doubles; q, r fixed; lifted to
// 3D with the apex (0, 0, 1), where orient3d equals the 2D orientation of (p, q, r).
void check_kettner_grids(Checker& check) {
  struct Config {
    double px, py, qx, qy, rx, ry;
  };
  const Config configs[3] = {{0.5, 0.5, 12, 12, 24, 24},
                             {0.50000000000002531, 0.5000000000000171, 17.300000000000001, 17.300000000000001,
                              24.00000000000005, 24.0000000000000517765},
                             {0.5, 0.5, 8.8000000000000007, 8.8000000000000007, 12.1, 12.1}};
  Tally grid{"Kettner 256x256 ulp grids lifted to 3D"};
  long wrong2d = 0, bad2d = 0;
  const int side = scale_down == 1 ? 256 : 64;
  for (const Config& c : configs) {
    double px = c.px;
    for (int i = 0; i < side; ++i, px = std::nextafter(px, 1.0)) {
      double py = c.py;
      for (int j = 0; j < side; ++j, py = std::nextafter(py, 1.0)) {
        const Quad q{{px, py, 0}, {c.qx, c.qy, 0}, {c.rx, c.ry, 0}, {0, 0, 1}};
        const int exact = exact_sign(q);
        check(q, grid, true, exact);
        // The same grid through orient2d.
        const double p2[2] = {px, py}, q2[2] = {c.qx, c.qy}, r2[2] = {c.rx, c.ry};
        if (int(cmx::orient2d(p2, q2, r2, cmx::PredicateContext::certain())) != exact) ++bad2d;
        if (int(cmx::orient2d(p2, q2, r2, {*parse_filter_policy("naive"), nullptr})) != exact) ++wrong2d;
      }
    }
  }
  report(grid);
  MESSAGE("orient2d on the same grids: naive wrong ", wrong2d, ", cascade disagreements ", bad2d);
  CHECK(bad2d == 0);
  CHECK(grid.naive_wrong > 0);  // measured 42 086 of 196 608 (11 972 + 19 776 + 10 338)
}

// Tiny and huge magnitudes, inside and beyond the filter guards (1e-97/1e102) and the adaptive
// range (2^-250..2^250), up to about 1e-300 and 1e300. TetGen is only valid without
// under/overflow, so it is consulted for |exponent| <= 200.
void check_extreme_magnitudes(Rng& rng, Checker& check) {
  Tally extreme{"scaled by 2^k, k in [-996, 996]"};
  const int exponents[] = {-996, -700, -330, -250, -200, 200, 250, 330, 700, 996};
  for (int e : exponents)
    for (int i = 0; i < 8000 / scale_down; ++i) {
      Quad q = i % 2 ? on_plane(rng) : dyadic_coplanar(rng);
      if (i % 4 == 1) perturb_ulps(rng, q);
      check(scaled(q, e), extreme, e >= -200 && e <= 200);
    }
  report(extreme);
}

}  // namespace

TEST_CASE("differential: cascade == exact (== TetGen) on >= 10^6 double quadruples") {
  const std::uint64_t seed = test_seed();
  MESSAGE("seed ", std::to_string(seed), " (set CMX_TEST_SEED to replay); scale 1/", scale_down);
  Rng rng(seed);
  Checker check;
  check_random_families(rng, check);
  check_kettner_grids(check);
  check_extreme_magnitudes(rng, check);
  MESSAGE("total ", check.total, " quadruples; cascade tiers:\n", check.stats.report());
  if (scale_down == 1) CHECK(check.total >= 1000000);
}

TEST_CASE("differential: rational points with large W, cascade == exact == mpq determinant") {
  Rng rng(test_seed() ^ 0x77);
  // num / den - 1/2 with independent random `bits`-bit numerator and denominator.
  auto random_integer = [&](int bits) {
    Integer z = 0;
    for (int k = 0; k < bits; k += 32) {
      mpz_mul_2exp(z.get_mpz_t(), z.get_mpz_t(), 32);
      z += static_cast<unsigned long>(rng.next() >> 32);
    }
    return z;
  };
  auto rational = [&](int bits) {
    const Integer num = random_integer(bits), den = random_integer(bits) + 1;
    const Integer shifted = 2 * num - den;
    Rational q(shifted, 2 * den);
    q.canonicalize();
    return q;
  };
  const FilterPolicy mpfr = *parse_filter_policy("mpfr:80");
  long cases = 0, bad = 0, zeros = 0;
  FilterStats stats;
  for (int i = 0; i < 6000 / scale_down; ++i) {
    const int bits = 32 << ((i / 4) % 4);  // 32 .. 256-bit numerators and denominators
    const HPoint a(rational(bits), rational(bits), rational(bits)),
        b(rational(bits), rational(bits), rational(bits));
    const HPoint c(rational(bits), rational(bits), rational(bits));
    const Rational s = rational(bits), t = rational(bits);
    // Mode i % 4: 0 on the plane abc, 1 and 2 off it by 2^-200 and 2^-60, 3 a random point.
    Rational d[3];
    for (int k = 0; k < 3; ++k) {
      d[k] =
          a.coordinate(k) + s * (b.coordinate(k) - a.coordinate(k)) + t * (c.coordinate(k) - a.coordinate(k));
      if (i % 4 == 1) d[k] += Rational(1, 1) / (Integer(1) << 200);
      if (i % 4 == 2 && k == 2) d[k] += Rational(1, 1) / (Integer(1) << 60);
      if (i % 4 == 3) d[k] = rational(bits);
    }
    const HPoint dp(d[0], d[1], d[2]);
    const Sign exact = orient3d_exact(a, b, c, dp);
    Rational pa[3], pb[3], pc[3], pd[3];
    for (int k = 0; k < 3; ++k)
      pa[k] = a.coordinate(k), pb[k] = b.coordinate(k), pc[k] = c.coordinate(k), pd[k] = d[k];
    const Sign mpq = sign_of(orient3d_det(pa, pb, pc, pd));
    ++cases;
    if (i % 4 == 0) zeros += exact == Sign::zero;
    if (cmx::orient3d(a, b, c, dp, {FilterPolicy{}, &stats}) != exact || mpq != exact ||
        cmx::orient3d(a, b, c, dp, {mpfr, &stats}) != exact ||
        cmx::orient3d(b, a, c, dp, {*parse_filter_policy("interval"), nullptr}) != -exact)
      ++bad;
  }
  MESSAGE(cases, " rational cases (32..256-bit), ", zeros, " exactly coplanar; tiers:\n", stats.report());
  CHECK(bad == 0);
  CHECK(zeros == (cases + 3) / 4);
  CHECK(stats.interval > 0);
}
