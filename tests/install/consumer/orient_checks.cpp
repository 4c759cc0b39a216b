// Orientation signs through the installed package, against the library's exact-only arithmetic
// (compiled into cmx::cmx with cmx's own flags, GMP integers throughout). The header-only kernel
// is inline floating-point code compiled here with the consumer's flags: its semi-static filter
// and its adaptive expansions (Two-Product) are exact only under cmx::fp_model's flags.
#include <cmath>
#include <cmx/kernel.hpp>
#include <cmx_standalone/kernel/orient_standalone.hpp>
#include <cstdio>
#include <random>

#include "checks.hpp"

namespace {

struct Tally {
  int cases = 0, filter_decided = 0, standalone_wrong = 0, cascade_wrong = 0;
};

// One tetrahedron (a, b, c, d) and the triangle (a, b, c) in the plane, each way against exact.
void check_case(const cmx::Point3d& a, const cmx::Point3d& b, const cmx::Point3d& c, const cmx::Point3d& d,
                Tally& t) {
  const int exact = cmx::orient3d(a, b, c, d, cmx::PredicateArithmetic::exact);
  ++t.cases;
  if (cmx::semistatic::orient3d(a.data(), b.data(), c.data(), d.data())) ++t.filter_decided;
  if (int(cmx::standalone::orient3d(a.data(), b.data(), c.data(), d.data())) != exact) ++t.standalone_wrong;
  if (cmx::orient3d(a, b, c, d) != exact) ++t.cascade_wrong;
  const std::array<double, 2> a2{a[0], a[1]}, b2{b[0], b[1]}, c2{c[0], c[1]};
  const int exact2 = cmx::orient2d(a2, b2, c2, cmx::PredicateArithmetic::exact);
  if (int(cmx::standalone::orient2d(a.data(), b.data(), c.data())) != exact2) ++t.standalone_wrong;
}

}  // namespace

int check_orient() {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Tally t;
  for (int i = 0; i < 20000; ++i) {
    cmx::Point3d a, b, c, d;
    const double s = unit(rng), r = unit(rng);
    for (int k = 0; k < 3; ++k) a[k] = unit(rng), b[k] = unit(rng), c[k] = unit(rng);
    // d on the plane through a, b, c, rounded, then one ulp or 2^-20 .. 2^-55 off it: flat to
    // nearly flat, so the filter's answers come near its error bound and the rest goes on to the
    // adaptive stage. c is moved onto the line a, b the same way for orient2d.
    for (int k = 0; k < 3; ++k) d[k] = a[k] + s * (b[k] - a[k]) + r * (c[k] - a[k]);
    if (i % 3 == 1) d[i % 2] = std::nextafter(d[i % 2], 2.0);
    if (i % 3 == 2) d[2] += std::ldexp(1.0, -20 - i % 36);
    if (i % 2 == 0)
      for (int k = 0; k < 2; ++k) c[k] = a[k] + s * (b[k] - a[k]);
    check_case(a, b, c, d, t);
  }
  std::printf(
      "orient3d/orient2d: %d near-flat cases; semi-static filter decided %d; header-only kernel "
      "%d wrong; cmx::orient3d %d wrong\n",
      t.cases, t.filter_decided, t.standalone_wrong, t.cascade_wrong);
  return t.standalone_wrong + t.cascade_wrong;
}
