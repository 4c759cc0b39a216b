#pragma once
// The project's own test domains (no TetGen in the core): ball-topology tet meshes with exact
// positions, every tet strictly positive (det[b-a, c-a, d-a] > 0, exact).
//
//   perturbed_grid  Freudenthal grid of nx*ny*nz unit cells (topology::grid_complex), vertex
//                   (i,j,k) at (i,j,k).
//   voxel_ball      the cells of a 2R*2R*2R grid whose centre lies in the closed ball of radius R
//                   around the grid's centre, Freudenthal-cut, translated so that the ball's centre
//                   is the origin: a thick, round shape. It is a ball for every R >= 1: a Gauss
//                   digitisation of a Euclidean ball has no critical 2x2 or 2x2x2 configuration
//                   (the two diagonals of any such block have equal sums of squared distances to
//                   the centre), so its boundary is a 2-manifold, and it is simply connected.
//   thin_slab       nx*ny*layers cells (layers 1 or 2): most tets touch the boundary; with one
//                   layer every vertex is a boundary vertex.
//   bings_house     topology::bings_house_nobuenoss: a voxel ball whose interior vertices span
//                   Bing's house, so the cluster mesh is a NOBUENOSS from the start.
//   bings_house_box topology::bings_house_in_box: the same house in a full (shellable) box.
//   compact_bings_house_box topology::compact_bings_house_in_box: a compact house, in a box.
//   knotted_hole    topology::knotted_hole_ball: Furch's knotted hole, whose cluster mesh erodes
//                   to a NOBUENOSS under greedy expansion.
//   thin_fingers    a hand: a palm of (2F+1)W x 4W x 4W cells with F fingers of W x W cells and
//                   L cells' length on its top, W cells apart, each bent along a parabola
//                   (layer h above the palm shifted by floor(h^2 / 2L) cells in y, alternately
//                   +y and -y: about L/2 at the tip). Tubes of width W/L (0.04 to 0.2 for the
//                   benchmark family), the thin parts of real meshes (fingers, tentacles) on
//                   which the global method has run out of time. A ball for W >= 2: consecutive
//                   layers of a finger overlap in W - 1 >= 1 cells, so no two cells meet in an
//                   edge alone.
//
// Perturbation (amplitude > 0): every vertex, interior and boundary alike, in index order, draws
// an offset amplitude * (2k + 1 - 2^17) / 2^17 per axis with k uniform below 2^17 (a dyadic number
// in (-amplitude, amplitude), from a std::mt19937_64 seeded with perturb_seed). The offset is kept
// only when every tet around the vertex stays strictly positive (exact orient3d on the exact
// positions), so the result is positive by construction. amplitude = 0 leaves the integer grid.
// The same arguments give the same mesh and positions on every platform.
#include <array>
#include <cstdint>
#include <vector>

#include "arith/rational.hpp"
#include "topology/tet_mesh.hpp"

namespace cmx::generators {

struct GeneratedDomain {
  topology::TetMesh mesh;
  std::vector<std::array<Rational, 3>> positions;  // exact, one per vertex

  // The nearest doubles of the positions. They are the exact positions when the amplitude has a
  // short binary mantissa (0.25, 0.375, ...): an offset has the amplitude's significant bits plus
  // 17. An amplitude like 0.1 (53 significant bits) gives exact positions that are not doubles.
  [[nodiscard]] std::vector<std::array<double, 3>> double_positions() const;
};

// Default jitter: a quarter of a cell.
inline constexpr double default_perturb_amplitude = 0.25;

// Throws std::invalid_argument when a dimension is 0, when the grid would have 2^31 or more
// vertices, or when the amplitude is negative or not finite.
[[nodiscard]] GeneratedDomain perturbed_grid(std::uint32_t nx, std::uint32_t ny, std::uint32_t nz,
                                             std::uint64_t perturb_seed, double amplitude = default_perturb_amplitude);
[[nodiscard]] GeneratedDomain voxel_ball(std::uint32_t radius_cells, std::uint64_t perturb_seed,
                                         double amplitude = default_perturb_amplitude);
// layers: 1 or 2 (std::invalid_argument otherwise).
[[nodiscard]] GeneratedDomain thin_slab(std::uint32_t nx, std::uint32_t ny, std::uint64_t perturb_seed,
                                        std::uint32_t layers = 1, double amplitude = default_perturb_amplitude);

// scale: even, >= 4 (std::invalid_argument otherwise).
[[nodiscard]] GeneratedDomain bings_house(std::uint32_t scale, std::uint64_t perturb_seed,
                                          double amplitude = default_perturb_amplitude);
// topology::bings_house_in_box: the house inside a full box, its vertices numbered last (greedy
// `index` order meets it as a NOBUENOSS; the box is shellable). scale: even, 2 to 64.
[[nodiscard]] GeneratedDomain bings_house_box(std::uint32_t scale, std::uint64_t perturb_seed,
                                              double amplitude = default_perturb_amplitude);
// topology::compact_bings_house_in_box: the same with a compact house. scale: even, 2 to 64.
[[nodiscard]] GeneratedDomain compact_bings_house_box(std::uint32_t scale, std::uint64_t perturb_seed,
                                                      double amplitude = default_perturb_amplitude);
// scale: cells per lattice unit, 1 to 5 (std::invalid_argument otherwise): the same solid meshed
// scale^3 times more finely.
[[nodiscard]] GeneratedDomain knotted_hole(std::uint64_t perturb_seed, double amplitude = default_perturb_amplitude,
                                           std::uint32_t scale = 1);
// fingers in [1, 16], width in [2, 8], length in [1, 400] (std::invalid_argument otherwise).
[[nodiscard]] GeneratedDomain thin_fingers(std::uint32_t fingers, std::uint32_t width, std::uint32_t length,
                                           std::uint64_t perturb_seed, double amplitude = default_perturb_amplitude);

}  // namespace cmx::generators
