#include "arith/rounding.hpp"

#include <cfloat>
#include <climits>
#include <cmath>
#include <limits>

namespace cmx {
namespace {

long bits(const Integer& z) {
  return long(mpz_sizeinbase(z.get_mpz_t(), 2));
}

// floor(log2(a / b)) for a, b > 0.
long floor_log2(const Integer& a, const Integer& b) {
  long e = bits(a) - bits(b);  // 2^(e-1) < a/b < 2^(e+1)
  Integer lhs = a, rhs = b;
  if (e >= 0)
    rhs <<= static_cast<mp_bitcnt_t>(e);
  else
    lhs <<= static_cast<mp_bitcnt_t>(-e);
  return lhs < rhs ? e - 1 : e;
}

// |q| rounded to m * 2^lsb with m < 2^k and lsb >= min_lsb; `negative` is q's sign, so that the
// directed modes round the magnitude the right way. q != 0.
void round_magnitude(const Rational& q, unsigned k, long min_lsb, Round dir, Integer& m, long& lsb) {
  Integer a = abs(q.get_num());
  const Integer& b = q.get_den();
  bool negative = sgn(q) < 0;
  lsb = std::max(floor_log2(a, b) - long(k) + 1, min_lsb);
  Integer num = a, den = b, r;
  if (lsb <= 0)
    num <<= static_cast<mp_bitcnt_t>(-lsb);
  else
    den <<= static_cast<mp_bitcnt_t>(lsb);
  mpz_fdiv_qr(m.get_mpz_t(), r.get_mpz_t(), num.get_mpz_t(), den.get_mpz_t());
  bool up = false;
  if (r != 0) {
    switch (dir) {
      case Round::nearest_even: {
        int c = cmp(Integer(r << 1), den);
        up = c > 0 || (c == 0 && mpz_odd_p(m.get_mpz_t()));
        break;
      }
      case Round::toward_zero:
        up = false;
        break;
      case Round::upward:
        up = !negative;
        break;
      case Round::downward:
        up = negative;
        break;
    }
  }
  if (up) ++m;
  if (bits(m) > long(k)) {  // carried into 2^k
    m >>= 1;
    ++lsb;
  }
}

}  // namespace

double to_double(const Rational& q, Round dir) {
  if (sgn(q) == 0) return 0.0;
  bool negative = sgn(q) < 0;
  Integer m;
  long lsb;
  round_magnitude(q, 53, -1074, dir, m, lsb);
  if (bits(m) + lsb > 1024) {  // beyond the largest finite double
    constexpr double inf = std::numeric_limits<double>::infinity();
    bool to_infinity = dir == Round::nearest_even || (dir == Round::upward && !negative) ||
                       (dir == Round::downward && negative);
    double magnitude = to_infinity ? inf : DBL_MAX;
    return negative ? -magnitude : magnitude;
  }
  double magnitude = std::ldexp(m.get_d(), int(lsb));  // exact: m < 2^53, lsb >= -1074
  return negative ? -magnitude : magnitude;
}

Rational Dyadic::value() const {
  Rational q;
  if (exponent >= 0) {
    q = Rational(mantissa << static_cast<mp_bitcnt_t>(exponent));
  } else {
    Integer den = 1;
    den <<= static_cast<mp_bitcnt_t>(-exponent);
    q = Rational(mantissa, den);
    q.canonicalize();
  }
  return q;
}

Dyadic round_to_dyadic(const Rational& q, unsigned k, Round dir) {
  Dyadic d;
  if (sgn(q) == 0 || k == 0) return d;
  round_magnitude(q, k, LONG_MIN / 2, dir, d.mantissa, d.exponent);
  if (sgn(q) < 0) d.mantissa = -d.mantissa;
  return d;
}

DoubleEnclosure enclose(const Rational& q) {
  // Fast path: GMP's conversion truncates toward zero, exactly. Away from the ends of the double
  // range the enclosure is that truncation and its neighbour away from zero, or the truncation
  // alone when q is itself a double (a power-of-two denominator and at most 53 significant
  // bits). Every HPoint computes three enclosures, so this is on the hot path.
  const double t = mpq_get_d(q.get_mpq_t());
  const double a = std::fabs(t);
  if (!(a > 0x1p-1000 && a < 0x1p1000)) return {to_double(q, Round::downward), to_double(q, Round::upward)};
  const Integer& num = q.get_num();
  const Integer& den = q.get_den();
  const bool dyadic = mpz_scan1(den.get_mpz_t(), 0) + 1 == mpz_sizeinbase(den.get_mpz_t(), 2);
  const bool exact = dyadic && mpz_sizeinbase(num.get_mpz_t(), 2) - mpz_scan1(num.get_mpz_t(), 0) <= 53;
  if (exact) return {t, t};
  constexpr double inf = std::numeric_limits<double>::infinity();
  return t > 0 ? DoubleEnclosure{t, std::nextafter(t, inf)} : DoubleEnclosure{std::nextafter(t, -inf), t};
}

}  // namespace cmx
