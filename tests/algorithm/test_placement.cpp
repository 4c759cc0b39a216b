// The quick placement of simple cones (placement.hpp, place_at_float_centre): whatever it returns
// lies strictly inside the exact expansion cone, checked through the cone's half-spaces (a code
// path apart from its own orientation checks), and it declines where it does not apply.
#include <doctest/doctest.h>

#include "algorithm/expansion/expansion_cone.hpp"
#include "algorithm/expansion/placement.hpp"
#include "map_test_util.hpp"
#include "shrunk_state.hpp"

using namespace cmx;
using namespace cmx::algorithm;
using namespace cmx::generators;

TEST_CASE(
    "a float-centre placement is strictly inside the exact cone and keeps a margin like the dyadic policy") {
  for (const char* shape : {"sphere", "star:4", "stiff-tet"}) {
    CAPTURE(shape);
    test::Shrunk s = test::shrunk(test::problem_from(perturbed_grid(6, 5, 5, 11), shape));
    const PlacementOptions options;
    std::size_t placed = 0, declined = 0;
    for (VertexId v{0}; v < s.e.num_vertices(); ++v) {
      if (!s.e.unexpanded[v]) continue;
      CAPTURE(v);
      const FloatCone guess = float_expansion_cone(s.e, v);
      const std::optional<Placement> p = place_at_float_centre(s.e, v, guess, options);
      if (!p) {
        ++declined;
        continue;
      }
      ++placed;
      const ExpansionCone cone = gather_expansion_cone(s.e, v);
      REQUIRE(p->ok());
      CHECK(strictly_inside(cone, p->position));
      // The certified path's answer for the same cone: the float centre is within half the
      // exact radius of its centre (the dyadic policy's point is within a quarter).
      const Placement exact = place_in_cone(cone, options);
      REQUIRE(exact.ok());
      const lp::ChebyshevResult c = lp::chebyshev_center(lp_halfspaces(cone), options.lp);
      for (int k = 0; k < 3; ++k)
        CHECK(abs(p->position.coordinate(k) - c.center[std::size_t(k)]) <= c.radius / 2);
    }
    CHECK(placed >= 20);
    CHECK(declined >= 1);  // vertices deep in the cluster: no base tet, an unbounded float LP
  }
}

TEST_CASE("a float-centre placement declines other backends, precision policies and coordinate arithmetics") {
  test::Shrunk s = test::shrunk(test::problem_from(perturbed_grid(4, 4, 3, 7), "sphere"));
  VertexId v{0};
  while (!s.e.unexpanded[v] || !place_at_float_centre(s.e, v, float_expansion_cone(s.e, v), {})) ++v;
  const FloatCone guess = float_expansion_cone(s.e, v);
  PlacementOptions o;
  o.lp.backend = "exact";
  CHECK_FALSE(place_at_float_centre(s.e, v, guess, o));
  for (PrecisionPolicy policy : {PrecisionPolicy::none, PrecisionPolicy::shift}) {
    o = {};
    o.precision = policy;
    CHECK_FALSE(place_at_float_centre(s.e, v, guess, o));
  }
  o = {};
  o.precision = PrecisionPolicy::segment;
  CHECK(place_at_float_centre(s.e, v, guess, o));
  o.arith = *parse_coordinate_arith("double");
  CHECK_FALSE(place_at_float_centre(s.e, v, guess, o));
}

TEST_CASE("a cone proved closed on its float basis's rows has no interior for the certified LP either") {
  std::size_t proved = 0, open = 0;
  for (const char* shape : {"sphere", "star:4", "stiff-tet", "tet"}) {
    for (std::uint64_t seed : {3, 11, 19}) {
      test::Shrunk s = test::shrunk(test::problem_from(perturbed_grid(5, 4, 4, seed), shape));
      for (VertexId v{0}; v < s.e.num_vertices(); ++v) {
        if (!s.e.unexpanded[v]) continue;
        const FloatCone guess = float_expansion_cone(s.e, v);
        if (guess.base_tets == 0) continue;
        const FloatConeVerdict g = guess_cone(guess, {});
        const Placement exact = place_in_cone(gather_expansion_cone(s.e, v), {});
        CAPTURE(shape);
        CAPTURE(v);
        if (exact.ok()) ++open;
        if (g.guess != ConeGuess::closed || !certified_closed(s.e, v, guess, g.lp)) continue;
        ++proved;
        CHECK_FALSE(exact.ok());
      }
    }
  }
  MESSAGE("proved closed " << proved << ", open " << open);
  CHECK(proved >= 1);
  CHECK(open >= 1);
}
