// The NOBUENOSS fallback's first stage: the search for a shelling of the input.
#include <doctest/doctest.h>

#include <chrono>
#include <string>
#include <vector>

#include "algorithm/refinement/shelling_fallback.hpp"
#include "topology/generators.hpp"
#include "topology/nobuenoss.hpp"

namespace {

std::vector<cmx::topology::Tet> tets_of(const cmx::topology::TetMesh& m) {
  std::vector<cmx::topology::Tet> out;
  for (cmx::topology::TetId t : m.live_tets()) out.push_back(m.tet(t));
  return out;
}

}  // namespace

TEST_CASE("shelling search: found on the unknotted control, not on Furch's knotted hole, both said") {
  const auto control = cmx::topology::unknotted_hole_ball();
  const auto yes = cmx::algorithm::search_input_shelling(tets_of(control.mesh), control.mesh.num_vertices(),
                                                         1, nullptr, 2);
  CHECK(yes.found);
  CHECK(yes.best_removed == yes.tets);
  CHECK(yes.tets > control.mesh.num_tets());  // its chords are split first
  CHECK(yes.message.find("chord splits") != std::string::npos);
  CHECK(yes.message.find("the input is shellable") != std::string::npos);
  CHECK(yes.message.find("replays it topologically with the boundary in place") != std::string::npos);
  CHECK_MESSAGE(yes.replay_completed, yes.message);  // the control's replay: every interior vertex by Eq. (1)
  CHECK(yes.replay_expansions > 0);

  const auto knot = cmx::topology::knotted_hole_ball();
  const auto no =
      cmx::algorithm::search_input_shelling(tets_of(knot.mesh), knot.mesh.num_vertices(), 1, nullptr, 2);
  CHECK_FALSE(no.found);
  CHECK(no.attempts == 2);
  CHECK(no.split_chords > 0);  // searched with every chord split
  CHECK(no.tets > knot.mesh.num_tets());
  CHECK(no.message.find("after " + std::to_string(no.split_chords) + " chord splits") != std::string::npos);
  CHECK(no.best_removed > 0);
  CHECK(no.best_removed < no.tets);
  CHECK(no.message.find("no shelling of the input found in 2 greedy attempts") != std::string::npos);
  CHECK(no.message.find(std::to_string(no.best_removed) + " of " + std::to_string(no.tets)) !=
        std::string::npos);

  // A time limit already passed: one attempt, and the message says it was cut short.
  cmx::algorithm::MapOptions options;
  options.time_limit_seconds = 1e-9;
  cmx::algorithm::RunControl past(options, std::chrono::steady_clock::now() - std::chrono::seconds(1));
  const auto late =
      cmx::algorithm::search_input_shelling(tets_of(knot.mesh), knot.mesh.num_vertices(), 1, &past, 4);
  CHECK(late.attempts == 1);
  CHECK(late.message.find("cut short by the time limit") != std::string::npos);
}

TEST_CASE(
    "shelling search on Bing's house in a box: found, replayed topologically, and the message counts the "
    "steps "
    "with an empty cone") {
  const auto box = cmx::topology::bings_house_in_box();
  const auto v =
      cmx::algorithm::search_input_shelling(tets_of(box.mesh), box.mesh.num_vertices(), 1, nullptr, 2);
  CHECK(v.found);
  CHECK(v.replay_completed);
  CHECK(v.replay_expansions > box.mesh.num_vertices() / 2);
  CHECK(v.replay_empty_cone_steps > 0);
  CHECK(v.replay_empty_cone_steps < v.replay_expansions);
  CHECK(v.message.find("replays it topologically") != std::string::npos);
  CHECK(v.message.find(std::to_string(v.replay_empty_cone_steps) +
                       " of them split a cluster edge whose cone is empty") != std::string::npos);
  CHECK(v.message.find("which inflation opens") != std::string::npos);
}
