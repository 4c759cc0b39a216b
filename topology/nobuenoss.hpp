#pragma once
// Balls whose cluster mesh gets stuck: NOBUENOSS constructions (paper Sec. 4.1.1, Fig. 8), with
// unknotted controls. See docs/topology.md for the constructions and what was verified.
//
// All are voxel balls (voxel_complex), so GridComplex::coords gives integer positions with
// every tet positive. Their interior vertices form the initial cluster mesh.

#include <array>
#include <cstdint>
#include <span>

#include "topology/generators.hpp"

namespace cmx::topology {

// Furch's knotted hole: a box of unit cells minus a tunnel of unit cells that enters through
// the top face, runs down and then follows a trefoil-knotted lattice arc, and stops inside
// (so the solid is still a ball). The interior vertices form a (subdivided) knotted hole too;
// greedy topological expansion erodes it down to a NOBUENOSS and reports stuck, in every
// order we tried (59286 tets, 7944 interior vertices). `scale` cells per lattice unit (1 to 5)
// meshes the same solid more finely (scale^3 times the tets): the tunnel is scale cells wide.
[[nodiscard]] GridComplex knotted_hole_ball(std::uint32_t scale = 1);
// Control: the same construction along an unknotted arc of similar length; expansion completes.
[[nodiscard]] GridComplex unknotted_hole_ball(std::uint32_t scale = 1);
// The construction for any axis-aligned lattice arc: `corners` are the turning points (each
// consecutive pair differing in one coordinate); the tunnel also runs straight up (+z) from the
// first corner through the top face. The box is the arc's bounding box grown by `margin`
// cells (the top face is `margin`+1 above the arc). Not a ball if the tunnel touches itself.
// Each cell of that construction is then cut into scale^3 cells.
[[nodiscard]] GridComplex ball_with_hole(std::span<const std::array<std::int32_t, 3>> corners,
                                         std::int32_t margin = 2, std::uint32_t scale = 1);

// Bing's house with two rooms, thickened: a voxel ball whose interior vertices induce exactly
// Bing's house, a contractible 2-complex in which every edge lies in >= 2 triangles (so no
// vertex satisfies Eq. (1) from the start: a NOBUENOSS in the sense of Fig. 8, a disc glued
// along its boundary to itself). `scale` (>= 4, even) is the number of cells per design unit.
[[nodiscard]] GridComplex bings_house_nobuenoss(std::uint32_t scale = 4);
// The same house (`scale` >= 2, even, cells per design unit) inside a full box of cells: a
// shellable ball (greedy shelling finds one at once) whose vertices on the house are numbered
// last. Greedy expansion in `index` order expands every other interior vertex first and then
// meets the house, a NOBUENOSS; other orders need not. `house_vertices` (when given) receives
// how many vertices lie on the house (the last ids). The paper's shelling fallback (Sec. 4.3)
// applies to it; docs/algorithm/expansion.md says what replaying a shelling does here.
[[nodiscard]] GridComplex bings_house_in_box(std::uint32_t scale = 2, std::size_t* house_vertices = nullptr);
// The same construction for a compact Bing's house (box 5x3x2 design units, rooms one unit
// high): 6,720 tets and 1,485 vertices at scale 2 (the two-room house in its box has 34,560),
// the last 309 on the house. Shellable the same way; greedy expansion in `index` order, or in
// any order with the house deferred (ExpansionOrder::deferred), meets the house as a NOBUENOSS.
[[nodiscard]] GridComplex compact_bings_house_in_box(std::uint32_t scale = 2,
                                                     std::size_t* house_vertices = nullptr);

// A small shellable ball whose greedy expansion meets a dunce hat (a NOBUENOSS) once its other
// vertices are expanded: 27 vertices and 90 tets, given combinatorially (no positions; map it
// with --combinatorial). Built from published definitions, with no data file:
//   1. Hachimori's 8-vertex dunce hat D (17 triangles; every edge in two or three of them);
//   2. a 3-sphere containing D: the boundary of the cyclic 4-polytope C(8,4) (facets by Gale's
//      evenness condition) after the bistellar 3-2 move on the edge of its positions 2 and 8,
//      its vertices along the moment curve being D's 2, 5, 1, 4, 6, 3, 8, 7 (found by a search
//      over flips; the 19 tets of the result contain D in their 2-skeleton, as Benedetti and
//      Lutz's 8-vertex ball does);
//   3. that sphere minus the tet (1, 2, 4, 5): a ball containing D;
//   4. stellar subdivisions of the simplices spanned by D's vertices that are not D's (edges
//      first, then triangles), so that D is the full subcomplex on its vertices;
//   5. a collar on the boundary, so that every vertex so far is interior; `collars` (1 to 64) of
//      them, each around the last, put the hat deeper inside (6 vertices and 24 tets each).
// Numbering: the 13 vertices of step 4 first, the collars' copies next (the last 6 are the
// boundary), D's vertices last (ids 19 to 26 with one collar; `hat_vertices` receives 8). Expanding
// D last (index order, or any order with D deferred) gets stuck on exactly D; greedy shelling
// shells the ball.
[[nodiscard]] TetMesh dunce_hat_ball(std::size_t* hat_vertices = nullptr, std::uint32_t collars = 1);

}  // namespace cmx::topology
