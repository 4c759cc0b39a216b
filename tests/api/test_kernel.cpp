// cmx/kernel.hpp: exact signs under every arithmetic, on doubles and on exact text, against an
// independent oracle (tests/kernel/orient_cases.hpp); bad input is a cmx::Error naming it.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>

#include "api_test_util.hpp"
#include "arith/exact_decimal.hpp"
#include "cmx/kernel.hpp"
#include "kernel/orient_cases.hpp"

namespace {

using cmx::test::error_of;

using cmx::PredicateArithmetic;
constexpr PredicateArithmetic all_arithmetics[] = {PredicateArithmetic::cascade,
                                                   PredicateArithmetic::interval, PredicateArithmetic::exact};

cmx::ExactPoint3 text(const cmx::Point3d& p) {
  return {cmx::exact_decimal(p[0]), cmx::exact_decimal(p[1]), cmx::exact_decimal(p[2])};
}

}  // namespace

TEST_CASE("api orient3d: the unit tetrahedron is +1, its mirror -1, a coplanar point 0") {
  const cmx::Point3d o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1}, w{3, -2, 0};
  for (const PredicateArithmetic a : all_arithmetics) {
    INFO(cmx::to_string(a));
    CHECK(cmx::orient3d(o, x, y, z, a) == 1);
    CHECK(cmx::orient3d(o, y, x, z, a) == -1);
    CHECK(cmx::orient3d(o, x, y, w, a) == 0);
    CHECK(cmx::orient3d(text(o), text(x), text(y), text(z), a) == 1);
    CHECK(cmx::orient3d(text(o), text(y), text(x), text(z), a) == -1);
  }
  CHECK(cmx::orient3d(o, x, y, z) == 1);  // the default is the cascade
}

TEST_CASE("api orient3d: a determinant that underflows in doubles gets its exact sign") {
  // det = s * s * t = 1e-600 * 1e-310: zero in doubles, positive exactly (the exact tier decides,
  // the coordinates lying outside the adaptive stages' range).
  const double s = 1e-300, t = 1e-310;
  const cmx::Point3d a{0, 0, 0}, b{s, 0, 0}, c{0, s, 0}, flat{s, s, 0}, up{s, s, t};
  REQUIRE((b[0] - a[0]) * (c[1] - a[1]) * (up[2] - a[2]) == 0.0);
  for (const PredicateArithmetic arithmetic : all_arithmetics) {
    INFO(cmx::to_string(arithmetic));
    CHECK(cmx::orient3d(a, b, c, flat, arithmetic) == 0);
    CHECK(cmx::orient3d(a, b, c, up, arithmetic) == 1);
    CHECK(cmx::orient3d(b, a, c, up, arithmetic) == -1);
  }
}

TEST_CASE("api orient3d: hard near-degenerate double quadruples agree with an exact oracle") {
  // Uniform points, points rounded onto planes and moved by ulps, exactly coplanar points with
  // mixed magnitudes, scaled by 2^-996 .. 2^996: the differential set of the kernel tests. The text
  // overload gets the doubles' exact decimal expansions, on every 16th quadruple.
  std::size_t checked = 0, zeros = 0, index = 0, mismatches = 0;
  cmx::test::for_each_differential_quad(20261202, [&](const cmx::test::Quad& q) {
    const int expected = cmx::test::exact_sign(q);
    zeros += expected == 0;
    for (const PredicateArithmetic arithmetic : all_arithmetics)
      mismatches += cmx::orient3d(q.a, q.b, q.c, q.d, arithmetic) != expected;
    if (index++ % 16 == 0) {
      mismatches += cmx::orient3d(text(q.a), text(q.b), text(q.c), text(q.d)) != expected;
      ++checked;
    }
  });
  CHECK(mismatches == 0);
  CHECK(checked > 5000);
  CHECK(zeros > 1000);  // the set does exercise exact zeros
}

