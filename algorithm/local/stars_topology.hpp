#pragma once
// Ball checks of a set of tets of a mesh (algorithm/local/stars.hpp, conditions (a) and (b)):
// topology::check_ball on the tets as a mesh of their own.
#include <vector>

#include "topology/ball_check.hpp"
#include "topology/tet_mesh.hpp"

namespace cmx::algorithm::stars {

// check_ball of `tets` (handles of live tets of `mesh`) with their vertices renumbered; the
// verdict's simplex is given back in the vertex handles of `mesh`.
topology::BallVerdict check_ball_of(const topology::TetMesh& mesh, const std::vector<topology::TetId>& tets);

}  // namespace cmx::algorithm::stars
