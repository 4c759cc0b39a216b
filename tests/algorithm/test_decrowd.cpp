// Opening crowds around the shrink point before rounding (algorithm/doubles/decrowd.hpp): a crowd made
// by shrinking vertices toward p_c far below double resolution is scaled back open by a
// homothety, and a vertex pushed into p_c is re-centred out by a sweep; the exact map stays valid.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "algorithm/doubles/decrowd.hpp"
#include "algorithm/doubles/double_output.hpp"
#include "algorithm/expansion/expansion_cone.hpp"
#include "algorithm/map.hpp"
#include "arith/rounding.hpp"
#include "kernel/orient.hpp"
#include "map_test_util.hpp"
#include "topology/complex_queries.hpp"

using namespace cmx;
using namespace cmx::algorithm;
using namespace cmx::generators;
using cmx::test::embedding_of;
using cmx::test::map_checked;
using cmx::test::problem_from;

namespace {

bool all_positive(const Embedding& e) {
  for (TetId t : e.mesh.live_tets())
    if (e.orient_target(e.mesh.tet(t)) != Sign::positive) return false;
  return true;
}

HPoint toward_center(const Embedding& e, const HPoint& p, int k) {
  const Rational f(Integer(1), Integer(1) << k);
  Rational x[3];
  for (int i = 0; i < 3; ++i) x[i] = e.center.coordinate(i) + f * (p.coordinate(i) - e.center.coordinate(i));
  return HPoint(x[0], x[1], x[2]);
}

double distance_from_center(const Embedding& e, VertexId v) {
  double s = 0;
  for (int i = 0; i < 3; ++i) s += std::pow(to_double(e.target[v].coordinate(i) - e.center.coordinate(i)), 2);
  return std::sqrt(s);
}

std::size_t bad_doubles(const Embedding& e) {
  Embedding copy = e;
  const DoubleMap d = make_double_map(copy, SnapPolicy::nearest, {});
  return d.check.inverted + d.check.degenerate;
}

// Two adjacent interior vertices moved together 2^-k of the way to p_c, when that keeps every tet
// positive (checked exactly): the first such pair found, or nullopt.
std::optional<std::pair<VertexId, VertexId>> shrink_pair(Embedding& e, int k) {
  for (TetId t : e.mesh.live_tets())
    for (VertexId a : e.mesh.tet(t))
      for (VertexId b : e.mesh.tet(t)) {
        if (a >= b || e.boundary[a] || e.boundary[b]) continue;
        const HPoint pa = e.target[a], pb = e.target[b];
        e.target[a] = toward_center(e, pa, k);
        e.target[b] = toward_center(e, pb, k);
        if (all_positive(e)) return std::pair(a, b);
        e.target[a] = pa;
        e.target[b] = pb;
      }
  return std::nullopt;
}

}  // namespace

TEST_CASE("a crowd shrunk far below double resolution is scaled back open about p_c") {
  const MapResult r = map_checked(problem_from(perturbed_grid(4, 4, 3, 5), "sphere"));
  Embedding e = embedding_of(r);
  REQUIRE(bad_doubles(e) == 0);
  const auto pair = shrink_pair(e, 1100);
  REQUIRE(pair);
  const auto [a, b] = *pair;
  // Both now round to p_c's double (2^-1100 is below the smallest double): every tet holding both
  // is flat in doubles.
  REQUIRE(bad_doubles(e) > 0);

  CHECK(scale_crowds(e) >= 1);
  CHECK(all_positive(e));
  CHECK(distance_from_center(e, a) > 1e-10);
  CHECK(distance_from_center(e, b) > 1e-10);
  CHECK(bad_doubles(e) == 0);
  for (VertexId v{0}; v < e.num_vertices(); ++v)
    if (e.boundary[v]) CHECK(e.target[v] == r.target[v]);
  // Deterministic: the same crowd opens the same way.
  Embedding again = embedding_of(r);
  REQUIRE(shrink_pair(again, 1100) == pair);
  scale_crowds(again);
  CHECK(again.target == e.target);
}

TEST_CASE("scale_crowds keeps a map without crowds valid, and does nothing in non-exact arithmetic") {
  const MapResult r = map_checked(problem_from(perturbed_grid(4, 4, 3, 5), "sphere"));
  Embedding e = embedding_of(r);
  scale_crowds(e);
  CHECK(all_positive(e));
  Embedding rounded = embedding_of(r);
  REQUIRE(shrink_pair(rounded, 1100));
  rounded.arith = *parse_coordinate_arith("double");
  const std::vector<HPoint> crowded = rounded.target;
  CHECK(scale_crowds(rounded) == 0);
  CHECK(rounded.target == crowded);
}

TEST_CASE("a sweep re-centres a vertex pushed into p_c back out, outermost first") {
  const MapResult r = map_checked(problem_from(perturbed_grid(4, 4, 3, 5), "sphere"));
  Embedding e = embedding_of(r);
  // An interior vertex whose star's kernel holds p_c: moving it 2^-300 of the way to p_c keeps
  // its star positive (the kernel is convex).
  std::optional<VertexId> pushed;
  for (VertexId v{0}; v < e.num_vertices() && !pushed; ++v)
    if (!e.boundary[v] && strictly_inside(gather_expansion_cone(e, v), e.center)) pushed = v;
  REQUIRE(pushed);
  e.target[*pushed] = toward_center(e, e.target[*pushed], 300);
  REQUIRE(all_positive(e));
  const std::vector<VertexId> crowd = crowd_around_center(e);
  CHECK(std::find(crowd.begin(), crowd.end(), *pushed) != crowd.end());
  // The sweeps' second measure of progress (double_output.cpp): the innermost vertex's distance.
  const double innermost = innermost_log2_distance(e, crowd);
  CHECK(innermost < -250);
  CHECK(innermost >= std::log2(distance_from_center(e, *pushed)) - 1);
  std::size_t lps = 0;
  CHECK(sweep_crowd(e, crowd, {}, lps) >= 1);
  CHECK(lps == crowd.size());
  CHECK(distance_from_center(e, *pushed) > 1e-6);
  CHECK(innermost_log2_distance(e, crowd) > innermost + 200);
  CHECK(all_positive(e));
  CHECK(std::isinf(innermost_log2_distance(e, {})));
}
