// The mapping method end to end on the project's own meshes, every invariant asserted after every
// step (MapOptions::check), each result verified exactly on the independent code path.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>

#include "algorithm/map.hpp"
#include "algorithm/verify/verify_map.hpp"
#include "map_test_util.hpp"
#include "topology/generators.hpp"
#include "topology/topological_expansion.hpp"

#ifdef CMX_HAVE_TETGEN_BALL
#include "support/tetgen_ball.hpp"
#endif

using namespace cmx;
using namespace cmx::algorithm;
using namespace cmx::generators;
using cmx::test::map_checked;
using cmx::test::problem_from;

namespace {

const char* const shapes[] = {"tet", "stiff-tet", "sphere", "star:3"};

}  // namespace

TEST_CASE("a grid mapped onto its own boundary: the identity problem is solved and verified") {
  const GeneratedDomain d = perturbed_grid(3, 3, 3, 5);
  const MapResult r = map_checked(cmx::test::identity_problem(d));
  CHECK(r.stats.input_interior_vertices == 8);
  CHECK(r.stats.output_vertices >= r.stats.input_vertices);
}

TEST_CASE("perturbed grids onto the four generated boundary shapes") {
  const GeneratedDomain d = perturbed_grid(4, 3, 3, 11);
  for (const char* shape : shapes) {
    CAPTURE(shape);
    const MapResult r = map_checked(problem_from(d, shape));
    CHECK(r.stats.expansions_simple + r.stats.expansions_star_shapified + r.stats.expansions_inflated +
              r.stats.expansions_automatic >=
          r.stats.input_interior_vertices);
  }
}

TEST_CASE(
    "the float shortcuts are taken and counted: float-centre placements and closed cones proved on their "
    "basis") {
  const GeneratedDomain d = perturbed_grid(6, 5, 5, 3);
  std::size_t placed = 0, proved = 0;
  for (const char* shape : shapes) {
    CAPTURE(shape);
    const MapResult r = map_checked(problem_from(d, shape));
    // A float-centre placement is one popped vertex classified simple by its float guess.
    CHECK(r.stats.placements_float_centre <= r.stats.expansions_simple);
    CHECK(r.stats.placements_float_centre <= r.stats.lp_float_guesses);
    placed += r.stats.placements_float_centre;
    proved += r.stats.closed_by_support;
  }
  CHECK(placed >= 100);
  CHECK(proved >= 10);
}

TEST_CASE("voxel balls onto the four generated boundary shapes") {
  const GeneratedDomain d = voxel_ball(3, 2);
  for (const char* shape : shapes) {
    CAPTURE(shape);
    map_checked(problem_from(d, shape));
  }
}

TEST_CASE("thin slabs, where most tets touch the boundary, onto the generated shapes") {
  const GeneratedDomain one = thin_slab(5, 4, 3, 1);  // one layer: no interior vertex at all
  const GeneratedDomain two = thin_slab(5, 4, 3, 2);
  for (const char* shape : shapes) {
    CAPTURE(shape);
    map_checked(problem_from(one, shape));
    map_checked(problem_from(two, shape));
  }
}

#ifdef CMX_HAVE_TETGEN_BALL
TEST_CASE("Delaunay balls built through TetGen's library onto the generated shapes") {
  const test::TetgenBall ball = test::tetgen_ball(60, 40, 9);
  for (const char* shape : shapes) {
    CAPTURE(shape);
    map_checked(problem_from(ball.mesh, ball.positions, shape));
  }
}
#endif

TEST_CASE("the result is the same across runs and across expansion orders it is asked for") {
  const MapProblem p = problem_from(voxel_ball(2, 4), "star:8");
  const MapResult a = map_to_domain(p), b = map_to_domain(p);
  REQUIRE(a.outcome == MapOutcome::success);
  CHECK(a.tets == b.tets);
  CHECK(a.target == b.target);
  CHECK(a.source == b.source);
  for (const char* order : {"index", "random:5"}) {
    CAPTURE(order);
    MapOptions o;
    o.order = *topology::parse_expansion_order(order);
    map_checked(p, o);
  }
}

