// Double output (paper Sec. 4.2.7): every --snap policy on small generated cases, the doubles'
// verdict recounted on a second code path (exact homogeneous orientation of the doubles), the
// exact map still verified after the Chebyshev moves, a crowded map that rounding breaks and
// repair mends, and the same map re-mapped from its own nearest doubles.
#include <doctest/doctest.h>

#include <chrono>
#include <cmath>

#include "algorithm/doubles/double_output.hpp"
#include "algorithm/expansion/expansion_cone.hpp"
#include "algorithm/local/remap_doubles.hpp"
#include "algorithm/problem/validate_problem.hpp"
#include "algorithm/map.hpp"
#include "algorithm/run_control.hpp"
#include "algorithm/tuning.hpp"
#include "arith/rounding.hpp"
#include "kernel/orient.hpp"
#include "map_test_util.hpp"
#include "topology/complex_queries.hpp"

using namespace cmx;
using namespace cmx::algorithm;
using namespace cmx::generators;
using cmx::test::map_checked;
using cmx::test::problem_from;

namespace {

const SnapPolicy policies[] = {SnapPolicy::none, SnapPolicy::nearest, SnapPolicy::chebyshev_pass,
                               SnapPolicy::repair};

// The doubles' verdict through HPoint and the exact-only filter (not the raw-double cascade).
DoubleCheck recount(const std::vector<topology::Tet>& tets, const std::vector<std::array<double, 3>>& d) {
  DoubleCheck c;
  const FilterPolicy exact = *parse_filter_policy("exact");
  for (const auto& t : tets) {
    std::array<HPoint, 4> p;
    for (int i = 0; i < 4; ++i) p[std::size_t(i)] = HPoint::from_doubles(d[t[i]][0], d[t[i]][1], d[t[i]][2]);
    const Sign s = orient3d(p[0], p[1], p[2], p[3], {exact, nullptr});
    if (s == Sign::negative) ++c.inverted;
    if (s == Sign::zero) ++c.degenerate;
  }
  return c;
}

std::array<double, 3> nearest(const HPoint& p) {
  return {to_double(p.coordinate(0)), to_double(p.coordinate(1)), to_double(p.coordinate(2))};
}

void check_double_map(const MapProblem& p, const MapResult& r, SnapPolicy policy) {
  const DoubleMap& d = r.doubles;
  REQUIRE(d.target.size() == r.target.size());
  CHECK(d.checked == (policy != SnapPolicy::none));
  // Boundary vertices keep the nearest doubles of their prescribed positions.
  for (std::size_t i = 0; i < p.boundary_vertices.size(); ++i) {
    const auto& q = p.boundary_positions[i];
    const std::array<double, 3> want{to_double(q[0]), to_double(q[1]), to_double(q[2])};
    CHECK(d.target[p.boundary_vertices[i]] == want);
  }
  if (policy == SnapPolicy::none || policy == SnapPolicy::nearest || policy == SnapPolicy::chebyshev_pass)
    for (std::size_t v = 0; v < r.target.size(); ++v) CHECK(d.target[v] == nearest(r.target[v]));
  if (d.checked) {
    const DoubleCheck again = recount(r.tets, d.target);
    CHECK(again.inverted == d.check.inverted);
    CHECK(again.degenerate == d.check.degenerate);
  }
  if (policy == SnapPolicy::none || policy == SnapPolicy::nearest) CHECK(r.stats.chebyshev_moves == 0);
}

}  // namespace

TEST_CASE("every snap policy: the exact map verifies and the doubles verdict holds on a second code path") {
  const GeneratedDomain grid = perturbed_grid(4, 3, 3, 7);
  const GeneratedDomain slab = thin_slab(5, 4, 3, 1);
  for (const SnapPolicy policy : policies)
    for (const char* shape : {"tet", "stiff-tet", "sphere", "star:5"}) {
      CAPTURE(to_string(policy));
      CAPTURE(shape);
      MapOptions o;
      o.snap = policy;
      for (const GeneratedDomain* dom : {&grid, &slab}) {
        const MapProblem p = problem_from(*dom, shape);
        const MapResult r = map_checked(p, o);
        check_double_map(p, r, policy);
        if (policy == SnapPolicy::repair) CHECK(r.doubles.check.valid());
      }
    }
}

TEST_CASE("repair keeps the plain rounding when it is valid, and otherwise moves vertices") {
  // A grid onto the sphere: its nearest doubles are valid, so repair makes no move at all.
  MapOptions nearest_only;
  nearest_only.snap = SnapPolicy::nearest;
  const MapProblem easy = problem_from(perturbed_grid(4, 3, 3, 7), "sphere");
  const MapResult plain = map_checked(easy, nearest_only);
  REQUIRE(plain.doubles.check.valid());
  const MapResult repaired = map_checked(easy);  // the default, repair
  CHECK(repaired.stats.chebyshev_moves == 0);
  CHECK(repaired.target == plain.target);
  CHECK(repaired.doubles.target == plain.doubles.target);
  CHECK(repaired.doubles.check.valid());
}

