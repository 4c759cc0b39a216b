#pragma once
// Stars of a local repair: an initial map (every vertex at a target position, the boundary at its
// prescribed positions) is classified tet by tet, exactly, and every group of tets that it does
// not map positively is enclosed in a star, a ball of tets whose image boundary is star-shaped.
// Re-mapping each star on its own, its boundary kept where it is, then repairs the whole map
// (docs/algorithm/local.md, "Stars of a local repair": the growth rule and why it terminates).
#include <cstdint>
#include <string>
#include <vector>

#include "algorithm/expansion/placement.hpp"
#include "algorithm/run_control.hpp"
#include "kernel/homogeneous_point.hpp"
#include "topology/tet_mesh.hpp"

namespace cmx::algorithm {

enum class TetState : std::uint8_t { positive, flat, inverted };

struct StarOptions {
  double max_share = 0.5;          // stop (ok = false) once stars hold more than this share of the tets
  // Stop (ok = false) before growing anything when more than this share of the tets are
  // defects: such an initial map folds everywhere, and its stars would be most of the mesh.
  double max_defect_share = 1.0;
  PlacementOptions placement;      // the LP backend of the kernel test
  RunControl* control = nullptr;   // polled between growth steps (phase "stars"); stop -> ok = false
  // Give every non-positive tet a vertex interior to its star (unless all four lie on the domain
  // boundary). Without it, a defect whose four vertices all lie on its star's boundary stays
  // where it is under a re-map of the star, which can only repair it by splitting it.
  bool free_defects = true;
};

struct Star {
  std::vector<topology::TetId> tets;          // sorted handles into the mesh
  std::vector<topology::VertexId> vertices;   // sorted: every vertex of its tets
  // Sorted: vertices all of whose tets are in the star and that lie on no boundary triangle of it
  // (so no vertex of the domain boundary): they will move.
  std::vector<topology::VertexId> interior;
  std::vector<topology::Triangle> boundary;   // its boundary triangles, oriented outward (the star's tets on their negative side), sorted
  std::size_t defects = 0;                    // non-positive tets inside
};

struct StarSet {
  bool ok = false;
  std::string message;                        // why not ok (share exceeded, stopped, ...)
  std::vector<TetState> states;               // per tet slot of the mesh, in the initial map (dead slots: positive)
  std::size_t inverted = 0, flat = 0;
  std::vector<Star> stars;                    // disjoint in tets, ordered by their smallest tet; empty when not ok
  std::size_t tets_in_stars = 0;              // when not ok: how many the stars held when growth ended
  std::size_t growth_steps = 0;               // tets added beyond the defects, over all stars
  // How the growth went (docs/algorithm/local.md measures them).
  std::size_t kernel_tests = 0;               // kernel tests run (one float LP each)
  std::size_t exact_lps = 0;                  // of those, decided by the exact Chebyshev LP
  std::size_t repairs = 0;                    // additions that may break the ball, repaired by local tests
  std::size_t ball_checks = 0;                // full ball checks (topology::check_ball), one per finished star
  std::size_t merges = 0;                     // finished stars absorbed by a growing one
};

// Classifies every live tet of `mesh` by the exact orientation of `target` (filtered predicates,
// kernel/orient.hpp), then grows stars until each satisfies, exactly:
//  (a) its tets form a combinatorial 3-ball; (b) its boundary is a 2-sphere;
//  (c) some point sees every boundary triangle strictly from inside in `target` (the exact
//      Chebyshev LP of the triangles' inner half-spaces has radius > 0), so the image of the
//      boundary is a star-shaped sphere;
//  (d) every tet outside all stars is strictly positive.
// Stars that meet (would share a tet) merge. Triangles on the domain boundary (boundary_vertex
// flags of all three vertices AND the face on the mesh boundary) keep their positions like any
// other boundary triangle of a star. No star when every tet is positive (ok, empty).
// `boundary_vertex` flags the vertices that keep their positions: no flagged vertex, and no
// vertex on the mesh boundary, is ever interior to a star.
// Preconditions (std::invalid_argument otherwise): `target` and `boundary_vertex` have one entry
// per vertex, and no face of `mesh` lies in three or more tets.
StarSet grow_stars(const topology::TetMesh& mesh, const std::vector<HPoint>& target,
                   const std::vector<char>& boundary_vertex, const StarOptions& options = {});

// Independent check of (a)-(d) for `stars` (for tests and cmx map --check): "" or the first violation.
// Also checks what the stars say of themselves: states and counts, sorted and disjoint tets,
// vertices, interior vertices and outward boundary triangles as recomputed from the tets.
std::string check_stars(const topology::TetMesh& mesh, const std::vector<HPoint>& target, const StarSet& stars);

}  // namespace cmx::algorithm
