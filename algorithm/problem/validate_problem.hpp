#pragma once
// Problem validation (issue: "each failure a distinct, clear error naming the first offending
// element"), in this order: sizes and indices; ball topology; source tets positive; positions
// prescribed for exactly the boundary vertices; no degenerate prescribed boundary triangle; the
// prescribed boundary not mirrored; star-shaped with a kernel of positive volume (Chebyshev LP
// over the boundary triangles, r > 0).
#include <vector>

#include "algorithm/map.hpp"
#include "kernel/plane.hpp"
#include "topology/complex_queries.hpp"

namespace cmx::algorithm {

struct ValidatedProblem {
  topology::TetMesh mesh;
  std::vector<HPoint> source;                       // per vertex
  std::vector<char> boundary;                       // per vertex
  std::vector<HPoint> prescribed;                   // per vertex (meaningful on boundary vertices)
  std::vector<topology::BoundaryFace> boundary_faces;  // outward
  std::vector<InnerHalfSpace> kernel;               // per boundary face, prescribed positions
  std::vector<HPoint> boundary_positions;           // problem.boundary_positions as points
  bool combinatorial = false;                       // the source positions carry no geometry
};

// Throws MapError of the matching kind. combinatorial: the source positions carry no geometry
// (MapOptions::combinatorial), so they are not checked.
ValidatedProblem validate_problem(const MapProblem& problem, const FilterPolicy& filter, const lp::ChebyshevOptions& lp,
                                  bool combinatorial = false);

// The first prefix of `halfspaces` (in order) whose common interior is empty, found incrementally
// (an LP only when the running centre leaves the new half-space). Returns the index of the
// half-space that empties it, or SIZE_MAX when all of them have a common interior point.
std::size_t first_emptying_halfspace(const std::vector<InnerHalfSpace>& halfspaces, const lp::ChebyshevOptions& lp);

}  // namespace cmx::algorithm
