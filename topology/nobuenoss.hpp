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

}  // namespace cmx::topology
