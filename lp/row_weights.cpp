#include "lp/row_weights.hpp"

#include <gmp.h>
#include <mpfr.h>

#include <cmath>

#include "arith/interval.hpp"

namespace cmx::lp {

std::optional<Norm> parse_norm(std::string_view name) {
  if (name == "l2-upper") return Norm::l2_upper;
  if (name == "l1") return Norm::l1;
  return std::nullopt;
}

std::string_view to_string(Norm norm) { return norm == Norm::l1 ? "l1" : "l2-upper"; }

namespace {

// A double u >= |q| (u = |q| when q is a double), or -1 when |q| is outside [2^-500, 2^500].
double magnitude_upper(const Rational& q) {
  if (sgn(q) == 0) return 0;
  const mpz_srcptr num = q.get_num_mpz_t(), den = q.get_den_mpz_t();
  const bool integer = mpz_cmp_ui(den, 1) == 0;
  const double t = std::fabs(integer ? mpz_get_d(num) : mpq_get_d(q.get_mpq_t()));  // truncated: t <= |q|
  if (!(t >= 0x1p-500 && t <= 0x1p500)) return -1;
  // q is a double iff its denominator is a power of two and its numerator fits 53 bits (within
  // the range above no subnormal can occur).
  const bool exact = mpz_popcount(den) == 1 && mpz_sizeinbase(num, 2) - mpz_scan1(num, 0) <= 53;
  return exact ? t : std::nextafter(t, INFINITY);
}

Rational mpfr_weight(const Rational& a, const Rational& b, const Rational& c, unsigned bits) {
  const Rational s = a * a + b * b + c * c;
  mpfr_t w;
  mpfr_init2(w, mpfr_prec_t(bits));
  mpfr_set_q(w, s.get_mpq_t(), MPFR_RNDU);
  mpfr_sqrt(w, w, MPFR_RNDU);
  Integer m;
  const long e = mpfr_get_z_2exp(m.get_mpz_t(), w);
  mpfr_clear(w);
  Rational r(m);
  if (e >= 0) mpq_mul_2exp(r.get_mpq_t(), r.get_mpq_t(), mp_bitcnt_t(e));
  else mpq_div_2exp(r.get_mpq_t(), r.get_mpq_t(), mp_bitcnt_t(-e));
  return r;
}

}  // namespace

Rational l2_upper_weight(const Rational& a, const Rational& b, const Rational& c, unsigned bits) {
  const double ua = magnitude_upper(a), ub = magnitude_upper(b), uc = magnitude_upper(c);
  if (bits < 2 || bits > 53 || ua < 0 || ub < 0 || uc < 0) return mpfr_weight(a, b, c, bits < 2 ? 2 : bits);
  double u;
  {
    // Upward rounding: every operation returns at least its exact result, so u >= |n|_2. The
    // barriers keep the optimiser from moving the arithmetic out of the scope.
    UpwardRoundingScope up;
    double x = ua, y = ub, z = uc;
    fp_barrier(x);
    fp_barrier(y);
    fp_barrier(z);
    u = std::sqrt(x * x + y * y + z * z);
    fp_barrier(u);
  }
  if (bits < 53) {  // round u up to `bits` significant bits (exact operations)
    int e = 0;
    const double f = std::frexp(u, &e);  // u = f 2^e, f in [1/2, 1)
    u = std::ldexp(std::ceil(std::ldexp(f, int(bits))), e - int(bits));
  }
  return Rational(u);  // exact: mpq_set_d
}

Rational l1_weight(const Rational& a, const Rational& b, const Rational& c) { return abs(a) + abs(b) + abs(c); }

Rational row_weight(Norm norm, const Rational& a, const Rational& b, const Rational& c, unsigned bits) {
  return norm == Norm::l1 ? l1_weight(a, b, c) : l2_upper_weight(a, b, c, bits);
}

}  // namespace cmx::lp
