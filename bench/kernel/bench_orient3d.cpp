// orient3d per tier and input class. Each benchmark iterates over a fixed pool of quadruples
// (generated with a fixed seed) so the branch predictor cannot learn one case; times are per call.
//
//   doubles: easy (uniform in [0,1)^3), near (d rounded onto plane abc), zero (exactly coplanar
//            dyadic grid): naive, TetGen adaptive (libtet), cascade on raw doubles, cascade on
//            HPoints, interval policy, exact policy.
//   rationals of B-bit numerators and denominators (B = 32..1024): cascade on HPoints,
//            exact homogeneous determinant, and the determinant on per-coordinate mpq_class.
#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <vector>

#include "kernel/determinant.hpp"
#include "kernel/orient.hpp"
#include "kernel/orient_exact.hpp"

#ifdef CMX_HAVE_TETGEN
double orient3d(double* pa, double* pb, double* pc, double* pd);
void exactinit(int verbose, int noexact, int nofilter, double maxx, double maxy, double maxz);
#endif

using namespace cmx;

namespace {

constexpr int pool = 1024;  // HPoint pools stay within L2 (1024 x 4 x 120 bytes)

struct Rng {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return double(next() >> 11) * 0x1p-53; }
};

using Quad = std::array<std::array<double, 3>, 4>;

std::vector<Quad> make_doubles(int kind) {
  Rng r{std::uint64_t(42 + kind)};
  std::vector<Quad> v(pool);
  for (Quad& q : v) {
    if (kind == 0) {
      for (auto& p : q)
        for (auto& x : p) x = r.uniform();
    } else if (kind == 1) {
      for (int i = 0; i < 3; ++i)
        for (auto& x : q[i]) x = r.uniform();
      const double s = r.uniform(), t = r.uniform();
      for (int k = 0; k < 3; ++k) q[3][k] = q[0][k] + s * (q[1][k] - q[0][k]) + t * (q[2][k] - q[0][k]);
    } else {  // exactly on x + y + z = 1, dyadic
      for (auto& p : q) {
        p[0] = double(r.next() % 1024) / 1024;
        p[1] = double(r.next() % 1024) / 1024;
        p[2] = 1 - p[0] - p[1];
      }
    }
  }
  return v;
}

const std::vector<Quad>& doubles(int kind) {
  static const std::vector<Quad> sets[3] = {make_doubles(0), make_doubles(1), make_doubles(2)};
  return sets[kind];
}

std::vector<std::array<HPoint, 4>> to_hpoints(const std::vector<Quad>& v) {
  std::vector<std::array<HPoint, 4>> out;
  for (const Quad& q : v) {
    std::array<HPoint, 4> h;
    for (int i = 0; i < 4; ++i) h[i] = HPoint::from_doubles(q[i][0], q[i][1], q[i][2]);
    out.push_back(h);
  }
  return out;
}

const char* kind_name[3] = {"easy", "near", "zero"};

void BM_naive(benchmark::State& st) {
  const auto& v = doubles(int(st.range(0)));
  std::size_t i = 0;
  for (auto _ : st) {
    const Quad& q = v[i++ & (pool - 1)];
    benchmark::DoNotOptimize(cmx::orient3d(q[0].data(), q[1].data(), q[2].data(), q[3].data(),
                                           {FilterPolicy{FilterPolicy::Kind::naive, 0}, nullptr}));
  }
  st.SetLabel(kind_name[st.range(0)]);
}

#ifdef CMX_HAVE_TETGEN
void BM_tetgen(benchmark::State& st) {
  static const bool init = [] {
    exactinit(0, 0, 1, 1.0, 1.0, 1.0);  // pure adaptive path, no static filter
    return true;
  }();
  (void)init;
  std::vector<Quad> v = doubles(int(st.range(0)));
  std::size_t i = 0;
  for (auto _ : st) {
    Quad& q = v[i++ & (pool - 1)];
    benchmark::DoNotOptimize(::orient3d(q[0].data(), q[1].data(), q[2].data(), q[3].data()));
  }
  st.SetLabel(kind_name[st.range(0)]);
}
BENCHMARK(BM_tetgen)->DenseRange(0, 2);
#endif

void BM_double_policy(benchmark::State& st, const char* policy) {
  const auto& v = doubles(int(st.range(0)));
  const FilterPolicy p = *parse_filter_policy(policy);
  std::size_t i = 0;
  for (auto _ : st) {
    const Quad& q = v[i++ & (pool - 1)];
    benchmark::DoNotOptimize(cmx::orient3d(q[0].data(), q[1].data(), q[2].data(), q[3].data(), {p, nullptr}));
  }
  st.SetLabel(kind_name[st.range(0)]);
}

