// bench_topo_expand: topological expansion of a Freudenthal grid complex (6 tets per cell),
// per expansion order, plus the ball check of the same mesh for scale, and of Furch's knotted
// hole (59,286 tets; the expansion gets stuck). The mesh is built once per benchmark, outside the
// timed loop. Target (issue 4): under 2 s for a 100k-tet mesh in every order.
#include <benchmark/benchmark.h>

#include "topology/ball_check.hpp"
#include "topology/generators.hpp"
#include "topology/nobuenoss.hpp"
#include "topology/topological_expansion.hpp"

namespace {

using namespace cmx::topology;

// n x n x n cells: n = 26 gives 105456 tets, n = 56 about 1.05M.
void bench_topo_expand(benchmark::State& state, ExpansionOrder order) {
  const auto n = static_cast<std::uint32_t>(state.range(0));
  const GridComplex g = grid_complex(n, n, n);
  std::size_t length = 0;
  for (auto _ : state) {
    const TopologicalExpansionResult r = topological_expansion(g.mesh, order);
    length = r.length();
    benchmark::DoNotOptimize(length);
    if (r.stuck) state.SkipWithError("stuck on a grid");
  }
  state.counters["tets"] = static_cast<double>(g.mesh.num_tets());
  state.counters["expansions"] = static_cast<double>(length);
  state.counters["tets_per_s"] =
      benchmark::Counter(static_cast<double>(g.mesh.num_tets()), benchmark::Counter::kIsIterationInvariantRate);
}

void bench_knotted_hole(benchmark::State& state, ExpansionOrder order) {
  const GridComplex g = knotted_hole_ball();
  std::size_t length = 0;
  for (auto _ : state) {
    const TopologicalExpansionResult r = topological_expansion(g.mesh, order);
    length = r.length();
    benchmark::DoNotOptimize(length);
    if (!r.stuck) state.SkipWithError("the knotted hole did not get stuck");
  }
  state.counters["tets"] = static_cast<double>(g.mesh.num_tets());
  state.counters["expansions"] = static_cast<double>(length);
}

void bench_ball_check(benchmark::State& state) {
  const auto n = static_cast<std::uint32_t>(state.range(0));
  const GridComplex g = grid_complex(n, n, n);
  for (auto _ : state) {
    const BallVerdict v = check_ball(g.mesh);
    benchmark::DoNotOptimize(v.ok);
  }
  state.counters["tets"] = static_cast<double>(g.mesh.num_tets());
}

}  // namespace

BENCHMARK_CAPTURE(bench_topo_expand, priority, ExpansionOrder{ExpansionOrderKind::priority, 0})
    ->Arg(26)->Arg(56)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(bench_topo_expand, index, ExpansionOrder{ExpansionOrderKind::index, 0})
    ->Arg(26)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(bench_topo_expand, random, ExpansionOrder{ExpansionOrderKind::random, 1})
    ->Arg(26)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(bench_knotted_hole, priority, ExpansionOrder{ExpansionOrderKind::priority, 0})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(bench_knotted_hole, index, ExpansionOrder{ExpansionOrderKind::index, 0})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(bench_knotted_hole, random, ExpansionOrder{ExpansionOrderKind::random, 1})->Unit(benchmark::kMillisecond);
BENCHMARK(bench_ball_check)->Arg(26)->Arg(56)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
