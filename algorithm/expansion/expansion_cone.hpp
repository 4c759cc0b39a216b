#pragma once
// The expansion cone of a cluster vertex v (paper Sec. 3.1) as the
// strict linear constraints on v's new position x:
//   * base tets   (v the only cluster vertex): x strictly on the inner side of the face opposite v;
//   * side tets   (v and one other cluster vertex u, which stays at p_c): the same, with u at p_c —
//     the planes through p_c along the cone base's boundary edges.
// Tets with two or more other cluster vertices stay degenerate whatever x is: no constraint.
// Moving v to any x satisfying all constraints keeps every invariant: base and side tets become
// (stay) strictly positive, the rest stay degenerate; v leaves the cluster.
//
// Near p_c the base constraints are slack (the base tets are positive with v at p_c), so the
// kernel has interior exactly when the side planes, all through p_c, leave an open cone of
// directions: that is what star-shapification (bends and pushes, expansion/cluster_expander.hpp)
// restores.
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "algorithm/embedding.hpp"
#include "kernel/plane.hpp"
#include "lp/chebyshev_center.hpp"

namespace cmx::algorithm {

struct ExpansionCone {
  VertexId apex = topology::invalid_vertex;
  std::vector<InnerHalfSpace> halfspaces;  // strict: u . x < w
  std::size_t base_tets = 0;
  std::size_t side_tets = 0;
  // A constraint's three points are collinear (no plane): the strict constraint cannot hold.
  bool degenerate = false;
};

// For an expanded vertex the same constraints describe where it may move (its star's kernel,
// cluster vertices at p_c): used to re-centre neighbours of the cluster.
ExpansionCone gather_expansion_cone(const Embedding& e, VertexId v);

// The same constraints in doubles, from the nearest doubles of the positions (rows a x + b y +
// c z <= d; a zero row for a collinear face): cheap, inexact, for classification guesses only.
struct FloatCone {
  std::vector<std::array<double, 4>> rows;
  std::vector<TetId> tets;  // the tet of each row
  std::size_t base_tets = 0;
};
FloatCone float_expansion_cone(const Embedding& e, VertexId v);
// One such row: the inner side of the plane through a, b, c from their nearest doubles.
std::array<double, 4> float_inner_row(const HPoint& a, const HPoint& b, const HPoint& c);
// The same from points already in doubles.
std::array<double, 4> float_inner_row(const std::array<double, 3>& p, const std::array<double, 3>& q,
                                      const std::array<double, 3>& r);

// The exact constraint of one tet of v's star (as gather_expansion_cone makes it).
InnerHalfSpace cone_halfspace(const Embedding& e, VertexId v, TetId t);

// The cone's constraints as LP half-spaces a x + b y + c z <= d.
std::vector<lp::HalfSpace> lp_halfspaces(const ExpansionCone& cone);

// True when x satisfies every constraint strictly (exact).
bool strictly_inside(const ExpansionCone& cone, const HPoint& x);

}  // namespace cmx::algorithm
