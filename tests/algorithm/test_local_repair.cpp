// Local repair (algorithm/local/local_repair.hpp): an initial map's defects enclosed in stars,
// each star mapped by the shrink method, the rest kept; verified as a whole, the same for every
// thread count, and the automatic choice falling back to the global method when it should.
#include <doctest/doctest.h>

#include <random>
#include <string>
#include <vector>

#include "generators/domain_generators.hpp"
#include "algorithm/map.hpp"
#include "algorithm/tuning.hpp"
#include "map_test_util.hpp"

using namespace cmx;
using namespace cmx::algorithm;
using namespace cmx::generators;
using namespace cmx::test;

namespace {

// The problem's source positions as its initial map, every interior vertex then moved by up to
// `amplitude` times the grid's cell in each coordinate (seeded): some tets fold, most do not.
MapProblem with_displaced_interior(MapProblem p, double amplitude, std::uint64_t seed) {
  std::vector<char> prescribed(p.source.size(), 0);
  for (std::uint32_t v : p.boundary_vertices) prescribed[v] = 1;
  p.initial_target = p.source;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(-amplitude, amplitude);
  for (std::size_t v = 0; v < p.source.size(); ++v)
    if (!prescribed[v])
      for (Rational& c : p.initial_target[v]) c += rational_from_double(jitter(rng));
  for (std::size_t i = 0; i < p.boundary_vertices.size(); ++i)
    p.initial_target[p.boundary_vertices[i]] = p.boundary_positions[i];
  return p;
}

MapOptions given(std::size_t threads = 1) {
  MapOptions o;
  o.init = InitialMapKind::given;
  o.threads = threads;
  return o;
}

void check_verified(const MapResult& r) {
  REQUIRE_MESSAGE(r.outcome == MapOutcome::success, r.message);
  CHECK_MESSAGE(r.verification.ok(), r.verification.first_failure);
}

}  // namespace

TEST_CASE("an initial map that is already valid is the output: no star, nothing moved") {
  const GeneratedDomain d = perturbed_grid(4, 4, 3, 7);
  MapProblem p = identity_problem(d);
  p.initial_target = p.source;
  const MapResult r = map_to_domain(p, given());
  check_verified(r);
  CHECK(r.stats.local.stars == 0);
  CHECK(r.stats.local.inverted + r.stats.local.flat == 0);
  CHECK(r.stats.output_vertices == p.source.size());
  CHECK(r.tets == p.tets);
  for (std::size_t v = 0; v < p.source.size(); ++v) CHECK(r.target[v] == HPoint(p.source[v][0], p.source[v][1], p.source[v][2]));
  CHECK(r.doubles.check.valid());
}

TEST_CASE("displaced interior vertices: stars around the folds, the rest kept, verified") {
  const GeneratedDomain d = perturbed_grid(6, 6, 5, 3);
  const MapProblem p = with_displaced_interior(identity_problem(d), 0.45, 11);
  const MapResult r = map_to_domain(p, given());
  check_verified(r);
  const LocalRepairStatistics& l = r.stats.local;
  CHECK(std::string(l.init) == "given");
  CHECK(l.inverted + l.flat > 0);
  REQUIRE(l.stars > 0);
  CHECK(l.share < 1.0);
  // Vertices no star moved keep the initial map's position exactly.
  std::size_t kept = 0;
  for (std::size_t v = 0; v < p.source.size(); ++v) {
    const auto& q = p.initial_target[v];
    kept += r.target[v] == HPoint(q[0], q[1], q[2]);
  }
  CHECK(kept > p.boundary_vertices.size());
}

TEST_CASE("the local repair's output is the same for every thread count") {
  const GeneratedDomain d = perturbed_grid(7, 6, 6, 5);
  const MapProblem p = with_displaced_interior(identity_problem(d), 0.5, 23);
  const MapResult one = map_to_domain(p, given(1));
  check_verified(one);
  REQUIRE(one.stats.local.stars > 1);
  for (std::size_t threads : {2u, 3u, 8u}) {
    CAPTURE(threads);
    const MapResult many = map_to_domain(p, given(threads));
    check_verified(many);
    CHECK(many.stats.local.threads == std::min<std::size_t>(threads, one.stats.local.stars));
    CHECK(many.tets == one.tets);
    CHECK(many.source == one.source);
    CHECK(many.target == one.target);
    CHECK(many.doubles.target == one.doubles.target);
  }
}

TEST_CASE("a Tutte initial map on a star-shaped target maps and verifies, and its trace rows name their stars") {
  const MapProblem p = problem_from(voxel_ball(4, 2), "star:5");
  MapOptions o;
  o.init = InitialMapKind::tutte;
  std::vector<TraceRow> rows;
  o.trace = [&](const TraceRow& row) { rows.push_back(row); };
  const MapResult r = map_to_domain(p, o);
  check_verified(r);
  CHECK(std::string(r.stats.local.init) == "tutte");
  if (r.stats.local.stars == 0) return;  // a Tutte map without a fold: nothing to trace
  REQUIRE(!rows.empty());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    CHECK(rows[i].star >= 1);
    CHECK(rows[i].star <= r.stats.local.stars);
    if (i > 0) CHECK(rows[i].step > rows[i - 1].step);
  }
}

