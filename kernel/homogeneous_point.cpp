#include "kernel/homogeneous_point.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cmx {

HPoint::HPoint() : c_{Integer(0), Integer(0), Integer(0), Integer(1)} { canonicalize_and_cache(); }

HPoint::HPoint(const Rational& x, const Rational& y, const Rational& z) {
  // W = lcm of the denominators; then X = x * W etc. are integers.
  Integer w = x.get_den();
  mpz_lcm(w.get_mpz_t(), w.get_mpz_t(), y.get_den().get_mpz_t());
  mpz_lcm(w.get_mpz_t(), w.get_mpz_t(), z.get_den().get_mpz_t());
  const Rational* xyz[3] = {&x, &y, &z};
  for (int i = 0; i < 3; ++i) c_[i] = xyz[i]->get_num() * (w / xyz[i]->get_den());
  c_[3] = w;
  canonicalize_and_cache();
}

HPoint HPoint::from_doubles(double x, double y, double z) {
  return HPoint(rational_from_double(x), rational_from_double(y), rational_from_double(z));
}

HPoint HPoint::from_homogeneous(Integer x, Integer y, Integer z, Integer w) {
  if (w == 0) throw std::invalid_argument("HPoint: homogeneous weight W = 0");
  HPoint p;
  p.c_ = {std::move(x), std::move(y), std::move(z), std::move(w)};
  p.canonicalize_and_cache();
  return p;
}

void HPoint::canonicalize_and_cache() {
  if (sgn(c_[3]) < 0)
    for (auto& v : c_) v = -v;
  Integer g = c_[3];
  for (int i = 0; i < 3 && g != 1; ++i) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), c_[i].get_mpz_t());
  if (g != 1)
    for (auto& v : c_) mpz_divexact(v.get_mpz_t(), v.get_mpz_t(), g.get_mpz_t());
  is_double_ = true;
  for (int i = 0; i < 3; ++i) {
    box_[i] = enclose(coordinate(i));
    is_double_ = is_double_ && box_[i].is_point();
  }
}

Rational HPoint::coordinate(int axis) const {
  Rational q(c_[axis], c_[3]);
  q.canonicalize();
  return q;
}

std::array<double, 3> HPoint::approx() const {
  if (is_double_) return {box_[0].lo, box_[1].lo, box_[2].lo};  // the cache holds the values themselves
  std::array<double, 3> a;
  for (int i = 0; i < 3; ++i) a[i] = to_double(coordinate(i));
  return a;
}

std::size_t HPoint::bit_size() const {
  std::size_t b = 0;
  for (const auto& v : c_) b = std::max(b, cmx::bit_size(v));
  return b;
}

HPoint convex_combination(const HPoint* points, const Rational* weights, int count) {
  if (count < 2 || count > 4) throw std::invalid_argument("convex_combination: 2 to 4 points");
  Rational total = 0;
  for (int i = 0; i < count; ++i) {
    if (sgn(weights[i]) < 0) throw std::invalid_argument("convex_combination: negative weight");
    total += weights[i];
  }
  if (total != 1) throw std::invalid_argument("convex_combination: weights do not sum to 1");
  // sum_i (p_i/n_i) X_i / W_i over a common denominator prod_i (n_i W_i).
  std::array<Integer, 4> acc{Integer(0), Integer(0), Integer(0), Integer(1)};
  for (int i = 0; i < count; ++i) {
    const HPoint& p = points[i];
    Integer scale = weights[i].get_num(), den = weights[i].get_den() * p.W();
    // acc/accW + scale*p/den  ->  (acc*den + scale*p*accW) / (accW*den)
    for (int k = 0; k < 3; ++k) acc[k] = acc[k] * den + scale * p.h(k) * acc[3];
    acc[3] *= den;
  }
  return HPoint::from_homogeneous(acc[0], acc[1], acc[2], acc[3]);
}

HPoint midpoint(const HPoint& a, const HPoint& b) {
  const HPoint p[2] = {a, b};
  const Rational w[2] = {Rational(1, 2), Rational(1, 2)};
  return convex_combination(p, w, 2);
}

}  // namespace cmx
