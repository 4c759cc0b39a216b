// The geometric replay of a shelling (paper Sec. 4.3, Alg. 2; expansion/shelling_replay.cpp).
#include <doctest/doctest.h>

#include "map_test_util.hpp"

using cmx::algorithm::MapOptions;
using cmx::algorithm::MapResult;
using cmx::algorithm::ReplayMode;
using cmx::test::map_checked;
using cmx::test::problem_from;

TEST_CASE("replaying a shelling maps a grid step by step, keeping every invariant") {
  // map_checked: every invariant after every step (the replay's splits and expansions included),
  // then the independent verifier.
  const auto d = cmx::generators::perturbed_grid(4, 4, 4, 1);
  MapOptions full;
  full.replay = ReplayMode::full;
  for (const char* shape : {"tet", "sphere", "star:7"}) {
    CAPTURE(shape);
    const MapResult r = map_checked(problem_from(d, shape), full);
    CHECK(r.stats.replay.ran);
    CHECK_FALSE(r.stats.replay.handed_over);
    CHECK(r.stats.replay.steps > 0);
    // Splits wait until the plan needs them: on a grid every planned vertex satisfies Eq. (1)
    // without its plan's splits of all-cluster edges and faces (the dunce-hat ball needs some:
    // test_map_combinatorial.cpp).
    CHECK(r.stats.replay.splits == 0);
    CHECK(r.stats.replay.expansions > 0);
  }
}

TEST_CASE("until-greedy hands over as soon as greedy expansion cannot meet a NOBUENOSS") {
  // A grid has no NOBUENOSS in the default order: the loop takes over before the first step.
  const auto d = cmx::generators::perturbed_grid(3, 3, 3, 2);
  MapOptions until;
  until.replay = ReplayMode::until_greedy;
  const MapResult r = map_checked(problem_from(d, "sphere"), until);
  CHECK(r.stats.replay.ran);
  CHECK(r.stats.replay.handed_over);
  CHECK(r.stats.replay.expansions == 0);
  const MapResult off = map_checked(problem_from(d, "sphere"));
  CHECK_FALSE(off.stats.replay.ran);
}
