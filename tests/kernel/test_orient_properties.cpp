// Laws of the orientation predicates: sign convention, antisymmetry under argument permutations,
// translation invariance, every policy exact (but naive), NaN/Inf rejected, policy names.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "kernel/orient.hpp"
#include "kernel/orient_adaptive.hpp"
#include "kernel/orient_exact.hpp"
#include "kernel/orient_predicates.hpp"
#include "kernel/orient_semistatic.hpp"
#include "orient_cases.hpp"

using namespace cmx;
using namespace cmx::test;

namespace {
const FilterPolicy exact_policies[] = {*parse_filter_policy("cascade"), *parse_filter_policy("interval"),
                                       *parse_filter_policy("exact"), *parse_filter_policy("mpfr:64")};

// The adaptive stages alone, counting the deciding stage into stats.
Sign adaptive3(const Quad& q, FilterStats& stats) {
  int stage = -1;
  const Sign s = adaptive::orient3d(q.a.data(), q.b.data(), q.c.data(), q.d.data(), &stage);
  ++stats.counter(Tier(int(Tier::adaptive_a) + stage));
  return s;
}

Sign o3(const Quad& q, const FilterPolicy& p = {}) {
  return cmx::orient3d(q.a.data(), q.b.data(), q.c.data(), q.d.data(), {p, nullptr});
}
}  // namespace

TEST_CASE("sign convention: the unit tetrahedron is positive under every policy") {
  const Quad unit{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const auto& p : exact_policies) CHECK(o3(unit, p) == Sign::positive);
  CHECK(o3(unit, *parse_filter_policy("naive")) == Sign::positive);
  const Quad mirror{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}};
  CHECK(o3(mirror) == Sign::negative);
  const double a[2] = {0, 0}, b[2] = {1, 0}, c[2] = {0, 1};
  CHECK(cmx::orient2d(a, b, c, cmx::PredicateContext::certain()) == Sign::positive);
  CHECK(cmx::orient2d(b, a, c, cmx::PredicateContext::certain()) == Sign::negative);
}

TEST_CASE("antisymmetry: odd permutations flip the sign, even ones keep it, in every tier") {
  Rng rng(11);
  long checked = 0;
  for (int i = 0; i < 20000; ++i) {
    Quad q = i % 3 == 0 ? dyadic_coplanar(rng) : on_plane(rng);
    if (i % 2) perturb_ulps(rng, q);
    const Sign s = Sign(exact_sign(q));
    for (const auto& p : i % 50 == 0
                             ? std::vector<FilterPolicy>(std::begin(exact_policies), std::end(exact_policies))
                             : std::vector<FilterPolicy>{FilterPolicy{}}) {
      CHECK(o3(q, p) == s);
      CHECK(o3(Quad{q.b, q.a, q.c, q.d}, p) == -s);
      CHECK(o3(Quad{q.a, q.b, q.d, q.c}, p) == -s);
      CHECK(o3(Quad{q.b, q.c, q.a, q.d}, p) == s);
      CHECK(o3(Quad{q.d, q.a, q.b, q.c}, p) == -s);  // a 4-cycle is odd
      ++checked;
    }
  }
  MESSAGE(checked, " permutation groups checked");
}

TEST_CASE("translation invariance on exact inputs") {
  Rng rng(12);
  for (int i = 0; i < 2000; ++i) {
    // Dyadic points and shifts with few bits: the translated doubles are exact.
    Quad q = dyadic_coplanar(rng);
    if (i % 2) q.d[2] += 1.0 / 4096;
    const double shift[3] = {double(rng.below(1000)) / 8, -double(rng.below(1000)),
                             double(rng.below(1 << 20))};
    Quad t = q;
    for (auto* p : {&t.a, &t.b, &t.c, &t.d})
      for (int k = 0; k < 3; ++k) (*p)[k] += shift[k];
    CHECK(o3(t) == o3(q));
    // Rational shift of rational points: the exact tier and the cascade on HPoints.
    const Rational r(rng.below(1000) + 1, 3 * (rng.below(1000) + 1));
    auto h = [&](const P3& p, const Rational& s) {
      return HPoint(Rational(p[0]) + s, Rational(p[1]) - s, Rational(p[2]) + 2 * s);
    };
    const Sign s0 =
        cmx::orient3d(h(q.a, 0), h(q.b, 0), h(q.c, 0), h(q.d, 0), cmx::PredicateContext::certain());
    CHECK(cmx::orient3d(h(q.a, r), h(q.b, r), h(q.c, r), h(q.d, r), cmx::PredicateContext::certain()) == s0);
    CHECK(orient3d_exact(h(q.a, r), h(q.b, r), h(q.c, r), h(q.d, r)) == s0);
  }
}

