#pragma once
// What the VTK readers (legacy and XML) do with each VTK cell type: linear tetrahedra (10) are
// read, 10-node quadratic tetrahedra (24) contribute their four corners (io/second_order.hpp),
// cells of dimension 0-2 are skipped, every other 3D cell is refused with a message that names it.
#include <cstdint>
#include <string>

namespace cmx::io {

enum class VtkCellKind { tetrahedron, quadratic_tetrahedron, lower_dimensional, refused };

VtkCellKind vtk_cell_kind(std::int64_t type);

// "cell 7 has VTK type 25 (a second-order 3D cell, quadratic hexahedron); ..." for a refused type.
std::string vtk_refusal(std::uint64_t cell, std::int64_t type);

}  // namespace cmx::io
