#pragma once
// Full incidence-consistency check of a TetMesh (used by tests after every edit, and by callers
// that want to assert their own edits): every live tet has 4 in-range vertices and appears
// exactly once in the list of each of its distinct vertices; every list entry is a live tet
// containing that vertex; the live count matches. O(T + sum of list lengths).

#include <string>

#include "topology/tet_mesh.hpp"

namespace cmx::topology {

struct ConsistencyVerdict {
  bool ok = true;
  std::string message;  // first inconsistency found
};

[[nodiscard]] ConsistencyVerdict check_incidences(const TetMesh& m);

}  // namespace cmx::topology
