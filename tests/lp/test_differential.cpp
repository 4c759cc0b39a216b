// All backends agree exactly on status and optimal value, on random feasible, infeasible,
// unbounded and degenerate problems with 10- to 1000-bit data; every interior centre is strictly
// inside (exact check) and every returned basis passes the exact certificate.
#include <doctest/doctest.h>

#include <map>

#include "lp/certify_basis.hpp"
#include "lp/exact_simplex.hpp"
#include "lp_test_util.hpp"

using namespace cmx;
using namespace cmx::lp;
using namespace cmx::lp::test;

namespace {

struct Tally {
  int compared = 0, glpk_skipped = 0, certified_direct = 0, fell_back = 0, row_generation = 0;
  std::map<ChebyshevStatus, int> statuses;
};

// Solves h with every backend at `weight_bits`, checks agreement and exactness.
void check_all(const std::vector<HalfSpace>& h, unsigned weight_bits, Tally& tally,
               Norm norm = Norm::l2_upper) {
  ChebyshevOptions o;
  o.weight_bits = weight_bits;
  o.norm = norm;
  std::vector<std::size_t> kept;
  const Problem p = chebyshev_problem(h, o, &kept);
  std::optional<ChebyshevResult> ref;
  for (const auto& backend : all_backends()) {
    o.backend = backend;
    ChebyshevResult r;
    try {
      r = chebyshev_center(h, o);
    } catch (const UnsupportedProblem&) {
      ++tally.glpk_skipped;
      continue;
    }
    CAPTURE(backend);
    if (backend == "certified") (r.lp.info.certified ? tally.certified_direct : tally.fell_back)++;
    if (backend == "certified" && r.lp.info.row_rounds > 0) ++tally.row_generation;
    if (r.status == ChebyshevStatus::interior) REQUIRE(strictly_inside(h, r.center));
    if (r.status == ChebyshevStatus::empty_interior) REQUIRE(inside(h, r.center));
    if (r.lp.status == Status::optimal) {
      REQUIRE(is_feasible(p, r.lp.x));
      REQUIRE(certify_basis(p, r.lp.basis).verdict == Certificate::Verdict::optimal);
    }
    if (!ref) {
      ref = r;
      tally.statuses[r.status]++;
    } else {
      REQUIRE(to_string(r.status) == to_string(ref->status));
      REQUIRE(r.radius == ref->radius);
    }
    ++tally.compared;
  }
}

std::vector<HalfSpace> unbounded_kernel(std::mt19937_64& rng, std::size_t m, unsigned bits) {
  auto h = random_kernel(rng, m, bits);
  for (auto& s : h) {  // every normal has c > 0: -z is a strict recession direction
    s.c = abs(s.c) + 1;
    s.d = abs(s.d) + 1;
  }
  return h;
}

std::vector<HalfSpace> infeasible_kernel(std::mt19937_64& rng, std::size_t m, unsigned bits) {
  auto h = random_kernel(rng, m, bits);
  HalfSpace s = h[0], t = h[0];
  t.a = -s.a, t.b = -s.b, t.c = -s.c, t.d = -s.d - Rational(1, 1 << 20);  // n.x <= d and n.x >= d + eps
  h.insert(h.begin() + std::ptrdiff_t(h.size() / 2), t);
  return h;
}

// The unit cube plus rows tangent to its inscribed ball with normals of rational length: the LP
// optimum is highly degenerate (many tight rows), and planes through the corner (1,1,1).
std::vector<HalfSpace> degenerate_cube(std::mt19937_64& rng) {
  std::vector<HalfSpace> h = {{1, 0, 0, 1},  {-1, 0, 0, 0}, {0, 1, 0, 1},
                              {0, -1, 0, 0}, {0, 0, 1, 1},  {0, 0, -1, 0}};
  const int pyth[][4] = {{3, 4, 0, 5}, {2, 3, 6, 7}, {1, 2, 2, 3}, {4, 4, 7, 9}, {6, 2, 3, 7}, {0, 3, 4, 5}};
  for (int k = 0; k < 12; ++k) {
    const auto& q = pyth[rng() % 6];
    int sg[3] = {(rng() & 1) ? 1 : -1, (rng() & 1) ? 1 : -1, (rng() & 1) ? 1 : -1};
    HalfSpace s{q[0] * sg[0], q[1] * sg[1], q[2] * sg[2], 0};
    s.d = (s.a + s.b + s.c) / 2 + Rational(q[3], 2);  // n.c + |n| r with c = (1/2,1/2,1/2), r = 1/2
    h.push_back(s);
  }
  for (int k = 0; k < 8; ++k) {  // through the corner (1,1,1), not cutting the cube
    HalfSpace s{int(rng() % 5) + 1, int(rng() % 5) + 1, int(rng() % 5) + 1, 0};
    s.d = s.a + s.b + s.c;
    h.push_back(s);
  }
  return h;
}

}  // namespace

