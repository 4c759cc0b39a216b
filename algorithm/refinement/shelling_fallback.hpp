#pragma once
// What cmx does after a NOBUENOSS (paper Sec. 4.1.1): the first stage of the shelling-based
// fallback of paper Sec. 4.3, the search for a shelling of the input ball.
//
// The fallback applies only to shellable inputs: Alg. 2 turns a shelling into an expansion
// sequence. The search is greedy (topology/shelling.hpp) and bounded; not finding a shelling does
// not prove that none exists, but the NOBUENOSS inputs that `cmx map` meets here (Furch's knotted
// hole, which is not shellable, and the thin ball around Bing's house) defeat it. Bing's house in
// a full box is shellable and meets its NOBUENOSS in topological index order, but no geometric
// run reaches it. The geometric replay of a shelling is built as an option of its own
// (MapOptions::replay, expansion/shelling_replay.cpp: from the start, not from the stuck state)
// and is not run here: its refinement runs away on inputs of Bing's house's size
// (docs/algorithm/expansion.md). This stage replays the plan topologically
// (topology/fixed_boundary_replay.hpp, as `cmx topo-expand` does when stuck), so a NOBUENOSS
// ends as `stuck` and says whether the input is known to be shellable, which is what a user can
// act on (a non-shellable input needs remeshing; a shellable one can be run again with
// --replay-shelling).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "algorithm/run_control.hpp"
#include "topology/tet_mesh.hpp"

namespace cmx::algorithm {

struct ShellingVerdict {
  bool found = false;
  std::size_t attempts = 0;
  std::size_t best_removed = 0;  // most tets one greedy attempt removed
  std::size_t tets = 0;          // of the mesh searched: the input after splitting every chord
  std::size_t split_chords = 0;
  // When found: Alg. 2's topological replay of it with the boundary in place
  // (topology/fixed_boundary_replay.hpp), which is what `cmx topo-expand` reports.
  bool replay_completed = false;  // every interior vertex expanded, each satisfying Eq. (1)
  std::size_t replay_expansions = 0;
  std::size_t replay_empty_cone_steps = 0;  // of those, split cluster edges with an empty geometric cone
  std::string message;                      // one sentence for the stuck message
};

// At most `max_attempts` greedy attempts with seeds derived from `seed`; none but the first
// starts once `control` (when given) says stop. When a shelling is found it is converted by
// Alg. 2 and replayed topologically, and the message gives that replay's verdict (map.cpp then
// replays it geometrically unless told not to: ReplayMode). O(attempts * T log T) plus the replay.
// `threads`: attempts run at once (topology::ShellingOptions::threads; 0: the machine's cores),
// the verdict the same for every count.
ShellingVerdict search_input_shelling(const std::vector<topology::Tet>& tets, std::size_t num_vertices,
                                      std::uint64_t seed, RunControl* control, std::size_t max_attempts = 8,
                                      std::size_t threads = 1);

}  // namespace cmx::algorithm