void BM_hpoint_policy(benchmark::State& st, const char* policy) {
  const auto h = to_hpoints(doubles(int(st.range(0))));
  const FilterPolicy p = *parse_filter_policy(policy);
  std::size_t i = 0;
  for (auto _ : st) {
    const auto& q = h[i++ & (pool - 1)];
    benchmark::DoNotOptimize(cmx::orient3d(q[0], q[1], q[2], q[3], {p, nullptr}));
  }
  st.SetLabel(kind_name[st.range(0)]);
}

BENCHMARK(BM_naive)->DenseRange(0, 2);
BENCHMARK_CAPTURE(BM_double_policy, cascade, "cascade")->DenseRange(0, 2);
BENCHMARK_CAPTURE(BM_double_policy, interval, "interval")->DenseRange(0, 2);
BENCHMARK_CAPTURE(BM_double_policy, exact, "exact")->DenseRange(0, 2);
BENCHMARK_CAPTURE(BM_hpoint_policy, cascade, "cascade")->DenseRange(0, 2);
BENCHMARK_CAPTURE(BM_hpoint_policy, interval, "interval")->DenseRange(0, 2);
BENCHMARK_CAPTURE(BM_hpoint_policy, exact, "exact")->DenseRange(0, 2);

// Rationals with `bits`-bit numerators and denominators, random points (a generic position, as in
// the mapping's verification): HPoint cascade vs per-coordinate mpq_class.
constexpr int rpool = 256;
struct RationalSet {
  std::vector<std::array<HPoint, 4>> h;
  std::vector<std::array<std::array<Rational, 3>, 4>> q;
};
const RationalSet& rationals(int bits) {
  static std::vector<std::pair<int, RationalSet>> cache;
  for (auto& [b, s] : cache)
    if (b == bits) return s;
  Rng r{std::uint64_t(bits)};
  auto big = [&] {
    Integer z = 0;
    for (int k = 0; k < bits; k += 32) {
      mpz_mul_2exp(z.get_mpz_t(), z.get_mpz_t(), 32);
      z += static_cast<unsigned long>(r.next() >> 32);
    }
    mpz_setbit(z.get_mpz_t(), bits - 1);  // exactly `bits` bits
    return z;
  };
  RationalSet s;
  for (int i = 0; i < rpool; ++i) {
    std::array<std::array<Rational, 3>, 4> q;
    std::array<HPoint, 4> h;
    for (int p = 0; p < 4; ++p) {
      for (auto& x : q[p]) {
        x = Rational(big(), big());
        x.canonicalize();
      }
      h[p] = HPoint(q[p][0], q[p][1], q[p][2]);
    }
    s.h.push_back(h);
    s.q.push_back(q);
  }
  cache.emplace_back(bits, std::move(s));
  return cache.back().second;
}

void BM_rational_cascade(benchmark::State& st) {
  const auto& s = rationals(int(st.range(0)));
  std::size_t i = 0;
  for (auto _ : st) {
    const auto& q = s.h[i++ % rpool];
    benchmark::DoNotOptimize(cmx::orient3d(q[0], q[1], q[2], q[3], cmx::PredicateContext::certain()));
  }
}
void BM_rational_homogeneous_exact(benchmark::State& st) {
  const auto& s = rationals(int(st.range(0)));
  std::size_t i = 0;
  for (auto _ : st) {
    const auto& q = s.h[i++ % rpool];
    benchmark::DoNotOptimize(orient3d_exact(q[0], q[1], q[2], q[3]));
  }
}
void BM_rational_mpq(benchmark::State& st) {
  const auto& s = rationals(int(st.range(0)));
  std::size_t i = 0;
  for (auto _ : st) {
    const auto& q = s.q[i++ % rpool];
    benchmark::DoNotOptimize(sign_of(orient3d_det(q[0].data(), q[1].data(), q[2].data(), q[3].data())));
  }
}
BENCHMARK(BM_rational_cascade)->RangeMultiplier(2)->Range(32, 1024);
BENCHMARK(BM_rational_homogeneous_exact)->RangeMultiplier(2)->Range(32, 1024);
BENCHMARK(BM_rational_mpq)->RangeMultiplier(2)->Range(32, 1024);

}  // namespace

BENCHMARK_MAIN();