TEST_CASE("every precision policy, LP backend and filter gives a verified map") {
  const MapProblem p = problem_from(perturbed_grid(3, 3, 2, 3), "sphere");
  for (const char* precision : {"none", "dyadic", "shift", "segment"}) {
    CAPTURE(precision);
    MapOptions o;
    o.placement.precision = *parse_precision_policy(precision);
    map_checked(p, o);
  }
  for (const char* filter : {"exact", "interval", "mpfr:200"}) {
    CAPTURE(filter);
    MapOptions o;
    o.filter = *parse_filter_policy(filter);
    map_checked(p, o);
  }
  MapOptions o;
  o.placement.lp.backend = "exact";
  map_checked(p, o);
  o = {};
  o.placement.lp.norm = lp::Norm::l1;
  map_checked(p, o);
}

TEST_CASE("smoothing every few expansions keeps every invariant and moves vertices") {
  MapOptions o;
  o.smooth_every = 3;
  std::size_t moves = 0;
  for (const char* shape : shapes) {
    CAPTURE(shape);
    const MapResult r = map_checked(problem_from(perturbed_grid(4, 4, 3, 5), shape), o);
    moves += r.stats.smoothing_moves;
  }
  CHECK(moves > 0);
}

TEST_CASE("the shrink point has as many zero coordinates as its constraints allow") {
  // Doubles resolve points near p_c far better next to 0 (docs/algorithm.md, "Shrink point").
  // The generated shapes are centred at the origin: p_c is the origin itself.
  const MapProblem p = problem_from(perturbed_grid(4, 4, 3, 5), "tet");
  const MapResult at_origin = map_checked(p);
  CHECK(at_origin.center == HPoint());
  // The same boundary moved by +5 along x: y and z can still be 0, x cannot.
  MapProblem moved_x = p;
  for (auto& q : moved_x.boundary_positions) q[0] += 5;
  const MapResult r = map_checked(moved_x);
  CHECK(r.center.coordinate(0) != 0);
  CHECK(r.center.coordinate(1) == 0);
  CHECK(r.center.coordinate(2) == 0);
  // Moved along every axis: no coordinate can be 0, and the map is as valid.
  MapProblem moved = p;
  for (auto& q : moved.boundary_positions)
    for (auto& c : q) c += 5;
  const MapResult far = map_checked(moved);
  for (int i = 0; i < 3; ++i) CHECK(far.center.coordinate(i) != 0);
}

TEST_CASE("where the shrink constraints need splits, p_c still gets the zeros the kernel allows") {
  // No point satisfies the kernel and every one-interior-vertex tet's half-space, so tets are
  // split: those whose half-space excludes the kernel point with the most zero coordinates (the
  // origin here). Tested against the kernel's Chebyshev centre instead, p_c ended at (0, 1/2, 0)
  // on the ball and (1/64, 1/4, 1/4) on the slab, where doubles resolve its crowd far worse.
  const std::pair<MapProblem, const char*> cases[] = {{problem_from(voxel_ball(3, 1), "sphere"), "ball"},
                                                      {problem_from(thin_slab(8, 7, 1), "tet"), "slab"}};
  for (const auto& [p, name] : cases) {
    CAPTURE(name);
    const MapResult r = map_checked(p);
    CHECK(r.stats.split_no_shrink_point > 0);
    CHECK(r.center == HPoint());
  }
}

TEST_CASE("collapsing what each star-shapification added keeps every invariant, and collapses") {
  // A one-layer slab (no interior vertex) onto the tetrahedron: five star-shapifications, three
  // of whose added vertices collapse right away (measured with the origin as shrink point).
  const MapProblem p = problem_from(thin_slab(9, 8, 3, 1), "tet");
  const MapResult r = map_checked(p);  // the default; every invariant checked after every step
  CHECK(r.stats.expansions_star_shapified > 0);
  CHECK(r.stats.refinement_collapses > 0);
  MapOptions o;
  o.collapse_refinement = false;
  const MapResult off = map_checked(p, o);
  CHECK(off.stats.refinement_collapses == 0);
}

