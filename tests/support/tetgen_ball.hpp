#pragma once
// Test-only Delaunay balls through TetGen's library (AGPL: linked by tests only, never by the core;
// built only with CMX_WITH_TETGEN_ORACLE, which defines CMX_HAVE_TETGEN_BALL for the suites that
// link cmx_test_support). Unlike the project's own grids, these are unstructured meshes with
// curved boundaries and slivers: the inputs the mapping method meets in practice.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "topology/tet_mesh.hpp"

namespace cmx::test {

struct TetgenBall {
  topology::TetMesh mesh;                        // every tet positive in the positions below
  std::vector<std::array<double, 3>> positions;  // one per vertex
  std::size_t reoriented_tets = 0;               // tets TetGen listed negatively (swapped here)
};

// The Delaunay tetrahedralisation (TetGen, switch "Q") of `interior_points` points uniform in the
// ball of radius 0.9 and `surface_points` points on the unit sphere (normalised, so within rounding
// of it), both drawn from std::mt19937_64(seed); the convex hull is the boundary. With
// quality > 0 the mesh is then refined by TetGen ("Qrq<quality>": radius-edge ratio bound, Steiner
// points inside and on hull faces; note that "q" on a bare point set, without "r", yields no tets).
// Every tet's orientation is checked exactly and flipped to positive when TetGen lists it
// negatively. Throws std::runtime_error when TetGen fails, a tet is degenerate, or the result is not
// a ball (topology::check_ball).
TetgenBall tetgen_ball(std::size_t interior_points, std::size_t surface_points, std::uint64_t seed,
                       double quality = 0);

}  // namespace cmx::test