TEST_CASE("auto falls back to the global method when the stars would be too large, and says why") {
  const MapProblem p = problem_from(voxel_ball(4, 2), "star:5");
  MapOptions o;
  o.init = InitialMapKind::automatic;
  o.star_max_share = 1e-6;  // no star is that small
  o.star_max_defect_share = 1.0;  // past the test in doubles, to the stars
  const MapResult r = map_to_domain(p, o);
  check_verified(r);
  REQUIRE(r.stats.local.inverted + r.stats.local.flat > 0);  // the Tutte map folds on this target
  CHECK(std::string(r.stats.local.init) == "shrink");
  CHECK(!r.stats.local.fallback.empty());
  const MapResult global = map_to_domain(p);
  CHECK(r.tets == global.tets);
  CHECK(r.target == global.target);
}

TEST_CASE("auto falls back before any exact classification when the Tutte map folds too much in doubles") {
  const MapProblem p = problem_from(voxel_ball(4, 2), "star:5");
  MapOptions o;
  o.init = InitialMapKind::automatic;
  o.star_max_defect_share = 0;  // any fold is too many
  const MapResult r = map_to_domain(p, o);
  check_verified(r);
  CHECK(std::string(r.stats.local.init) == "shrink");
  CHECK(r.stats.local.inverted + r.stats.local.flat == 0);  // not classified exactly
  CHECK(r.stats.local.fallback.find("in doubles, more than 0 %") != std::string::npos);
  o.star_max_defect_share = 1.0;
  o.star_max_share = 1.0;
  const MapResult local = map_to_domain(p, o);
  check_verified(local);
  CHECK(std::string(local.stats.local.init) == "tutte");  // the same map passes a looser share
}

TEST_CASE("an explicit initial map needs exact coordinates, and one of the right size") {
  const GeneratedDomain d = perturbed_grid(3, 3, 3, 1);
  MapProblem p = identity_problem(d);
  p.initial_target = p.source;
  MapOptions o = given();
  o.placement.arith = *parse_coordinate_arith("double", nullptr);
  CHECK_THROWS_AS(map_to_domain(p, o), MapError);
  p.initial_target.pop_back();
  CHECK_THROWS_AS(map_to_domain(p, given()), MapError);
}

TEST_CASE("auto does not start a Tutte factorisation that half the time limit cannot pay for") {
  // At the assumed 1e9 multiply-adds per second (algorithm/tuning.hpp), a limit of 1e-7 s allows
  // 50: the factorisation is not started, the run goes on with the global method (which then
  // meets the time limit), and the fallback says why.
  const MapProblem p = problem_from(voxel_ball(4, 2), "star:5");
  MapOptions o;
  o.init = InitialMapKind::automatic;
  o.time_limit_seconds = 1e-7;
  const MapResult r = map_to_domain(p, o);
  CHECK(std::string(r.stats.local.init) == "shrink");
  CHECK(r.stats.local.fallback.find("sparse Cholesky factorisation would take about") != std::string::npos);
  CHECK(r.stats.local.fallback.find("more than the 50 allowed") != std::string::npos);
  CHECK(r.outcome == MapOutcome::time_limit);
}

TEST_CASE("auto gives up a Tutte map that an approximate solve shows folding far too much, with the same output") {
  CHECK(MapOptions{}.tutte_screen_multiply_adds == tuning::tutte_screen_multiply_adds);
  const MapProblem p = problem_from(voxel_ball(4, 2), "star:5");  // its Tutte map folds about a quarter
  MapOptions o;
  o.init = InitialMapKind::automatic;
  o.tutte_screen_multiply_adds = 0;  // screen every map
  const MapResult screened = map_to_domain(p, o);
  check_verified(screened);
  CHECK(std::string(screened.stats.local.init) == "shrink");
  CHECK(screened.stats.local.fallback.find("solved approximately") != std::string::npos);
  CHECK(screened.stats.local.fallback.find("more than 10 %") != std::string::npos);
  MapOptions plain;
  plain.init = InitialMapKind::automatic;  // far below the default cost: factorised, then given up
  const MapResult factorised = map_to_domain(p, plain);
  CHECK(factorised.stats.local.fallback.find("of the initial map are inverted or flat") != std::string::npos);
  CHECK(screened.tets == factorised.tets);
  CHECK(screened.target == factorised.target);
}

TEST_CASE("a Tutte map that folds little passes the screen and is repaired as without it") {
  const MapProblem p = identity_problem(perturbed_grid(6, 6, 6, 3));  // its own box: few folds
  MapOptions o;
  o.init = InitialMapKind::automatic;
  o.tutte_screen_multiply_adds = 0;
  const MapResult screened = map_to_domain(p, o);
  check_verified(screened);
  CHECK(std::string(screened.stats.local.init) == "tutte");
  MapOptions plain;
  plain.init = InitialMapKind::automatic;
  const MapResult factorised = map_to_domain(p, plain);
  CHECK(std::string(factorised.stats.local.init) == "tutte");
  CHECK(screened.tets == factorised.tets);
  CHECK(screened.target == factorised.target);
}