TEST_CASE("differential: random feasible kernels, 10 to 1000 bits, integer and rational data") {
  std::mt19937_64 rng(20261123);
  Tally t;
  for (unsigned bits : {10u, 40u, 200u, 1000u})
    for (std::size_t m : {4u, 5u, 8u, 20u, 50u})
      for (int rep = 0; rep < (bits >= 200 ? 3 : 8); ++rep) {
        const auto h = random_kernel(rng, m, bits, rep % 2 == 1);
        check_all(h, 53, t);
        check_all(h, 24, t);
      }
  MESSAGE("compared " << t.compared << ", glpk skipped (>= 2^53) " << t.glpk_skipped
                      << ", certified directly " << t.certified_direct << ", fell back " << t.fell_back);
  CHECK(t.statuses[ChebyshevStatus::interior] > 0);
}

TEST_CASE("differential: infeasible and unbounded problems") {
  std::mt19937_64 rng(99);
  Tally t;
  for (unsigned bits : {10u, 40u, 200u})
    for (std::size_t m : {3u, 6u, 20u}) {
      check_all(infeasible_kernel(rng, m, bits), 24, t);
      check_all(unbounded_kernel(rng, m, bits), 24, t);
    }
  CHECK(t.statuses[ChebyshevStatus::infeasible] == 9);
  CHECK(t.statuses[ChebyshevStatus::unbounded] == 9);
}

TEST_CASE(
    "differential: degenerate problems (tangent rows, planes through a vertex, duplicates, zero rows, "
    "near-parallel)") {
  std::mt19937_64 rng(5);
  Tally t;
  for (int rep = 0; rep < 20; ++rep) {
    auto h = degenerate_cube(rng);
    check_all(h, 53, t);
    check_all(h, 24, t);
    check_all(h, 24, t, Norm::l1);
  }
  for (int rep = 0; rep < 20; ++rep) {
    const unsigned bits = rep % 2 ? 40 : 10;
    auto h = random_kernel(rng, 12, bits);
    const std::size_t m = h.size();
    for (std::size_t i = 0; i < m; i += 3) h.push_back(h[i]);  // duplicates
    for (std::size_t i = 1; i < m; i += 4) {                   // positive multiples
      HalfSpace s = h[i];
      s.a *= 3, s.b *= 3, s.c *= 3, s.d *= 3;
      h.push_back(s);
    }
    h.push_back({0, 0, 0, 1});
    h.push_back({0, 0, 0, 0});
    for (std::size_t i = 0; i < 4; ++i) {  // nearly parallel to row i: normal perturbed by 2^-bits
      HalfSpace s = h[i];
      s.a += Rational(1, Integer(1) << (bits + 20));
      h.push_back(s);
    }
    std::shuffle(h.begin(), h.end(), rng);
    check_all(h, 53, t);
    check_all(h, 24, t);
  }
  // The empty-interior kernel of many planes through one point (a cone apex cut by a plane).
  for (int rep = 0; rep < 10; ++rep) {
    std::vector<HalfSpace> h;
    const std::array<Rational, 3> apex = {random_rational(rng, 30), random_rational(rng, 30),
                                          random_rational(rng, 30)};
    for (int k = 0; k < 10; ++k) {
      HalfSpace s{random_int(rng, 10), random_int(rng, 10), -(abs(random_int(rng, 10)) + 1), 0};  // c < 0
      s.d = dot(s, apex);
      h.push_back(s);
    }
    HalfSpace cap{0, 0, 1, apex[2]};  // z <= apex z: only the apex remains
    h.push_back(cap);
    check_all(h, 53, t);
    check_all(h, 24, t);
  }
  CHECK(t.statuses[ChebyshevStatus::empty_interior] >= 20);
  MESSAGE("compared " << t.compared << ", glpk skipped " << t.glpk_skipped << ", certified directly "
                      << t.certified_direct << ", fell back " << t.fell_back);
}