TEST_CASE("every combination of precision policy and snap policy gives a verified map") {
  const MapProblem p = problem_from(perturbed_grid(3, 3, 2, 3), "sphere");
  for (const char* precision : {"none", "dyadic", "shift", "segment"})
    for (const SnapPolicy policy : policies) {
      CAPTURE(precision);
      CAPTURE(to_string(policy));
      MapOptions o;
      o.placement.precision = *parse_precision_policy(precision);
      o.snap = policy;
      const MapResult r = map_checked(p, o);
      check_double_map(p, r, policy);
    }
}

TEST_CASE("the Chebyshev pass keeps the exact map valid and the result deterministic") {
  const MapProblem p = problem_from(voxel_ball(3, 4), "star:9");
  MapOptions o;
  o.snap = SnapPolicy::chebyshev_pass;
  const MapResult a = map_checked(p, o);
  const MapResult b = map_checked(p, o);
  CHECK(a.stats.chebyshev_moves > 0);
  CHECK(a.target == b.target);
  CHECK(a.doubles.target == b.doubles.target);
}

namespace {

// A valid exact map of a perturbed grid onto a sphere in which one interior vertex sits within
// 2^-80 of a boundary neighbour (on the segment between them, still strictly inside its star's
// kernel, checked exactly): its nearest double is the neighbour's, so rounding flattens tets.
struct CrowdedMap {
  MapProblem problem;
  MapResult exact;  // the map before the move
  Embedding e;      // with the crowded vertex
};

CrowdedMap crowded_map() {
  const MapProblem p = problem_from(perturbed_grid(3, 3, 3, 3), "sphere");
  MapOptions o;
  o.snap = SnapPolicy::none;
  CrowdedMap out{p, map_checked(p, o), {}};
  const MapResult& r = out.exact;
  Embedding& e = out.e;
  e.mesh = topology::TetMesh(r.target.size(), r.tets);
  e.source = r.source;
  e.target = r.target;
  e.unexpanded.assign(r.target.size(), 0);
  e.boundary = topology::boundary_vertex_flags(e.mesh);
  bool crowded = false;
  for (VertexId v{0}; v < e.num_vertices() && !crowded; ++v) {
    if (e.boundary[v]) continue;
    const ExpansionCone cone = gather_expansion_cone(e, v);
    for (TetId t : e.mesh.tets_of(v)) {
      for (VertexId a : e.mesh.tet(t)) {
        if (a == v || !e.boundary[a]) continue;
        const Rational eps(Integer(1), Integer(1) << 80);
        std::array<Rational, 3> x;
        for (int i = 0; i < 3; ++i)
          x[std::size_t(i)] =
              e.target[a].coordinate(i) + eps * (e.target[v].coordinate(i) - e.target[a].coordinate(i));
        const HPoint xp(x[0], x[1], x[2]);
        if (!strictly_inside(cone, xp) || nearest(xp) != nearest(e.target[a])) continue;
        e.target[v] = xp;
        crowded = true;
        break;
      }
      if (crowded) break;
    }
  }
  REQUIRE(crowded);
  return out;
}

}  // namespace

TEST_CASE("a map crowded below double resolution: plain rounding flattens tets") {
  CrowdedMap m = crowded_map();
  const DoubleMap plain = make_double_map(m.e, SnapPolicy::nearest, {});
  REQUIRE_FALSE(plain.check.valid());
  CHECK(plain.check.degenerate > 0);
  CHECK_FALSE(plain.stopped_at_deadline);
}

TEST_CASE("a crowded map with a time limit already passed: doubles checked as they stand") {
  const CrowdedMap m = crowded_map();
  Embedding rounded = m.e;
  const DoubleMap plain = make_double_map(rounded, SnapPolicy::nearest, {});
  Embedding late = m.e;
  MapOptions past;
  past.time_limit_seconds = 1e-9;
  RunControl control(past, std::chrono::steady_clock::now() - std::chrono::seconds(1));
  const DoubleMap stopped = make_double_map(late, SnapPolicy::repair, {}, &control);
  CHECK(stopped.stopped_at_deadline);
  CHECK(stopped.chebyshev_moves == 0);
  CHECK(stopped.check.degenerate == plain.check.degenerate);
  CHECK(stopped.target == plain.target);
  CHECK(late.target == m.e.target);
}