TEST_CASE("api orient3d: exact text with values that are not doubles") {
  const cmx::ExactPoint3 a{"0", "0", "0"}, b{"1/3", "0", "0"}, c{"0", "1/3", "0"}, flat{"1/3", "1/3", "0"};
  CHECK(cmx::orient3d(a, b, c, flat) == 0);
  // 1e-400 is below the smallest double: as a double it would be 0, exactly it is positive.
  const cmx::ExactPoint3 up{"1/3", "1/3", "1e-400"}, down{"1/3", "1/3", "-1e-400"};
  for (const PredicateArithmetic arithmetic : all_arithmetics) {
    INFO(cmx::to_string(arithmetic));
    CHECK(cmx::orient3d(a, b, c, up, arithmetic) == 1);
    CHECK(cmx::orient3d(a, b, c, down, arithmetic) == -1);
  }
  // d = a + (b - a) / 7 + (c - a) * 2 / 7 exactly, in decimals and fractions mixed.
  const cmx::ExactPoint3 p{"0.1", "-2.5", "3"}, q{"7/10", "1/2", "-1"}, r{"1", "0", "0.25"};
  const cmx::ExactPoint3 on{"0.1e0", "-2.5", "3"};
  CHECK(cmx::orient3d(p, q, r, on) == 0);                  // a repeated point, written differently
  const cmx::ExactPoint3 mix{"31/70", "-19/14", "23/14"};  // p + (q-p)/7 + 2(r-p)/7
  // ... and 1e-30 above it: det = -3/2500000000000000000000000000000 (Python fractions).
  const cmx::ExactPoint3 off{"31/70", "-19/14",
                             "11500000000000000000000000000007/7000000000000000000000000000000"};
  CHECK(cmx::orient3d(p, q, r, mix) == 0);
  CHECK(cmx::orient3d(p, q, r, off) == -1);
  CHECK(cmx::orient3d(q, p, r, off) == 1);
}

TEST_CASE("api orient3d: NaN and infinite coordinates throw cmx::Error naming the coordinate") {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const cmx::Point3d o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0};
  for (const PredicateArithmetic arithmetic : all_arithmetics) {
    INFO(cmx::to_string(arithmetic));
    const std::string m = error_of([&] {
      (void)cmx::orient3d(o, x, cmx::Point3d{0, nan, 0}, y, arithmetic);
    });
    CHECK(m.find("point c, coordinate y is NaN") != std::string::npos);
    const std::string n = error_of([&] {
      (void)cmx::orient3d(o, x, y, cmx::Point3d{0, 0, -inf}, arithmetic);
    });
    CHECK(n.find("point d, coordinate z is infinite") != std::string::npos);
  }
}

TEST_CASE("api orient3d: text that is not an exact number throws cmx::Error naming the coordinate") {
  const cmx::ExactPoint3 o{"0", "0", "0"}, x{"1", "0", "0"}, y{"0", "1", "0"}, z{"0", "0", "1"};
  for (const std::string bad : {"abc", "nan", "inf", "1/0", "", "1.5.2", "2 "}) {
    INFO("text '" << bad << "'");
    const std::string m = error_of([&] { (void)cmx::orient3d(o, x, cmx::ExactPoint3{"0", "1", bad}, z); });
    CHECK(m.find("point c, coordinate z '" + bad + "'") != std::string::npos);
  }
  CHECK(error_of([&] {
          (void)cmx::orient3d(cmx::ExactPoint3{"x", "0", "0"}, x, y, z);
        }).find("point a, coordinate x") != std::string::npos);
}

TEST_CASE("api orient2d: counterclockwise, clockwise, collinear and near-collinear points") {
  using P2 = std::array<double, 2>;
  for (const PredicateArithmetic arithmetic : all_arithmetics) {
    INFO(cmx::to_string(arithmetic));
    CHECK(cmx::orient2d(P2{0, 0}, P2{1, 0}, P2{0, 1}, arithmetic) == 1);
    CHECK(cmx::orient2d(P2{0, 0}, P2{0, 1}, P2{1, 0}, arithmetic) == -1);
    CHECK(cmx::orient2d(P2{0, 0}, P2{1, 1}, P2{3, 3}, arithmetic) == 0);
    // Kettner et al.'s classroom example: p near (1/2, 1/2) on a 64 x 64 grid of ulps, q = (12, 12),
    // r = (24, 24). The sign is that of py - px exactly: det[q-p, r-p] = 12 (py - px).
    std::size_t wrong = 0;
    for (int i = 0; i < 64; ++i)
      for (int j = 0; j < 64; ++j) {
        const P2 p{0.5 + i * 0x1p-53, 0.5 + j * 0x1p-53};
        const int expected = p[1] > p[0] ? 1 : p[1] < p[0] ? -1 : 0;
        wrong += cmx::orient2d(p, P2{12, 12}, P2{24, 24}, arithmetic) != expected;
      }
    CHECK(wrong == 0);
  }
  const std::string m = error_of([] {
    (void)cmx::orient2d(P2{0, 0}, P2{std::numeric_limits<double>::infinity(), 0}, P2{0, 1});
  });
  CHECK(m.find("orient2d: point b, coordinate x is infinite") != std::string::npos);
}

TEST_CASE("api orient3d: arithmetic names") {
  CHECK(std::string(cmx::to_string(PredicateArithmetic::cascade)) == "cascade");
  CHECK(std::string(cmx::to_string(PredicateArithmetic::interval)) == "interval");
  CHECK(std::string(cmx::to_string(PredicateArithmetic::exact)) == "exact");
}
