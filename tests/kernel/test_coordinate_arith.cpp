// The coordinate arithmetic of `cmx map --arith`: names, and roundings that agree with the
// IEEE double conversion and with MPFR's own rounding of a rational.
#include <doctest/doctest.h>
#include <mpfr.h>

#include <random>

#include "arith/rounding.hpp"
#include "kernel/coordinate_arith.hpp"

using namespace cmx;

namespace {

Rational random_rational(std::mt19937_64& rng) {
  std::uniform_int_distribution<std::int64_t> num(-(std::int64_t(1) << 62), std::int64_t(1) << 62);
  std::uniform_int_distribution<std::int64_t> den(1, std::int64_t(1) << 40);
  Rational q(Integer(std::to_string(num(rng))), Integer(std::to_string(den(rng))));
  q.canonicalize();
  return q;
}

// MPFR's round-to-nearest-even of q at `bits` of precision, read back exactly.
Rational mpfr_rounding(const Rational& q, unsigned bits) {
  mpfr_t f;
  mpfr_init2(f, mpfr_prec_t(bits));
  mpfr_set_q(f, q.get_mpq_t(), MPFR_RNDN);
  mpz_t m;
  mpz_init(m);
  const mpfr_exp_t e = mpfr_get_z_2exp(m, f);
  Rational r{Integer(m)};
  if (e >= 0) r *= Rational(Integer(1) << static_cast<mp_bitcnt_t>(e));
  else r /= Rational(Integer(1) << static_cast<mp_bitcnt_t>(-e));
  mpz_clear(m);
  mpfr_clear(f);
  return r;
}

}  // namespace

TEST_CASE("arith names parse and print back, and bad names say what is valid") {
  for (const char* name : {"rational", "double", "mpfr:2", "mpfr:80", "mpfr:65536"}) {
    CAPTURE(name);
    const auto a = parse_coordinate_arith(name);
    REQUIRE(a);
    CHECK(to_string(*a) == name);
  }
  CHECK(parse_coordinate_arith("rational")->exact());
  CHECK_FALSE(parse_coordinate_arith("double")->exact());
  for (const char* bad : {"float", "mpfr:", "mpfr:1", "mpfr:65537", "mpfr:12x", "mpfr:-3", "Double"}) {
    CAPTURE(bad);
    std::string why;
    CHECK_FALSE(parse_coordinate_arith(bad, &why));
    CHECK(why.find("rational, double or mpfr:BITS") != std::string::npos);
  }
}

TEST_CASE("double arith rounds to the nearest double, mpfr:BITS exactly as MPFR rounds a rational") {
  std::mt19937_64 rng(20261129);
  const CoordinateArith dbl = *parse_coordinate_arith("double");
  for (int i = 0; i < 2000; ++i) {
    const Rational q = random_rational(rng);
    const Rational d = dbl.round(q);
    CHECK(d == rational_from_double(to_double(q)));
    CHECK(dbl.round(d) == d);
    for (unsigned bits : {2u, 7u, 24u, 53u, 113u}) {
      const CoordinateArith m{CoordinateArith::Kind::mpfr, bits};
      const Rational r = m.round(q);
      CHECK(r == mpfr_rounding(q, bits));
      CHECK(m.round(r) == r);
    }
  }
}

TEST_CASE("representable points are left alone, others are rounded coordinate by coordinate") {
  const CoordinateArith dbl = *parse_coordinate_arith("double");
  const CoordinateArith m24 = *parse_coordinate_arith("mpfr:24");
  const HPoint tenth(Rational(1, 10), Rational(3), Rational(-7, 4));
  CHECK_FALSE(dbl.representable(tenth));
  const HPoint r = dbl.round(tenth);
  CHECK(r.is_double());
  CHECK(r.coordinate(0) == rational_from_double(0.1));
  CHECK(r.coordinate(1) == 3);
  CHECK(r.coordinate(2) == Rational(-7, 4));
  CHECK(dbl.representable(r));
  CHECK_FALSE(m24.representable(r));  // 0.1 as a double has 53 significant bits
  CHECK(m24.representable(HPoint(Rational(3), Rational(-7, 4), Rational(1, 1024))));
  CHECK(CoordinateArith{}.round(tenth) == tenth);
}