TEST_CASE("subclusters are expanded where no single vertex is simply expandable, keeping every invariant") {
  // One-layer slabs (no interior vertex): the cases found to need them, in two orders.
  MapOptions index;
  index.order = *topology::parse_expansion_order("index");
  const std::pair<MapProblem, MapOptions> cases[] = {
      {problem_from(thin_slab(8, 7, 1, 1), "stiff-tet"), index},
      {problem_from(thin_slab(10, 9, 1, 1), "star:3"), MapOptions{}}};
  for (const auto& [p, o] : cases) {
    const MapResult r = map_checked(p, o);  // every invariant after every step, then verified
    CHECK(r.stats.subcluster_expansions > 0);
    CHECK(r.stats.expansions_subcluster >= 2 * r.stats.subcluster_expansions);
    CHECK(r.stats.expansions_subcluster <= 4 * r.stats.subcluster_expansions);
    CHECK(r.stats.subcluster_candidates >= r.stats.subcluster_expansions);
    MapOptions off = o;
    off.subclusters = 1;
    const MapResult without = map_checked(p, off);
    CHECK(without.stats.subcluster_expansions == 0);
    CHECK(without.stats.subcluster_candidates == 0);
  }
}

TEST_CASE("strict-index expands the lowest-numbered candidate first, refined if need be") {
  // Where nothing needs refinement the sequence is exactly that of topological expansion in
  // index order (the order cmx topo-expand --order index reports), a different one from the
  // default's.
  const GeneratedDomain d = perturbed_grid(4, 4, 3, 2);
  const MapProblem p = cmx::test::identity_problem(d);
  MapOptions strict;
  strict.order = *topology::parse_expansion_order("strict-index");
  std::vector<std::uint32_t> sequence;
  strict.trace = [&sequence](const TraceRow& row) { sequence.push_back(row.vertex); };
  const MapResult r = map_checked(p, strict);
  REQUIRE(r.stats.expansions_star_shapified + r.stats.expansions_inflated + r.stats.expansions_subcluster == 0);
  const topology::TetMesh input(p.source.size(), p.tets);
  const topology::TopologicalExpansionResult t =
      topology::topological_expansion(input, *topology::parse_expansion_order("index"));
  REQUIRE(!t.stuck);
  REQUIRE(sequence.size() == t.sequence.size());
  for (std::size_t i = 0; i < sequence.size(); ++i) CHECK(sequence[i] == std::uint32_t(t.sequence[i]));
  const topology::TopologicalExpansionResult by_priority = topology::topological_expansion(input, {});
  CHECK(by_priority.sequence != t.sequence);
  // Where refinement is needed it still keeps every invariant and maps.
  for (const char* shape : {"star:3", "stiff-tet"}) {
    CAPTURE(shape);
    map_checked(problem_from(perturbed_grid(4, 3, 3, 11), shape), strict);
  }
}

TEST_CASE("star-shapification by shelling the cone base, tried first, keeps every invariant") {
  // MapOptions::shelled first runs the fallback (refinement/shelled_star_shapify.cpp) wherever a
  // cone is not star-shaped, so these runs use it on every kind of base the loop meets: discs
  // (shelled triangle by triangle, free edges split) and pinched or edged bases (pushed greedily).
  // Every invariant is checked after every step and each map is verified exactly.
  MapOptions first;
  first.shelled = ShelledMode::first;
  std::size_t shelled = 0, splits = 0;
  const MapProblem problems[] = {problem_from(thin_slab(9, 8, 3, 1), "tet"),
                                 problem_from(thin_slab(10, 9, 1, 1), "star:3"),
                                 problem_from(perturbed_grid(5, 4, 4, 3), "star:3"),
                                 problem_from(perturbed_grid(5, 4, 4, 3), "stiff-tet")};
  for (const MapProblem& p : problems) {
    const MapResult r = map_checked(p, first);
    CHECK(r.stats.shelled_star_shapifications <= r.stats.expansions_star_shapified);
    shelled += r.stats.shelled_star_shapifications;
    splits += r.stats.base_edge_splits;
    // The default keeps it for a run that would otherwise end stuck; these runs do not.
    CHECK(map_checked(p).stats.shelled_star_shapifications == 0);
  }
  CAPTURE(splits);
  CHECK(shelled >= 10);
}

TEST_CASE("without the final collapses every added vertex is kept, and the map is still valid") {
  const MapProblem p = problem_from(thin_slab(4, 4, 1, 1), "tet");
  MapOptions o;
  o.collapse = false;
  const MapResult kept = map_checked(p, o);
  const MapResult collapsed = map_checked(p);
  CHECK(collapsed.stats.output_vertices <= kept.stats.output_vertices);
  CHECK(collapsed.stats.collapsed == kept.stats.output_vertices - collapsed.stats.output_vertices);
}

