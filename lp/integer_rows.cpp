#include "lp/integer_rows.hpp"

namespace cmx::lp {

namespace {

// get(i) returns the i-th rational; avoids copying rows into a temporary array.
template <class Get>
void integerise_with(std::size_t k, Get get, Integer* out) {
  // Common denominator: lcm of the denominators (usually all 1 or powers of two).
  Integer l = 1;
  for (std::size_t i = 0; i < k; ++i) {
    const mpz_srcptr d = get(i).get_den_mpz_t();
    if (mpz_cmp_ui(d, 1) != 0) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), d);
  }
  Integer content = 0;
  for (std::size_t i = 0; i < k; ++i) {
    const Rational& q = get(i);
    mpz_divexact(out[i].get_mpz_t(), l.get_mpz_t(), q.get_den_mpz_t());
    mpz_mul(out[i].get_mpz_t(), out[i].get_mpz_t(), q.get_num_mpz_t());
    if (mpz_cmp_ui(content.get_mpz_t(), 1) != 0) mpz_gcd(content.get_mpz_t(), content.get_mpz_t(), out[i].get_mpz_t());
  }
  // Dividing out the content keeps the exact solvers' numbers small.
  if (mpz_cmp_ui(content.get_mpz_t(), 1) > 0)
    for (std::size_t i = 0; i < k; ++i) mpz_divexact(out[i].get_mpz_t(), out[i].get_mpz_t(), content.get_mpz_t());
}

}  // namespace

void integerise(const Rational* q, std::size_t k, Integer* out) {
  integerise_with(k, [q](std::size_t i) -> const Rational& { return q[i]; }, out);
}

IntegerRow integer_row(const Problem& p, std::size_t id) {
  const std::size_t m = p.num_rows(), n = p.num_vars;
  IntegerRow r;
  r.v.resize(n + 1);
  if (id < m) {
    const Rational* row = p.matrix.data() + id * n;
    const Rational& rhs = p.rhs[id];
    integerise_with(n + 1, [row, n, &rhs](std::size_t i) -> const Rational& { return i < n ? row[i] : rhs; }, r.v.data());
    return r;
  }
  std::vector<Rational> g;
  Rational h;
  constraint(p, id, g, h);
  // A bound row is +-e_j <= h: scale by den(h) only.
  const Integer& den = h.get_den();
  for (std::size_t j = 0; j < n; ++j) r.v[j] = Integer(g[j].get_num()) * den;
  r.v[n] = h.get_num();
  return r;
}

std::vector<Integer> integer_objective(const Problem& p) {
  std::vector<Integer> c(p.num_vars);
  integerise(p.objective.data(), p.num_vars, c.data());
  return c;
}

}  // namespace cmx::lp
