// Chebyshev centres of random kernels: m = 10..200 half-spaces, 10/40/200-bit integer data, per
// LP backend, plus CGAL's QP solver on Gmpq with Bland pricing (the Shrink-and-Expand set-up).
//
// Instances (fixed seeds, a pool of 32 per size cycled per call): tangent planes of a random
// polytope around a known interior point c, as an expansion cone's kernel: normals n with
// `bits`-bit integer entries, d = n.c + h with h in [|n|_1, 2|n|_1). shift:1 puts c at random
// 8-bit integer coordinates (the origin is then usually outside: phase 1 needed); shift:0 puts c
// at the origin, a distribution (b > 0, the slack basis is feasible).
// Every backend solves the same LP: l2-upper weights with 24 significant bits (so that GLPK gets
// integer-scaled rows below 2^53 at 40 bits). The timed call is the whole chebyshev_center
// (weights, LP set-up, solve, exact answer); CGAL's time covers building its program from the
// same LP rows and solving it.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <deque>
#include <map>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "lp/backend_registry.hpp"
#include "lp/certified_solver.hpp"
#include "lp/chebyshev_center.hpp"
#ifdef CMX_HAVE_GLPK
#include "lp/glpk/glpk_backend.hpp"
#endif
#ifdef CMX_HAVE_CGAL
#include <CGAL/Gmpq.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>
#endif

using namespace cmx;
using namespace cmx::lp;

