#pragma once
// Generators of combinatorial test complexes.
//
// Grid numbering: a grid of nx*ny*nz unit cells has vertices (i,j,k), 0<=i<=nx, 0<=j<=ny,
// 0<=k<=nz, with id i + (nx+1)*(j + (ny+1)*k) (x fastest). Placing vertex (i,j,k) at the
// integer point (i,j,k) makes every tet positive: det[b-a, c-a, d-a] > 0 (tests check this).
// Each cell is cut into 6 tets around one of its main diagonals:
//   freudenthal: every cell uses the diagonal (0,0,0)-(1,1,1) (Kuhn/Freudenthal);
//   reflected  : every cell uses the diagonal through its corner with all coordinates even
//                (the Kuhn triangulation mirrored in alternate cells). Both are conforming.
// voxel_complex keeps only some cells and renumbers the used vertices in the same (i,j,k)
// order; GridComplex::coords gives each vertex's integer position.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "topology/tet_mesh.hpp"

namespace cmx::topology {

enum class GridTriangulation : std::uint8_t { freudenthal, reflected };

struct GridComplex {
  TetMesh mesh;
  std::vector<std::array<std::int32_t, 3>> coords;  // integer position of each vertex
};

[[nodiscard]] GridComplex grid_complex(std::uint32_t nx, std::uint32_t ny, std::uint32_t nz,
                                       GridTriangulation tri = GridTriangulation::freudenthal);
// keep_cell[i + nx*(j + ny*k)] != 0 keeps cell (i,j,k). Vertices of no kept cell are dropped.
[[nodiscard]] GridComplex voxel_complex(std::uint32_t nx, std::uint32_t ny, std::uint32_t nz,
                                        std::span<const char> keep_cell,
                                        GridTriangulation tri = GridTriangulation::freudenthal);

// One tet (0,1,2,3), positive at (0,0,0),(1,0,0),(0,1,0),(0,0,1).
[[nodiscard]] TetMesh single_tet();
// Tets (0,1,2,3) and (1,2,3,4) glued along face (1,2,3); both positive with the single_tet
// positions for 0..3 and vertex 4 at (1,1,1).
[[nodiscard]] TetMesh two_tets_sharing_face();

}  // namespace cmx::topology