// Stopped at any poll of the repair: the exact map stays valid, and the doubles are the valid
// doubles of a finished repair or the plain rounding of the exact map as it was.
TEST_CASE("a crowded map's repair stopped at any poll keeps the exact map valid") {
  const CrowdedMap m = crowded_map();
  const Embedding& e = m.e;
  Embedding rounded = e;
  const DoubleMap plain = make_double_map(rounded, SnapPolicy::nearest, {});
  std::size_t polls = 0;
  {
    MapOptions counting;
    counting.stop = [&](std::string_view phase) {
      CHECK(phase == "doubles");
      ++polls;
      return false;
    };
    Embedding copy = e;
    RunControl never(counting, std::chrono::steady_clock::now());
    CHECK(make_double_map(copy, SnapPolicy::repair, {}, &never).check.valid());
  }
  REQUIRE(polls > 2);
  for (std::size_t cut = 0; cut < polls; ++cut) {
    CAPTURE(cut);
    MapOptions cutting;
    std::size_t seen = 0;
    cutting.stop = [&](std::string_view) { return seen++ >= cut; };
    Embedding copy = e;
    RunControl control(cutting, std::chrono::steady_clock::now());
    const DoubleMap d = make_double_map(copy, SnapPolicy::repair, {}, &control);
    for (TetId t : copy.mesh.live_tets()) CHECK(copy.orient_target(copy.mesh.tet(t)) == Sign::positive);
    if (d.check.valid()) continue;
    CHECK(d.stopped_at_deadline);
    CHECK(d.target == plain.target);
    CHECK(copy.target == e.target);
  }
}

TEST_CASE("a crowded map's repair separates the flattened tets and keeps the exact map valid") {
  CrowdedMap m = crowded_map();
  Embedding& e = m.e;
  const MapResult& r = m.exact;
  const DoubleMap mended = make_double_map(e, SnapPolicy::repair, {});
  CHECK(mended.check.valid());
  CHECK_FALSE(mended.stopped_at_deadline);
  CHECK(recount(r.tets, mended.target).degenerate == 0);
  // The exact map is still valid after the exact moves repair made.
  for (TetId t : e.mesh.live_tets()) CHECK(e.orient_target(e.mesh.tet(t)) == Sign::positive);
  for (VertexId v{0}; v < e.num_vertices(); ++v)
    if (e.boundary[v]) CHECK(e.target[v] == r.target[v]);
}

TEST_CASE(
    "repair rounds a boundary vertex to another double within one ulp when the nearest flattens an "
    "all-boundary tet") {
  // One tet, all four vertices prescribed: a flat but positive tet whose apex height 2^-60 above
  // z = 1 is not a double. The nearest doubles put the apex at z = 1 (flat); the double on the
  // exact value's other side, 1 + 2^-52, keeps it positive. No interior vertex can help.
  MapProblem p;
  p.tets = topology::make_tets({{0, 1, 2, 3}});
  p.source = {{Rational(0), Rational(0), Rational(0)},
              {Rational(1), Rational(0), Rational(0)},
              {Rational(0), Rational(1), Rational(0)},
              {Rational(0), Rational(0), Rational(1)}};
  p.boundary_vertices = {0, 1, 2, 3};
  const Rational apex_z = Rational(1) + rational_from_double(std::ldexp(1.0, -60));
  p.boundary_positions = {{Rational(0), Rational(0), Rational(1)},
                          {Rational(1), Rational(0), Rational(1)},
                          {Rational(0), Rational(1), Rational(1)},
                          {Rational(1, 3), Rational(1, 3), apex_z}};
  MapOptions nearest;
  nearest.snap = SnapPolicy::nearest;
  const MapResult plain = map_checked(p, nearest);
  CHECK(plain.doubles.check.degenerate == 1);
  const MapResult r = map_checked(p);  // repair, the default
  CHECK(r.doubles.check.valid());
  CHECK(recount(r.tets, r.doubles.target).degenerate == 0);
  CHECK(recount(r.tets, r.doubles.target).inverted == 0);
  CHECK(r.stats.snap_boundary_rerounded == 1);
  CHECK(r.doubles.target[3][2] == std::nextafter(1.0, 2.0));
  for (int v = 0; v < 3; ++v) CHECK(r.doubles.target[std::size_t(v)] == plain.doubles.target[std::size_t(v)]);
}