// A tetrahedron whose every face is given by many rows that are nearly, not exactly, the same
// plane (as a flat boundary of many triangles rounded to doubles gives): normals 2^30 (+-1, +-1,
// +-1) plus integers below 2^`jitter`, offsets 2^30 plus the same. The certified backend then
// meets float bases that fail their certificate and solves by row generation.
std::vector<HalfSpace> jittered_tetrahedron(std::mt19937_64& rng, std::size_t per_face, unsigned jitter) {
  const int normals[4][3] = {{1, 1, 1}, {-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}};
  const Integer big = Integer(1) << 30;
  std::vector<HalfSpace> h;
  for (const auto& n : normals)
    for (std::size_t k = 0; k < per_face; ++k)
      h.push_back({Rational(big * n[0] + random_int(rng, jitter)),
                   Rational(big * n[1] + random_int(rng, jitter)),
                   Rational(big * n[2] + random_int(rng, jitter)), Rational(big + random_int(rng, jitter))});
  std::shuffle(h.begin(), h.end(), rng);
  return h;
}

TEST_CASE(
    "differential: tall problems of nearly parallel rows (row generation agrees with the exact simplex)") {
  std::mt19937_64 rng(17);
  Tally t;
  for (int rep = 0; rep < 12; ++rep) {
    const auto h = jittered_tetrahedron(rng, rep % 2 ? 60 : 250, rep % 3 == 0 ? 4 : 12);
    check_all(h, 53, t);
    check_all(h, 24, t, Norm::l1);
  }
  // Infeasible: the same faces pushed past each other (every offset negative).
  for (int rep = 0; rep < 3; ++rep) {
    auto h = jittered_tetrahedron(rng, 80, 8);
    for (auto& s : h) s.d = -s.d;
    check_all(h, 53, t);
  }
  CHECK(t.statuses[ChebyshevStatus::interior] == 24);
  CHECK(t.statuses[ChebyshevStatus::infeasible] == 3);
  CHECK(t.row_generation > 0);
  MESSAGE("compared " << t.compared << ", certified directly " << t.certified_direct << ", fell back "
                      << t.fell_back << ", by row generation " << t.row_generation);
}

TEST_CASE("differential: general small LPs with bounds (n = 1..5)") {
  std::mt19937_64 rng(42);
  int optimal = 0, infeasible = 0, unbounded = 0;
  for (int rep = 0; rep < 400; ++rep) {
    const std::size_t n = 1 + rng() % 5, m = rng() % 12;
    Problem p(n);
    for (auto& c : p.objective) c = Rational(random_int(rng, 4));
    for (std::size_t i = 0; i < m; ++i) {
      std::vector<Rational> row(n);
      for (auto& a : row) a = (rng() % 4 == 0) ? Rational(0) : Rational(random_int(rng, 5), 1 + rng() % 3);
      p.add_row(row, Rational(random_int(rng, 6), 1 + rng() % 4));
    }
    for (std::size_t j = 0; j < n; ++j) {
      if (rng() % 2) p.set_lower(j, Rational(random_int(rng, 3), 1 + rng() % 2));
      if (rng() % 3 == 0)
        p.set_upper(j, Rational(abs(random_int(rng, 3)), 1 + rng() % 2) +
                           (p.lower.empty() || !p.lower[j] ? Rational(0) : *p.lower[j]));
    }
    std::optional<Solution> ref;
    for (const auto& backend : all_backends()) {
      CAPTURE(backend);
      CAPTURE(rep);
      const Solution s = solve(p, backend);
      if (s.status == Status::optimal) {
        REQUIRE(is_feasible(p, s.x));
        REQUIRE(s.value == objective_value(p, s.x));
        REQUIRE(certify_basis(p, s.basis).verdict == Certificate::Verdict::optimal);
      }
      if (!ref) {
        ref = s;
        (s.status == Status::optimal ? optimal : s.status == Status::infeasible ? infeasible : unbounded)++;
      } else {
        REQUIRE(to_string(s.status) == to_string(ref->status));
        if (s.status == Status::optimal) REQUIRE(s.value == ref->value);
      }
    }
    // A warm start from any basis (here: a random one) reaches the same optimum.
    Basis warm;
    const auto ids = constraint_ids(p);
    for (std::size_t k = 0; k < n && !ids.empty(); ++k) warm.tight.push_back(ids[rng() % ids.size()]);
    const Solution w = exact_simplex(p, &warm);
    REQUIRE(to_string(w.status) == to_string(ref->status));
    if (w.status == Status::optimal) REQUIRE(w.value == ref->value);
  }
  MESSAGE("optimal " << optimal << ", infeasible " << infeasible << ", unbounded " << unbounded);
  CHECK(optimal > 50);
  CHECK(infeasible > 10);
  CHECK(unbounded > 10);
}
