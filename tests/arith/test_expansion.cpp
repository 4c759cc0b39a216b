// Expansion arithmetic: every routine is exact (checked with GMP rationals), outputs are
// nonoverlapping and zero-free, and no routine reads past its inputs (ASan builds).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "arith/expansion.hpp"
#include "arith/rational.hpp"

using namespace cmx;
namespace ex = cmx::expansion;

namespace {
std::uint64_t state = 0x1234567;
std::uint64_t next() {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}
// Random doubles over a wide exponent range (no overflow/underflow in products).
double any_double() {
  const double m = double(next() >> 11) * 0x1p-53 + 0.5;
  return std::ldexp(next() & 1 ? m : -m, int(next() % 200) - 100);
}

Rational value(const double* e, int n) {
  Rational s = 0;
  for (int i = 0; i < n; ++i) s += rational_from_double(e[i]);
  return s;
}

// Exponent of the lowest set bit of a nonzero double.
int lowest_bit(double x) {
  int e;
  const double m = std::frexp(std::fabs(x), &e);
  const auto mant = static_cast<std::uint64_t>(std::ldexp(m, 53));
  return e - 53 + __builtin_ctzll(mant);
}

// Increasing magnitude, zero-free, nonoverlapping (Shewchuk: the highest set bit of each
// component lies below the lowest set bit of the next).
bool well_formed(const double* e, int n) {
  for (int i = 0; i < n; ++i)
    if (e[i] == 0 && n > 1) return false;
  for (int i = 0; i + 1 < n; ++i)
    if (!(std::fabs(e[i]) < std::ldexp(1.0, lowest_bit(e[i + 1])))) return false;
  return true;
}

// Inputs copied into exactly-sized heap blocks so ASan flags any read past the end.
std::unique_ptr<double[]> exact_copy(const std::vector<double>& v) {
  std::unique_ptr<double[]> p(new double[v.size()]);
  for (std::size_t i = 0; i < v.size(); ++i) p[i] = v[i];
  return p;
}

// A random expansion built by growing: n doubles summed exactly.
std::vector<double> random_expansion(int terms) {
  std::vector<double> h(1, 0.0), t;
  for (int i = 0; i < terms; ++i) {
    t.resize(h.size() + 1);
    const int n = ex::grow_expansion_zeroelim(int(h.size()), h.data(), any_double(), t.data());
    t.resize(n);
    h.swap(t);
  }
  return h;
}
}  // namespace

TEST_CASE("two_sum, two_diff, fast_two_sum and two_product are exact") {
  for (int i = 0; i < 20000; ++i) {
    const double a = any_double(), b = any_double();
    double x, y;
    ex::two_sum(a, b, x, y);
    CHECK(x == a + b);
    CHECK(rational_from_double(x) + rational_from_double(y) == rational_from_double(a) + rational_from_double(b));
    ex::two_diff(a, b, x, y);
    CHECK(x == a - b);
    CHECK(rational_from_double(x) + rational_from_double(y) == rational_from_double(a) - rational_from_double(b));
    CHECK(ex::two_diff_tail(a, b, x) == y);
    const double big = std::fabs(a) >= std::fabs(b) ? a : b, small = std::fabs(a) >= std::fabs(b) ? b : a;
    ex::fast_two_sum(big, small, x, y);
    CHECK(rational_from_double(x) + rational_from_double(y) == rational_from_double(a) + rational_from_double(b));
    ex::two_product(a, b, x, y);
    CHECK(x == a * b);
    CHECK(rational_from_double(x) + rational_from_double(y) == rational_from_double(a) * rational_from_double(b));
    double hi, lo;
    ex::split(a, hi, lo);
    CHECK(hi + lo == a);
  }
}

TEST_CASE("two_two_diff is exact") {
  for (int i = 0; i < 5000; ++i) {
    double a1, a0, b1, b0, x[4];
    ex::two_product(any_double(), any_double(), a1, a0);
    ex::two_product(any_double(), any_double(), b1, b0);
    ex::two_two_diff(a1, a0, b1, b0, x);
    CHECK(value(x, 4) == value(&a0, 1) + value(&a1, 1) - value(&b0, 1) - value(&b1, 1));
  }
}

TEST_CASE("expansion sum, scale and multiply are exact, well formed, and stay in bounds") {
  for (int i = 0; i < 3000; ++i) {
    const std::vector<double> e = random_expansion(1 + int(next() % 6)), f = random_expansion(1 + int(next() % 6));
    REQUIRE(well_formed(e.data(), int(e.size())));
    const auto ep = exact_copy(e), fp = exact_copy(f);
    const int en = int(e.size()), fn = int(f.size());
    std::vector<double> h(en + fn);
    int n = ex::fast_expansion_sum_zeroelim(en, ep.get(), fn, fp.get(), h.data());
    CHECK(value(h.data(), n) == value(ep.get(), en) + value(fp.get(), fn));
    CHECK(well_formed(h.data(), n));
    CHECK(ex::sign(n, h.data()) == sgn(value(h.data(), n)));
    const double b = any_double();
    std::vector<double> s(2 * en);
    n = ex::scale_expansion_zeroelim(en, ep.get(), b, s.data());
    CHECK(value(s.data(), n) == value(ep.get(), en) * rational_from_double(b));
    CHECK(well_formed(s.data(), n));
    const double two[2] = {f.size() > 1 ? f[f.size() - 2] : 0.0, f.back()};
    const int tn = f.size() > 1 ? 2 : 1;
    const double* tp = f.size() > 1 ? two : &f.back();
    std::vector<double> m(4 * en), scratch(4 * en);
    n = ex::multiply_by_short(en, ep.get(), tn, tp, m.data(), scratch.data());
    CHECK(value(m.data(), n) == value(ep.get(), en) * value(tp, tn));
    const double est = ex::estimate(n, m.data());
    CHECK(sgn(value(m.data(), n)) == (est > 0) - (est < 0));
  }
}

TEST_CASE("cancellation to zero gives the single component 0") {
  const double e[2] = {0x1p-60, 1.0}, f[2] = {-0x1p-60, -1.0};
  double h[4];
  const int n = ex::fast_expansion_sum_zeroelim(2, e, 2, f, h);
  CHECK(n == 1);
  CHECK(h[0] == 0.0);
  CHECK(ex::sign(n, h) == 0);
  const int g = ex::grow_expansion_zeroelim(0, e, 0.0, h);
  CHECK(g == 1);
  CHECK(h[0] == 0.0);
}