TEST_CASE("merges remove added vertices that plain collapses keep, and the map stays valid") {
  std::size_t merged = 0;
  for (const char* shape : shapes) {
    CAPTURE(shape);
    const MapProblem p = problem_from(thin_slab(8, 6, 2, 1), shape);  // no interior vertex
    MapOptions off;
    off.merge = false;
    const MapResult plain = map_checked(p, off);
    const MapResult r = map_checked(p);
    CHECK(plain.stats.merged == 0);
    // The plain collapses come first and are the same; each merge (or collapse it enables)
    // removes one more vertex.
    CHECK(r.stats.output_vertices + r.stats.merged == plain.stats.output_vertices);
    CHECK(r.stats.collapsed == plain.stats.collapsed + r.stats.merged);
    merged += r.stats.merged;
  }
  CHECK(merged > 0);
  // With interior input vertices, added vertices also merge into them (their targets move, their
  // source positions stay: the verification's input_kept).
  std::size_t into_input = 0;
  for (const char* shape : shapes) {
    CAPTURE(shape);
    const MapProblem p = problem_from(perturbed_grid(6, 5, 5, 3), shape);
    MapOptions off;
    off.merge = false;
    const MapResult plain = map_checked(p, off);
    const MapResult r = map_checked(p);
    CHECK(r.verification.input_kept);
    CHECK(r.stats.output_vertices + r.stats.merged == plain.stats.output_vertices);
    into_input += r.stats.merged;
  }
  CHECK(into_input > 0);
}

TEST_CASE("the independent verifier rejects a broken map") {
  const MapProblem p = problem_from(perturbed_grid(2, 2, 2, 1), "tet");
  MapResult r = map_to_domain(p);
  REQUIRE(r.outcome == MapOutcome::success);
  std::vector<HPoint> source;
  for (const auto& q : p.source) source.emplace_back(q[0], q[1], q[2]);
  std::vector<HPoint> prescribed;
  for (const auto& q : p.boundary_positions) prescribed.emplace_back(q[0], q[1], q[2]);
  const VerificationInput in{&p.tets, &source, &p.boundary_vertices, &prescribed};
  CHECK(verify_map(in, r.tets, r.source, r.target).ok());
  // Swapping two vertices of one tet inverts it.
  auto tets = r.tets;
  std::swap(tets[0][0], tets[0][1]);
  const MapVerification inverted = verify_map(in, tets, r.source, r.target);
  CHECK_FALSE(inverted.ok());
  CHECK_FALSE(inverted.target_positive);
  CHECK(inverted.inverted >= 1);
  // A boundary vertex moved off its prescribed position.
  auto target = r.target;
  target[p.boundary_vertices[0]] = HPoint(Rational(1000), Rational(0), Rational(0));
  const MapVerification moved = verify_map(in, r.tets, r.source, target);
  CHECK_FALSE(moved.ok());
  CHECK_FALSE(moved.input_kept);
}

TEST_CASE("double coordinates are checked with exact predicates") {
  const MapProblem p = problem_from(perturbed_grid(3, 2, 2, 2), "sphere");
  const MapResult r = map_to_domain(p);
  REQUIRE(r.outcome == MapOutcome::success);
  std::vector<std::array<double, 3>> d;
  for (const HPoint& q : r.target) d.push_back(q.approx());
  const DoubleCheck ok = check_doubles(r.tets, d);
  CHECK(ok.inverted + ok.degenerate <= r.tets.size());
  // Collapsing every vertex onto one point makes every tet degenerate.
  std::vector<std::array<double, 3>> flat(d.size(), {0.0, 0.0, 0.0});
  const DoubleCheck bad = check_doubles(r.tets, flat);
  CHECK(bad.degenerate == r.tets.size());
  CHECK_FALSE(bad.valid());
}

