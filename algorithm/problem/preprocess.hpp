#pragma once
// Preprocessing with parsimony, and the shrink point (issue: "split only what the invariant
// requires"; the invariants of algorithm/verify/invariants.hpp).
//
// The shrunk state needs every tet with no cluster vertex to be positive with the prescribed
// positions, and every tet with exactly one cluster vertex u to be positive with u at p_c, i.e.
// p_c strictly on the inner side of the face opposite u. The predecessor program splits every
// interior face and edge whose vertices are all on the boundary, unconditionally. Here p_c is the
// Chebyshev centre of the boundary kernel intersected with the half-spaces of the one-interior-
// vertex tets, and a face is split only when a tet is still invalid:
//   * an all-boundary tet that is not positive: one of its interior faces is split (the new
//     vertex is interior, so its pieces become one-interior-vertex tets);
//   * a one-interior-vertex tet whose half-space no shrink point compatible with the half-spaces
//     accepted so far satisfies (tested exactly; its face is then split, turning the tet and its
//     neighbour across the face into tets with more interior vertices).
// Tets are processed in id order, new tets after; a half-space satisfied by the running centre
// is accepted without an LP. Termination: every split consumes an interior face whose vertices
// are all on the boundary and creates none. Feasibility: when no such face is left, every
// one-interior-vertex tet faces a boundary triangle, so its half-space is a kernel half-space
// (and no tet is all-boundary): the kernel, which validation found to have interior, remains.
#include <cstddef>

#include "algorithm/embedding.hpp"
#include "algorithm/expansion/placement.hpp"
#include "algorithm/problem/validate_problem.hpp"

namespace cmx::algorithm {

struct PreprocessResult {
  std::size_t split_topology = 0;          // chord faces/edges split so the cluster mesh is simply connected
  std::size_t split_all_boundary_tet = 0;  // all-boundary tet not positive
  std::size_t split_no_shrink_point = 0;   // one-interior-vertex tet no shrink point could make positive
  std::size_t split_fallback = 0;          // the predecessor's split-everything fallback
  std::size_t lps = 0;
  double shrink_radius = 0;  // Chebyshev radius around p_c (of everything accepted), nearest double
};

// `e` holds the validated mesh with boundary vertices at their prescribed positions and every
// interior vertex flagged unexpanded. On return: faces split as above, e.center = a few-bit point
// strictly inside every accepted half-space, every cluster vertex at e.center.
// The state before preprocessing: boundary vertices at their prescribed positions, every other
// vertex unexpanded (its target is set by the shrink).
Embedding initial_embedding(const ValidatedProblem& problem, const FilterPolicy& filter,
                            const CoordinateArith& arith, FilterStats* stats = nullptr);

PreprocessResult preprocess_and_shrink(Embedding& e, const ValidatedProblem& problem,
                                       const PlacementOptions& options);

}  // namespace cmx::algorithm
