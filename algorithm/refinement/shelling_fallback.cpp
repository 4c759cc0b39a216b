#include "algorithm/refinement/shelling_fallback.hpp"

#include "topology/shelling.hpp"

namespace cmx::algorithm {

ShellingVerdict search_input_shelling(const std::vector<topology::Tet>& tets, std::size_t num_vertices,
                                      std::uint64_t seed, RunControl* control, std::size_t max_attempts) {
  const topology::TetMesh input(num_vertices, tets);
  topology::ShellingOptions options;
  options.max_attempts = max_attempts;
  options.seed = seed;
  if (control) options.should_stop = [control] { return control->should_stop("shelling search"); };
  const topology::ShellingResult r = topology::find_shelling(input, options);
  ShellingVerdict v;
  v.found = r.found;
  v.attempts = r.attempts;
  v.best_removed = r.best_removed;  // all tets when found
  v.tets = tets.size();
  if (r.found)
    v.message =
        "the input is shellable (a shelling of its " + std::to_string(v.tets) +
        " tets was found), but replaying a shelling as an expansion sequence (paper Alg. 2) is not built";
  else
    v.message = "no shelling of the input found in " + std::to_string(r.attempts) +
                " greedy attempts (at most " + std::to_string(r.best_removed) + " of " +
                std::to_string(v.tets) + " tets peeled" +
                (r.stopped_at_deadline ? ", cut short by the time limit" : "") +
                "), and the fallback of paper Sec. 4.3 needs one: the input may not be shellable";
  return v;
}

}  // namespace cmx::algorithm
