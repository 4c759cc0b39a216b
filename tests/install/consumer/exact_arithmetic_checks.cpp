// Inline floating-point code of the installed headers, compiled here with the consumer's flags,
// checked against exact GMP arithmetic and the library's exact predicates.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include "arith/expansion.hpp"
#include "arith/rational.hpp"
#include "arith/rounding.hpp"
#include "checks.hpp"
#include "kernel/homogeneous_point.hpp"
#include "kernel/orient.hpp"
#include "kernel/orient_exact.hpp"
#include "kernel/orient_semistatic.hpp"

namespace {

// A double with a full random 53-bit significand, magnitude in [2^-20, 2^21) and a random sign.
double random_double(std::mt19937_64& rng) {
  const auto significand = double((rng() >> 11) | (std::uint64_t(1) << 52));
  const double magnitude = std::ldexp(significand, int(rng() % 41) - 20 - 52);
  return rng() % 2 ? -magnitude : magnitude;
}

// The exact error of fl(a*b), by GMP.
double exact_product_error(double a, double b) {
  const cmx::Rational exact = cmx::rational_from_double(a) * cmx::rational_from_double(b);
  return cmx::to_double(exact - cmx::rational_from_double(cmx::to_double(exact)));
}

// Counts a wrong error term y of two_product(a, b); prints the first.
void check_error_term(double a, double b, double y, int& failures) {
  const double exact = exact_product_error(a, b);
  if (y != exact && failures++ == 0) std::printf("two_product(%a, %a) error term %a (exact: %a)\n", a, b, y, exact);
}

// Read at run time, so nothing is folded: (1 + 2^-30)^2 has the error 2^-60, (2^53 - 1)^2 has +1.
volatile double near_one = 1.0 + 0x1p-30, odd = 0x1p53 - 1;

}  // namespace

// Whether contraction breaks Two-Product depends on the code around the call, so it is called
// for the error term alone (the rounded product unused), and in a loop keeping both.
int check_two_product() {
  int failures = 0;
  double x, y;
  cmx::expansion::two_product(near_one, near_one, x, y);
  check_error_term(near_one, near_one, y, failures);
  cmx::expansion::two_product(odd, odd, x, y);
  check_error_term(odd, odd, y, failures);
  constexpr int n = 20000;
  std::vector<double> a(n), b(n), products(n), errors(n);
  std::mt19937_64 rng(19);
  for (int i = 0; i < n; ++i) a[i] = random_double(rng), b[i] = random_double(rng);
  for (int i = 0; i < n; ++i) cmx::expansion::two_product(a[i], b[i], products[i], errors[i]);
  for (int i = 0; i < n; ++i) {
    if (products[i] != a[i] * b[i] && failures++ == 0) std::printf("two_product(%a, %a) rounded wrong\n", a[i], b[i]);
    check_error_term(a[i], b[i], errors[i], failures);
  }
  std::printf("two_product: %d products, %d wrong\n", n + 2, failures);
  return failures;
}

namespace {

// Two-Product and a 2x2 minor p*q - r*s as an exact 4-component expansion.
void minor_expansion(double p, double q, double r, double s, double m[4]) {
  double p1, p0, q1, q0;
  cmx::expansion::two_product(p, q, p1, p0);
  cmx::expansion::two_product(r, s, q1, q0);
  cmx::expansion::two_two_diff(p1, p0, q1, q0, m);
}

// The exact sign of det[u, v, w] from the expansion arithmetic alone (Shewchuk's exact stage).
cmx::Sign expansion_orient3d(const double* u, const double* v, const double* w) {
  double mx[4], my[4], mz[4], tx[8], ty[8], tz[8], txy[16], det[24];
  minor_expansion(v[1], w[2], v[2], w[1], mx);
  minor_expansion(v[2], w[0], v[0], w[2], my);
  minor_expansion(v[0], w[1], v[1], w[0], mz);
  const int nx = cmx::expansion::scale_expansion_zeroelim(4, mx, u[0], tx);
  const int ny = cmx::expansion::scale_expansion_zeroelim(4, my, u[1], ty);
  const int nz = cmx::expansion::scale_expansion_zeroelim(4, mz, u[2], tz);
  const int nxy = cmx::expansion::fast_expansion_sum_zeroelim(nx, tx, ny, ty, txy);
  const int n = cmx::expansion::fast_expansion_sum_zeroelim(nxy, txy, nz, tz, det);
  return cmx::Sign(cmx::expansion::sign(n, det));
}

cmx::HPoint exact_point(const double* p) { return cmx::HPoint::from_doubles(p[0], p[1], p[2]); }

struct OrientTally {
  int cases = 0, filter_decided = 0, filter_wrong = 0, expansion_cases = 0, expansion_wrong = 0, cascade_wrong = 0;
};

// One tetrahedron (a, b, c, d) through all three, against the exact sign.
void check_tetrahedron(const double* a, const double* b, const double* c, const double* d, OrientTally& t) {
  const cmx::HPoint A = exact_point(a), B = exact_point(b), C = exact_point(c), D = exact_point(d);
  const cmx::Sign exact = cmx::orient3d_exact(A, B, C, D);
  ++t.cases;
  if (const cmx::UncertainSign s = cmx::semistatic::orient3d(a, b, c, d)) {
    ++t.filter_decided;
    if (*s != exact) ++t.filter_wrong;
  }
  if (cmx::orient3d(a, b, c, d) != exact) ++t.cascade_wrong;
  // The expansion determinant takes a at the origin, where the differences are the coordinates.
  if (a[0] == 0 && a[1] == 0 && a[2] == 0) {
    ++t.expansion_cases;
    if (expansion_orient3d(b, c, d) != exact) ++t.expansion_wrong;
  }
}

}  // namespace

int check_orient3d() {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  OrientTally t;
  for (int i = 0; i < 20000; ++i) {
    double a[3], b[3], c[3], d[3];
    const double s = unit(rng), r = unit(rng);
    for (int k = 0; k < 3; ++k) a[k] = i % 4 < 2 ? unit(rng) : 0.0, b[k] = unit(rng), c[k] = unit(rng);
    // d on the plane through a, b, c, rounded, then one ulp or 2^-20 .. 2^-55 off it: flat to
    // nearly flat, so the filter's answers come near its error bound.
    for (int k = 0; k < 3; ++k) d[k] = a[k] + s * (b[k] - a[k]) + r * (c[k] - a[k]);
    if (i % 3 == 1) d[i % 2] = std::nextafter(d[i % 2], 2.0);
    if (i % 3 == 2) d[2] += std::ldexp(1.0, -20 - i % 36);
    check_tetrahedron(a, b, c, d, t);
  }
  std::printf("orient3d: %d near-flat tetrahedra; semi-static filter decided %d, %d wrong; "
              "expansion determinant %d of %d wrong; cascade %d wrong\n",
              t.cases, t.filter_decided, t.filter_wrong, t.expansion_wrong, t.expansion_cases, t.cascade_wrong);
  return t.filter_wrong + t.expansion_wrong + t.cascade_wrong;
}