namespace {

constexpr unsigned weight_bits = 24;

Integer random_int(std::mt19937_64& rng, unsigned bits) {
  Integer z = 0;
  for (unsigned done = 0; done < bits; done += 32) {
    const unsigned take = std::min(32u, bits - done);
    z <<= take;
    z += Integer(static_cast<unsigned long>(rng() & ((1ull << take) - 1)));
  }
  return (rng() & 1) ? Integer(-z) : z;
}

std::vector<HalfSpace> kernel(std::mt19937_64& rng, std::size_t m, unsigned bits, bool shifted) {
  Rational c[3];
  for (auto& x : c) x = shifted ? Rational(random_int(rng, 8)) : Rational(0);
  std::vector<HalfSpace> h;
  while (h.size() < m) {
    HalfSpace s{Rational(random_int(rng, bits)), Rational(random_int(rng, bits)), Rational(random_int(rng, bits)), 0};
    const Integer l1 = abs(s.a.get_num()) + abs(s.b.get_num()) + abs(s.c.get_num());
    if (l1 == 0) continue;
    Integer off = abs(random_int(rng, bits + 1)) % l1 + l1;
    s.d = s.a * c[0] + s.b * c[1] + s.c * c[2] + Rational(off);
    h.push_back(s);
  }
  return h;
}

const std::vector<std::vector<HalfSpace>>& pool(const benchmark::State& state) {
  const std::size_t m = std::size_t(state.range(0));
  const unsigned bits = unsigned(state.range(1));
  const bool shifted = state.range(2) != 0;
  static std::map<std::tuple<std::size_t, unsigned, bool>, std::vector<std::vector<HalfSpace>>> cache;
  auto& p = cache[{m, bits, shifted}];
  if (p.empty()) {
    std::mt19937_64 rng(1000003 * m + 2 * bits + shifted);
    for (int i = 0; i < 32; ++i) p.push_back(kernel(rng, m, bits, shifted));
  }
  return p;
}

void bm_backend(benchmark::State& state, const char* backend) {
  const auto& instances = pool(state);
  ChebyshevOptions o;
  o.backend = backend;
  o.weight_bits = weight_bits;
  std::size_t i = 0;
  int fell_back = 0;
  for (auto _ : state) {
    try {
      const ChebyshevResult r = chebyshev_center(instances[i++ % instances.size()], o);
      fell_back += r.lp.info.fell_back;
      benchmark::DoNotOptimize(r.radius);
    } catch (const UnsupportedProblem&) {
      state.SkipWithError("data too large for this backend");
      break;
    }
  }
  state.counters["fallbacks"] = fell_back;
}

#ifdef CMX_HAVE_CGAL
// Shrink-and-Expand's find_chebyshev_center: Quadratic_program<Gmpq>, rows n, w | d, r >= 0,
// objective -r, Bland pricing, exact type Gmpq.
void bm_cgal(benchmark::State& state) {
  const auto& instances = pool(state);
  ChebyshevOptions o;
  o.weight_bits = weight_bits;
  std::vector<Problem> lps;
  for (const auto& h : instances) lps.push_back(chebyshev_problem(h, o));
  CGAL::Quadratic_program_options options;
  options.set_pricing_strategy(CGAL::QP_BLAND);
  std::size_t i = 0;
  for (auto _ : state) {
    const Problem& p = lps[i++ % lps.size()];
    CGAL::Quadratic_program<CGAL::Gmpq> qp(CGAL::SMALLER, false, 0, false, 0);
    for (std::size_t r = 0; r < p.num_rows(); ++r) {
      for (int j = 0; j < 4; ++j) qp.set_a(j, int(r), CGAL::Gmpq(p.a(r, std::size_t(j)).get_mpq_t()));
      qp.set_b(int(r), CGAL::Gmpq(p.rhs[r].get_mpq_t()));
    }
    qp.set_l(3, true, 0);
    qp.set_c(3, -1);
    const auto s = CGAL::solve_linear_program(qp, CGAL::Gmpq(), options);
    benchmark::DoNotOptimize(s.objective_value());
  }
}
#endif

// Flat kernels: a tetrahedron whose every face is `per_face` rows that are nearly, not exactly,
// one plane (normals 2^30 (+-1, +-1, +-1) plus integers below 2^12, offsets 2^30 plus the same),
// as the boundary kernel of a flat prescribed face rounded to doubles. The float basis of these
// fails its certificate; `certified` then solves by row generation (lp/row_generation.hpp).
std::vector<HalfSpace> flat_tetrahedron(std::mt19937_64& rng, std::size_t per_face) {
  const int normals[4][3] = {{1, 1, 1}, {-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}};
  const Integer big = Integer(1) << 30;
  std::vector<HalfSpace> h;
  for (const auto& n : normals)
    for (std::size_t k = 0; k < per_face; ++k)
      h.push_back({Rational(big * n[0] + random_int(rng, 12)), Rational(big * n[1] + random_int(rng, 12)),
                   Rational(big * n[2] + random_int(rng, 12)), Rational(big + random_int(rng, 12))});
  std::shuffle(h.begin(), h.end(), rng);
  return h;
}

const std::vector<std::vector<HalfSpace>>& flat_pool(const benchmark::State& state) {
  static std::map<std::size_t, std::vector<std::vector<HalfSpace>>> cache;
  const std::size_t per_face = std::size_t(state.range(0));
  auto& p = cache[per_face];
  if (p.empty()) {
    std::mt19937_64 rng(77 + per_face);
    for (int i = 0; i < 4; ++i) p.push_back(flat_tetrahedron(rng, per_face));
  }
  return p;
}

void bm_flat(benchmark::State& state, const char* variant) {
  const auto& instances = flat_pool(state);
  ChebyshevOptions o;
  std::vector<Problem> lps;
  for (const auto& h : instances) lps.push_back(chebyshev_problem(h, o));
  const bool old_path = std::string(variant) == "certified-before-row-generation";
  std::size_t i = 0;
  int rounds = 0;
  for (auto _ : state) {
    const Problem& p = lps[i++ % lps.size()];
    const Solution s = old_path ? certified_solve(p, SIZE_MAX) : solve(p, variant);
    rounds += s.info.row_rounds;
    benchmark::DoNotOptimize(s.x);
  }
  state.counters["row_rounds"] = benchmark::Counter(rounds, benchmark::Counter::kAvgIterations);
}

void sizes(benchmark::internal::Benchmark* b) {
  for (int bits : {10, 40, 200})
    for (int m : {10, 20, 50, 100, 200}) b->Args({m, bits, 1});
  for (int m : {10, 20, 50, 100, 200}) b->Args({m, 40, 0});
  b->ArgNames({"m", "bits", "shift"})->Unit(benchmark::kMicrosecond);
}

const bool registered = [] {
#ifdef CMX_HAVE_GLPK
  register_glpk_backend();
#endif
  static std::deque<std::string> names;  // stable addresses for the benchmark arguments
  for (const auto& name : backend_names()) {
    names.push_back(name);
    benchmark::RegisterBenchmark(("chebyshev/" + name).c_str(), bm_backend, names.back().c_str())->Apply(sizes);
  }
#ifdef CMX_HAVE_CGAL
  benchmark::RegisterBenchmark("chebyshev/cgal_qp_gmpq_bland", bm_cgal)->Apply(sizes);
#endif
  for (const char* v : {"certified", "certified-before-row-generation", "exact"})
    benchmark::RegisterBenchmark((std::string("chebyshev_flat/") + v).c_str(), bm_flat, v)
        ->ArgName("per_face")
        ->Arg(100)
        ->Arg(1000)
        ->Unit(benchmark::kMillisecond);
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
