#include "algorithm/refinement/shelling_fallback.hpp"

#include <utility>

#include "topology/fixed_boundary_replay.hpp"

namespace cmx::algorithm {

ShellingVerdict search_input_shelling(const std::vector<topology::Tet>& tets, std::size_t num_vertices,
                                      std::uint64_t seed, RunControl* control, std::size_t max_attempts,
                                      std::size_t threads) {
  topology::TetMesh input(num_vertices, tets);
  topology::ShellingOptions options;
  options.max_attempts = max_attempts;
  options.seed = seed;
  options.threads = threads;
  if (control) options.should_stop = [control] { return control->should_stop("shelling search"); };
  const topology::ShellingFallback f = topology::shelling_fallback(std::move(input), options);
  ShellingVerdict v;
  v.found = f.shelling_found;
  v.attempts = f.attempts;
  v.best_removed = f.best_removed;  // all tets when found
  v.tets = f.tets;                  // after the chord splits
  v.split_chords = f.chords.size();
  v.replay_completed = f.replayed && f.replay.ok;
  v.replay_expansions = f.replay.expansions;
  v.replay_empty_cone_steps = f.replay.empty_cone_edge_splits;
  const std::string shellable =
      "the input is shellable (a shelling of its " + std::to_string(v.tets) + " tets" +
      (f.chords.empty() ? "" : ", after " + std::to_string(f.chords.size()) + " chord splits,") +
      " was found)";
  if (v.replay_completed)
    v.message =
        shellable + " and Alg. 2 replays it topologically with the boundary in place (" +
        std::to_string(v.replay_expansions) + " expansions, each satisfying Eq. (1); " +
        std::to_string(v.replay_empty_cone_steps) +
        " of them split a cluster edge whose cone is empty while its ends sit at the shrink point, which "
        "inflation opens)";
  else if (v.found)
    v.message = shellable + ", but Alg. 2's topological replay of it fails (" + f.message +
                "), so there is no plan to replay geometrically";
  else
    v.message = "no shelling of the input found in " + std::to_string(f.attempts) +
                " greedy attempts (at most " + std::to_string(f.best_removed) + " of " +
                std::to_string(v.tets) + " tets peeled" +
                (f.chords.empty() ? "" : ", after " + std::to_string(f.chords.size()) + " chord splits") +
                (f.stopped_at_deadline ? ", cut short by the time limit" : "") +
                "), and the fallback of paper Sec. 4.3 needs one: the input may not be shellable";
  return v;
}

}  // namespace cmx::algorithm