TEST_CASE("NaN and infinity are rejected, never given a sign") {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (double bad : {nan, inf, -inf})
    for (int where = 0; where < 12; ++where) {
      double p[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
      p[where] = bad;
      for (const char* name : {"cascade", "interval", "exact", "naive", "mpfr:100"})
        CHECK_THROWS_AS(cmx::orient3d(p, p + 3, p + 6, p + 9, {*parse_filter_policy(name), nullptr}),
                        std::domain_error);
      if (where < 6)
        CHECK_THROWS_AS(cmx::orient2d(p, p + 2, p + 4, cmx::PredicateContext::certain()), std::domain_error);
    }
  // All points equal to a NaN: the semi-static filter sees zero-free NaN differences.
  const double n3[3] = {nan, nan, nan};
  CHECK_THROWS_AS(cmx::orient3d(n3, n3, n3, n3, cmx::PredicateContext::certain()), std::domain_error);
}

TEST_CASE("the semi-static filter only decides when certain, and counts") {
  FilterStats stats;
  const Quad unit{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  CHECK(o3(unit) == Sign::positive);
  cmx::orient3d(unit.a.data(), unit.b.data(), unit.c.data(), unit.d.data(), {FilterPolicy{}, &stats});
  CHECK(stats.semi_static == 1);
  // A flat axis: exact zero, decided at once.
  CHECK(semistatic::orient3d(unit.a.data(), unit.b.data(), unit.c.data(), unit.a.data()) == Sign::zero);
  // Beyond the guards the filter abstains.
  const Quad tiny = scaled(unit, -400), huge = scaled(unit, 400);
  CHECK_FALSE(semistatic::orient3d(tiny.a.data(), tiny.b.data(), tiny.c.data(), tiny.d.data()).has_value());
  CHECK_FALSE(semistatic::orient3d(huge.a.data(), huge.b.data(), huge.c.data(), huge.d.data()).has_value());
  FilterStats s2;
  CHECK(cmx::orient3d(tiny.a.data(), tiny.b.data(), tiny.c.data(), tiny.d.data(), {FilterPolicy{}, &s2}) ==
        Sign::positive);
  CHECK(cmx::orient3d(huge.a.data(), huge.b.data(), huge.c.data(), huge.d.data(), {FilterPolicy{}, &s2}) ==
        Sign::positive);
  CHECK(s2.exact == 2);
  // Each adaptive stage is reached on suitable data.
  Rng rng(13);
  FilterStats s3;
  for (int i = 0; i < 20000; ++i) {
    Quad q = i % 2 ? on_plane(rng) : dyadic_coplanar(rng);
    if (i % 4 == 1) perturb_ulps(rng, q);
    CHECK(int(adaptive3(q, s3)) == exact_sign(q));
  }
  MESSAGE("adaptive stages on near-degenerate data:\n", s3.report());
  CHECK(s3.adaptive[1] > 0);
  CHECK(s3.adaptive[2] > 0);
}

TEST_CASE("stage D is reached and exact: differences that round, determinant far below the bounds") {
  // Exactly coplanar points (or moved by a few ulps) whose differences round.
  Rng rng(14);
  FilterStats s;
  for (int i = 0; i < 20000; ++i) {
    Quad q = mixed_coplanar(rng);
    if (i % 2) perturb_ulps(rng, q);
    CHECK(int(adaptive3(q, s)) == exact_sign(q));
  }
  MESSAGE(s.report());
  CHECK(s.adaptive[3] > 0);
}

TEST_CASE("orient2d: cascade == exact on near-collinear points, every policy") {
  Rng rng(15);
  for (int i = 0; i < 20000; ++i) {
    const double ax = rng.uniform(-1, 1), ay = rng.uniform(-1, 1), bx = rng.uniform(-1, 1),
                 by = rng.uniform(-1, 1);
    const double t = rng.uniform(-2, 2);
    double c[2] = {ax + t * (bx - ax), ay + t * (by - ay)};
    if (i % 2) c[i % 4 == 1] = std::nextafter(c[i % 4 == 1], 10.0);
    const double a[2] = {ax, ay}, b[2] = {bx, by};
    const Sign e = orient2d_exact(HPoint::from_doubles(ax, ay, 0), HPoint::from_doubles(bx, by, 0),
                                  HPoint::from_doubles(c[0], c[1], 0));
    CHECK(cmx::orient2d(a, b, c, cmx::PredicateContext::certain()) == e);
    CHECK(adaptive::orient2d(a, b, c, nullptr) == e);
    if (i % 20 == 0)
      for (const auto& p : exact_policies) CHECK(cmx::orient2d(a, b, c, {p, nullptr}) == e);
  }
}

TEST_CASE("interval and MPFR tiers: never a wrong certain sign") {
  Rng rng(16);
  for (int i = 0; i < 3000; ++i) {
    const Rational t(rng.below(1000) + 1, 997), u(rng.below(1000) + 1, 991);
    const HPoint a(Rational(1, 3), Rational(2, 7), Rational(rng.below(100), 11));
    const HPoint b(Rational(rng.below(50), 13), 1, Rational(-5, 17));
    const HPoint c(Rational(3, 19), Rational(rng.below(70), 23), 2);
    Rational d[3];
    for (int k = 0; k < 3; ++k)
      d[k] =
          a.coordinate(k) + t * (b.coordinate(k) - a.coordinate(k)) + u * (c.coordinate(k) - a.coordinate(k));
    d[2] += Rational(i % 3 - 1, 1000000007) / 1000000007;
    const HPoint dp(d[0], d[1], d[2]);
    const Sign e = orient3d_exact(a, b, c, dp);
    const PointArgs<4> args{{&a, &b, &c, &dp}};
    auto mpfr = [](std::int32_t bits) { return FilterPolicy{FilterPolicy::Kind::mpfr, bits}; };
    if (const auto s = try_tier<Orient3d, IntervalTier>(args, FilterPolicy{})) CHECK(*s == e);
    for (long bits : {20L, 60L, 200L})
      if (const auto s = try_tier<Orient3d, MpfrTier>(args, mpfr(bits))) CHECK(*s == e);
    if (e != Sign::zero)
      CHECK(try_tier<Orient3d, MpfrTier>(args, mpfr(400)).has_value());  // 400 bits suffice
    if (const auto s = try_tier<Orient2d, IntervalTier>(PointArgs<3>{{&a, &b, &dp}}, FilterPolicy{}))
      CHECK(*s == orient2d_exact(a, b, dp));
  }
}

TEST_CASE("filter policies by name") {
  CHECK(parse_filter_policy("cascade") == FilterPolicy{});
  CHECK(parse_filter_policy("mpfr:128")->mpfr_bits == 128);
  CHECK(to_string(*parse_filter_policy("mpfr:128")) == "mpfr:128");
  for (const char* n : {"cascade", "interval", "exact", "naive", "mpfr:53"})
    CHECK(to_string(*parse_filter_policy(n)) == n);
  std::string why;
  CHECK_FALSE(parse_filter_policy("fast", &why));
  CHECK(why.find("unknown filter 'fast'") != std::string::npos);
  CHECK(why.find("mpfr:BITS") != std::string::npos);
  for (const char* bad : {"mpfr:", "mpfr:1", "mpfr:x", "mpfr:12x", "mpfr:99999999", "Cascade", ""})
    CHECK_FALSE(parse_filter_policy(bad));
}

TEST_CASE("naive is wrong on the Kettner witness that cmx orient3d --demo shows") {
  const Quad q{{-233.33333333333334, 50.93333333333333, 0},
               {200, 49.200000000000003, 0},
               {166.66666666666669, 49.333333333333336, 0},
               {0, 0, 1}};
  CHECK(o3(q) == Sign(exact_sign(q)));
  CHECK(o3(q, *parse_filter_policy("naive")) != o3(q));
}
