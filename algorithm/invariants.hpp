#pragma once
// The method's invariants (ARCHITECTURE.md section 6), checked from scratch: what `--check` asserts
// after every step, and what the shrink asserts once.
//   1. every cluster vertex sits at p_c;
//   2. a tet with two or more cluster vertices is degenerate (automatic by 1); every other tet is
//      strictly positive in the target;
//   3. the cluster mesh is simply connected (b0 = 1, chi = 1) while it is not empty;
//   4. boundary vertices sit at their prescribed positions;
//   5. every tet is strictly positive in the source.
#include <string>
#include <vector>

#include "algorithm/embedding.hpp"

namespace cmx::algorithm {

// "" when every invariant holds, else a description of the first violation.
std::string check_invariants(const Embedding& e, const std::vector<HPoint>& prescribed);

// Invariant 2 on the tets around one vertex only (cheap; used after every expansion).
std::string check_local_invariant(const Embedding& e, VertexId v);

}  // namespace cmx::algorithm
