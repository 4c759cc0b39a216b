// The method on non-exact coordinates (MapOptions::placement.arith, `cmx map --arith`): runs that
// succeed hold only representable coordinates and verify exactly; runs that lose validity say
// where, and the tet they name is, recomputed here, really inverted or flat.
#include <doctest/doctest.h>

#include <algorithm>

#include "algorithm/map.hpp"
#include "kernel/orient.hpp"
#include "map_test_util.hpp"

using namespace cmx;
using namespace cmx::algorithm;
using namespace cmx::generators;
using cmx::test::problem_from;

namespace {

MapOptions with_arith(const char* name) {
  MapOptions o;
  o.placement.arith = *parse_coordinate_arith(name);
  return o;
}

bool all_representable(const std::vector<HPoint>& points, const CoordinateArith& arith) {
  return std::all_of(points.begin(), points.end(), [&](const HPoint& p) { return arith.representable(p); });
}

}  // namespace

TEST_CASE("double and mpfr:BITS coordinates: maps verified exactly, every coordinate representable") {
  for (const char* arith : {"double", "mpfr:53", "mpfr:64", "mpfr:100"}) {
    for (const char* shape : {"sphere", "star:3"}) {
      CAPTURE(arith);
      CAPTURE(shape);
      MapOptions o = with_arith(arith);
      o.check = true;
      const MapResult r = map_to_domain(problem_from(perturbed_grid(3, 3, 3, 7), shape), o);
      REQUIRE_MESSAGE(r.outcome == MapOutcome::success, r.message);
      CHECK_MESSAGE(r.verification.ok(), r.verification.first_failure);
      CHECK(r.stats.input_rounded == 0);  // generated inputs are doubles
      CHECK(all_representable(r.target, o.placement.arith));
      CHECK(all_representable(r.source, o.placement.arith));
      CHECK(r.doubles.checked);
      CHECK(r.doubles.check.valid());  // doubles (or finer floats) rounded to doubles: still checked
    }
  }
}

TEST_CASE("a double run rounds an input that is not in doubles and maps the rounded problem") {
  // The grid scaled by 1/10: most coordinates are not doubles.
  GeneratedDomain d = perturbed_grid(3, 3, 2, 0, 0.0);
  for (auto& p : d.positions)
    for (Rational& c : p) c /= 10;
  const MapProblem p = cmx::test::identity_problem(d);
  const MapResult r = map_to_domain(p, with_arith("double"));
  REQUIRE_MESSAGE(r.outcome == MapOutcome::success, r.message);
  CHECK(r.stats.input_rounded > 0);
  CHECK(r.verification.ok());
  const CoordinateArith dbl = *parse_coordinate_arith("double");
  for (std::size_t i = 0; i < p.boundary_vertices.size(); ++i) {
    const auto& q = p.boundary_positions[i];
    CHECK(r.target[p.boundary_vertices[i]] == dbl.round(HPoint(q[0], q[1], q[2])));
  }
}

TEST_CASE("too few bits: the loss is reported with a tet that is really not positive") {
  // An integer grid onto the sphere with 8-bit floats: the input survives the rounding, an
  // expansion's rounded centre does not.
  const MapProblem p = problem_from(perturbed_grid(4, 4, 4, 0, 0.0), "sphere");
  const MapResult r = map_to_domain(p, with_arith("mpfr:8"));
  REQUIRE(r.outcome == MapOutcome::precision_lost);
  REQUIRE(r.loss);
  const PrecisionLoss& l = *r.loss;
  CHECK(l.step > 0);
  CHECK(l.exact_bits > 8);
  CHECK(r.message == l.message());
  CHECK(r.message.find("vertex " + std::to_string(l.vertex)) != std::string::npos);
  REQUIRE(l.tet);
  CHECK(std::find(l.tet->begin(), l.tet->end(), l.vertex) != l.tet->end());
  const Sign s =
      orient3d(l.corners[0], l.corners[1], l.corners[2], l.corners[3], PredicateContext::certain());
  CHECK(s != Sign::positive);
  CHECK(s == l.orientation);
  // The state returned is the one where validity was lost: the tet is there, at those corners.
  CHECK(std::find(r.tets.begin(), r.tets.end(), *l.tet) != r.tets.end());
  const std::vector<HPoint>& at = l.in_source ? r.source : r.target;
  for (int i = 0; i < 4; ++i) CHECK(at[(*l.tet)[std::size_t(i)]] == l.corners[std::size_t(i)]);
  CHECK_FALSE(r.verification.ok());
}

TEST_CASE("too few bits for the input itself: the loss is in reading the input") {
  const MapProblem p = problem_from(perturbed_grid(4, 4, 4, 0, 0.0), "sphere");
  const MapResult r = map_to_domain(p, with_arith("mpfr:2"));
  REQUIRE(r.outcome == MapOutcome::precision_lost);
  REQUIRE(r.loss);
  CHECK(r.loss->phase == "input");
  CHECK(r.stats.input_rounded > 0);
  CHECK(r.message.find("not a valid problem") != std::string::npos);
}