TEST_CASE(
    "the compact Bing's house in a box, its house deferred: topology meets the NOBUENOSS, geometry maps") {
  // The order that leaves exactly the house (a NOBUENOSS) to topological expansion does not lead
  // the geometric loop there: candidates whose refinement fails wait, and house vertices that
  // are expandable while other cluster vertices still touch them go first. What the run does
  // instead is map, every invariant checked after every step (docs/algorithm/expansion.md).
  const GeneratedDomain d = compact_bings_house_box(2, 0);
  const std::uint32_t n = static_cast<std::uint32_t>(d.mesh.num_vertices());
  const std::uint32_t first = n - 309;  // the house's vertices are the last 309
  MapOptions deferred;
  deferred.order =
      *topology::parse_expansion_order("priority,defer:" + std::to_string(first) + "-" + std::to_string(n));
  const topology::TopologicalExpansionResult t = topology::topological_expansion(d.mesh, deferred.order);
  REQUIRE(t.stuck);
  REQUIRE(t.remaining.size() == 309);
  CHECK(t.remaining.front() == VertexId(first));
  std::vector<std::uint32_t> sequence;
  deferred.trace = [&sequence](const TraceRow& row) { sequence.push_back(row.vertex); };
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_UNDEFINED__)
  // Checking every invariant after every step costs 13 s here, ten times that under the
  // sanitizers: there the map alone, verified.
  const MapResult r = map_to_domain(problem_from(d, "sphere"), deferred);
  REQUIRE_MESSAGE(r.outcome == MapOutcome::success, r.message);
  CHECK_MESSAGE(r.verification.ok(), r.verification.first_failure);
#else
  const MapResult r = map_checked(problem_from(d, "sphere"), deferred);
#endif
  CHECK(!r.stats.nobuenoss);
  // The first house vertex goes while input vertices off the house are still in the cluster.
  const auto house =
      std::find_if(sequence.begin(), sequence.end(), [&](std::uint32_t v) { return v >= first && v < n; });
  REQUIRE(house != sequence.end());
  std::size_t off_house_before = 0;
  for (auto it = sequence.begin(); it != house; ++it) off_house_before += *it < first ? 1 : 0;
  const std::size_t off_house_interior = d.mesh.num_vertices() - 309 - r.stats.input_boundary_vertices;
  CHECK(off_house_before < off_house_interior);
  MESSAGE("first house vertex after " << off_house_before << " of the " << off_house_interior
                                      << " other interior vertices");
}

TEST_CASE("the compact Bing's house in a box: a shelling replayed from the start hands over and maps") {
  // Paper Alg. 2 from the shrunk state, the house deferred. After each planned expansion the
  // replay drains the refinement's own cluster vertices; here a refined expansion of one left
  // exactly one more, round after round, and the run reached its time limit with 670 cluster
  // vertices left. The drain now gives up after tuning::replay_drain_patience rounds without
  // fewer left, the plan goes on, and greedy expansion takes over (docs/algorithm/expansion.md).
  const GeneratedDomain d = compact_bings_house_box(2, 0);
  const std::uint32_t n = static_cast<std::uint32_t>(d.mesh.num_vertices());
  MapOptions o;
  o.order =
      *topology::parse_expansion_order("priority,defer:" + std::to_string(n - 309) + "-" + std::to_string(n));
  o.replay = ReplayMode::until_greedy;
  o.time_limit_seconds = 1200;  // the chase, were it back, ends here rather than hanging the suite
  const MapResult r = map_to_domain(problem_from(d, "sphere"), o);
  REQUIRE_MESSAGE(r.outcome == MapOutcome::success, r.message);
  CHECK_MESSAGE(r.verification.ok(), r.verification.first_failure);
  CHECK(r.doubles.check.valid());
  CHECK(r.stats.replay.ran);
  CHECK(r.stats.replay.handed_over);
  CHECK_FALSE(r.stats.nobuenoss);
  CHECK(r.stats.replay.expansions > 0);
  CHECK(r.stats.replay.drains_left > 0);  // the case needs the patience
  // The plan was chosen by its topological replay's handover, which the report gives.
  CHECK(r.stats.replay.plan_handover >= 1);
  CHECK(r.stats.replay.plan_handover <= r.stats.replay.steps + 1);
  MESSAGE(r.stats.replay.expansions << " planned expansions, " << r.stats.replay.drained << " drained, "
                                    << r.stats.replay.drains_left << " drains given up");
}