// The repair's last stage on the crowded map, run directly (the earlier stages would mend this
// one): its nearest doubles, the crowded vertex on its boundary neighbour, are an initial map of
// its mesh whose flat tets get a star of their own; the map kept is verified against the
// original problem and its doubles are valid.
TEST_CASE("a crowded map re-mapped from its own nearest doubles: valid doubles, verified against the problem") {
  CrowdedMap m = crowded_map();
  MapResult r = m.exact;
  r.target = m.e.target;
  Embedding rounded = m.e;
  r.doubles = make_double_map(rounded, SnapPolicy::nearest, {});
  REQUIRE(r.doubles.check.degenerate > 0);
  MapOptions o;
  CHECK(wants_remap_from_doubles(o, r));
  MapOptions no;
  no.snap = SnapPolicy::nearest;
  CHECK_FALSE(wants_remap_from_doubles(no, r));
  no = o;
  no.remap_doubles = false;  // the second pass itself, and a local repair's stars
  CHECK_FALSE(wants_remap_from_doubles(no, r));

  const MapProblem again = problem_from_doubles(r);
  CHECK(again.tets == r.tets);
  REQUIRE(again.initial_target.size() == r.target.size());
  for (std::size_t v = 0; v < r.target.size(); ++v)
    for (int i = 0; i < 3; ++i)
      CHECK(again.initial_target[v][std::size_t(i)] == rational_from_double(r.doubles.target[v][std::size_t(i)]));

  const ValidatedProblem v = validate_problem(m.problem, FilterPolicy{}, lp::ChebyshevOptions{});
  const VerificationInput in{&m.problem.tets, &v.source, &m.problem.boundary_vertices, &v.boundary_positions};
  const double first_pass_init = 1e6;  // a first pass's initial-map time stays in the report
  r.stats.local.seconds_init = first_pass_init;
  remap_from_doubles(o, in, 0, r);
  CHECK(r.stats.local.seconds_init >= first_pass_init);
  CHECK_MESSAGE(r.verification.ok(), r.verification.first_failure);
  CHECK(r.doubles.check.valid());
  CHECK(recount(r.tets, r.doubles.target).degenerate == 0);
  CHECK(recount(r.tets, r.doubles.target).inverted == 0);
  CHECK(r.stats.local.stars >= 1);
  CHECK(r.stats.local.fallback.find("re-mapped from them") != std::string::npos);
}

// The passes of the re-map: each goes on from the last one's doubles only while the count of
// inverted or flat tets falls, and at most tuning::doubles_remap_passes of them run.
TEST_CASE("re-map passes: adopt valid doubles, go on while the bad tets fall, else stop") {
  MapResult again;
  again.outcome = MapOutcome::success;
  again.doubles.checked = true;
  CHECK(after_remap_pass(1, 409, again) == RemapStep::adopt);  // nothing inverted or flat
  again.doubles.check.inverted = 100;
  again.doubles.check.degenerate = 20;
  CHECK(after_remap_pass(1, 409, again) == RemapStep::go_on);
  CHECK(after_remap_pass(1, 120, again) == RemapStep::stop);  // no fewer than before
  CHECK(after_remap_pass(1, 121, again) == RemapStep::go_on);
  CHECK(after_remap_pass(tuning::doubles_remap_passes, 409, again) == RemapStep::stop);
  again.doubles.stopped_at_deadline = true;
  CHECK(after_remap_pass(1, 409, again) == RemapStep::stop);
  again.doubles.stopped_at_deadline = false;
  again.outcome = MapOutcome::stuck;
  CHECK(after_remap_pass(1, 409, again) == RemapStep::stop);
  again.outcome = MapOutcome::success;
  again.doubles.checked = false;
  CHECK(after_remap_pass(1, 409, again) == RemapStep::stop);
}

// Without valid doubles from any pass, the one that leaves the fewest bad tets is kept when it
// leaves fewer than the first map: a pass that stops the passes (no pass left) can still be it.
TEST_CASE("re-map passes: the pass kept without valid doubles leaves strictly fewer bad tets") {
  MapResult again;
  again.outcome = MapOutcome::success;
  again.doubles.checked = true;
  again.doubles.check.inverted = 8;
  again.doubles.check.degenerate = 2;
  CHECK(improves_on(158, again));
  CHECK(improves_on(11, again));
  CHECK_FALSE(improves_on(10, again));  // no fewer
  CHECK(after_remap_pass(tuning::doubles_remap_passes, 108, again) == RemapStep::stop);
  CHECK(improves_on(108, again));            // the last pass, kept although no pass follows
  again.doubles.stopped_at_deadline = true;  // a repair cut short: its count is not the map's
  CHECK_FALSE(improves_on(158, again));
  again.doubles.stopped_at_deadline = false;
  again.doubles.checked = false;
  CHECK_FALSE(improves_on(158, again));
  again.doubles.checked = true;
  again.outcome = MapOutcome::stuck;
  CHECK_FALSE(improves_on(158, again));
}
