#include "lp/few_bit_point.hpp"

#include <algorithm>
#include <stdexcept>

#include "arith/rounding.hpp"

namespace cmx::lp {

std::size_t point_bits(const Point3& p) {
  std::size_t b = 0;
  for (const Rational& q : p) b = std::max(b, bit_size(q));
  return b;
}

namespace {

FewBitResult start(const std::vector<HalfSpace>& h, const Point3& interior) {
  if (!strictly_inside(h, interior)) throw std::invalid_argument("few-bit search: the start point is not strictly inside");
  FewBitResult r;
  r.point = interior;
  r.bits = point_bits(interior);
  r.checks = 1;
  return r;
}

// Takes `cand` when it is strictly inside and shorter than the current result.
bool offer(const std::vector<HalfSpace>& h, const Point3& cand, FewBitResult& r) {
  const std::size_t b = point_bits(cand);
  if (b >= r.bits) return false;
  ++r.checks;
  if (!strictly_inside(h, cand)) return false;
  r.point = cand;
  r.bits = b;
  r.reduced = true;
  return true;
}

Point3 rounded_dyadic(const Point3& p, unsigned k) {
  Point3 q;
  for (int i = 0; i < 3; ++i) q[std::size_t(i)] = round_to_dyadic(p[std::size_t(i)], k).value();
  return q;
}

}  // namespace

FewBitResult few_bits_by_doubles(const std::vector<HalfSpace>& h, const Point3& interior) {
  FewBitResult r = start(h, interior);
  Point3 q;
  for (int i = 0; i < 3; ++i) q[std::size_t(i)] = Rational(to_double(interior[std::size_t(i)]));
  offer(h, q, r);
  return r;
}

FewBitResult few_bits_by_dyadics(const std::vector<HalfSpace>& h, const Point3& interior, unsigned max_k) {
  FewBitResult r = start(h, interior);
  unsigned fail = 0, ok = 0;
  for (unsigned k = 1; k <= max_k; k *= 2) {
    const Point3 q = rounded_dyadic(interior, k);
    if (point_bits(q) >= r.bits) break;  // longer than what we have: larger k only grows
    if (offer(h, q, r)) {
      ok = k;
      break;
    }
    fail = k;
  }
  // Bisection between the last failure and the first success for a smaller success.
  while (ok != 0 && ok - fail > 1) {
    const unsigned mid = fail + (ok - fail) / 2;
    if (offer(h, rounded_dyadic(interior, mid), r)) ok = mid;
    else fail = mid;
  }
  return r;
}

FewBitResult few_bits_by_segment(const std::vector<HalfSpace>& h, const Point3& interior, const Point3& other,
                                 int max_steps) {
  FewBitResult r = start(h, interior);
  const std::size_t cap = r.bits;
  Rational t(1, 2);
  for (int step = 0; step < max_steps; ++step, t /= 2) {
    Point3 q;
    for (std::size_t i = 0; i < 3; ++i) q[i] = interior[i] + t * (other[i] - interior[i]);
    if (point_bits(q) >= cap) break;  // excessive precision: stop (the paper's rule)
    ++r.checks;
    if (strictly_inside(h, q)) {
      r.point = q;
      r.bits = point_bits(q);
      r.reduced = true;
      break;
    }
  }
  return r;
}

namespace {

// SaE's lower_precision: num >> s and den >> s for every coordinate with min(bits) > s.
Point3 shifted(const Point3& p, unsigned long s) {
  Point3 q = p;
  for (Rational& c : q) {
    const std::size_t bn = bit_size(c.get_num()), bd = bit_size(c.get_den());
    if (std::min(bn, bd) <= s) continue;
    Integer num = c.get_num(), den = c.get_den();
    mpz_tdiv_q_2exp(num.get_mpz_t(), num.get_mpz_t(), s);
    mpz_tdiv_q_2exp(den.get_mpz_t(), den.get_mpz_t(), s);
    c = Rational(num, den);
    c.canonicalize();
  }
  return q;
}

bool shift_allowed(const Point3& p, unsigned long s) {
  Integer d;
  for (const Rational& c : p) {
    if (std::min(bit_size(c.get_num()), bit_size(c.get_den())) <= s) continue;
    mpz_tdiv_q_2exp(d.get_mpz_t(), c.get_den_mpz_t(), s);
    if (d <= 10) return false;
  }
  return true;
}

}  // namespace

FewBitResult few_bits_by_shift(const std::vector<HalfSpace>& h, const Point3& interior, int max_steps) {
  FewBitResult r = few_bits_by_doubles(h, interior);
  if (r.reduced) return r;
  unsigned long s_max = 0;
  for (const Rational& c : interior) s_max = std::max<unsigned long>(s_max, std::min(bit_size(c.get_num()), bit_size(c.get_den())));
  while (s_max > 0 && !shift_allowed(interior, s_max)) --s_max;
  if (s_max == 0) return r;
  if (offer(h, shifted(interior, s_max), r)) return r;
  unsigned long lo = 0, hi = s_max;  // lo: feasible (s = 0 is the point itself), hi: not
  for (int step = 0; step < max_steps && hi - lo > 1; ++step) {
    const unsigned long mid = lo + (hi - lo) / 2;
    ++r.checks;
    const Point3 q = shifted(interior, mid);
    if (strictly_inside(h, q)) {
      lo = mid;
      if (point_bits(q) < r.bits) {
        r.point = q;
        r.bits = point_bits(q);
        r.reduced = true;
      }
    } else {
      hi = mid;
    }
  }
  return r;
}

}  // namespace cmx::lp
