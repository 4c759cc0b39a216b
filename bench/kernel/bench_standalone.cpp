// The header-only kernel (kernel/orient_standalone.hpp, exact tier on Boost.Multiprecision's
// cpp_int) against the GMP build's cascade (cmx::orient3d on raw doubles), on the same pools:
//   0 easy:  uniform in [0,1)^3 (the semi-static filter decides, same code in both)
//   1 zero:  exactly coplanar dyadic points (adaptive stage B decides, same code in both)
//   2 huge:  the same scaled by 2^300, beyond the adaptive range: the exact tier decides
//   3 tiny:  scaled by 2^-300
// Times per call; bench/RESULTS.md, section "The header-only kernel".
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "kernel/orient.hpp"
#include "kernel/orient_standalone.hpp"

namespace {

constexpr int pool = 1024;
using Quad = std::array<std::array<double, 3>, 4>;

std::vector<Quad> make(int kind) {
  std::uint64_t s = 7 + std::uint64_t(kind);
  const auto next = [&] {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  };
  std::vector<Quad> v(pool);
  for (Quad& q : v)
    for (auto& p : q) {
      if (kind == 0) {
        for (auto& x : p) x = double(next() >> 11) * 0x1p-53;
        continue;
      }
      p[0] = double(next() % 1024) / 1024;
      p[1] = double(next() % 1024) / 1024;
      p[2] = 1 - p[0] - p[1];
      const int e = kind == 2 ? 300 : kind == 3 ? -300 : 0;
      for (auto& x : p) x = std::ldexp(x, e);
    }
  return v;
}

const std::vector<Quad>& quads(int kind) {
  static const std::vector<Quad> sets[4] = {make(0), make(1), make(2), make(3)};
  return sets[kind];
}

const char* names[4] = {"easy", "zero", "huge", "tiny"};

void BM_gmp_cascade(benchmark::State& st) {
  const auto& v = quads(int(st.range(0)));
  std::size_t i = 0;
  for (auto _ : st) {
    const Quad& q = v[i++ & (pool - 1)];
    benchmark::DoNotOptimize(
        cmx::orient3d(q[0].data(), q[1].data(), q[2].data(), q[3].data(), cmx::PredicateContext::certain()));
  }
  st.SetLabel(names[st.range(0)]);
}

void BM_standalone(benchmark::State& st) {
  const auto& v = quads(int(st.range(0)));
  std::size_t i = 0;
  for (auto _ : st) {
    const Quad& q = v[i++ & (pool - 1)];
    benchmark::DoNotOptimize(cmx::standalone::orient3d(q[0].data(), q[1].data(), q[2].data(), q[3].data()));
  }
  st.SetLabel(names[st.range(0)]);
}

}  // namespace

BENCHMARK(BM_gmp_cascade)->DenseRange(0, 3);
BENCHMARK(BM_standalone)->DenseRange(0, 3);
BENCHMARK_MAIN();
