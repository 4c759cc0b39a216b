#include "io/vtk_cell_types.hpp"

#include <iterator>

namespace cmx::io {
namespace {

struct Named {
  std::int64_t type;
  const char* name;
};

// VTK's higher-order 3D cells (vtkCellType.h), refused with their names.
constexpr Named higher_order_3d[] = {
    {25, "quadratic hexahedron"}, {26, "quadratic wedge"}, {27, "quadratic pyramid"},
    {29, "triquadratic hexahedron"}, {31, "quadratic-linear wedge"}, {32, "biquadratic-quadratic wedge"},
    {33, "biquadratic-quadratic hexahedron"}, {37, "triquadratic pyramid"}, {71, "Lagrange tetrahedron"},
    {72, "Lagrange hexahedron"}, {73, "Lagrange wedge"}, {74, "Lagrange pyramid"}, {78, "Bezier tetrahedron"},
    {79, "Bezier hexahedron"}, {80, "Bezier wedge"}, {81, "Bezier pyramid"}};

constexpr Named linear_3d[] = {{11, "voxel"}, {12, "hexahedron"}, {13, "wedge"}, {14, "pyramid"},
                               {15, "pentagonal prism"}, {16, "hexagonal prism"}, {42, "polyhedron"}};

const char* name_in(const Named* begin, const Named* end, std::int64_t type) {
  for (const Named* n = begin; n != end; ++n)
    if (n->type == type) return n->name;
  return nullptr;
}

}  // namespace

VtkCellKind vtk_cell_kind(std::int64_t type) {
  switch (type) {
    case 10: return VtkCellKind::tetrahedron;
    case 24: return VtkCellKind::quadratic_tetrahedron;
    case 1: case 2: case 3: case 4: case 5: case 6: case 7: case 8: case 9:  // linear 0D-2D
    case 21: case 22: case 23: case 28: case 30: case 34: case 35: case 36:  // quadratic/cubic 1D-2D
    case 68: case 69: case 70: case 75: case 76: case 77:                    // Lagrange/Bezier 1D-2D
      return VtkCellKind::lower_dimensional;
    default:
      return VtkCellKind::refused;
  }
}

std::string vtk_refusal(std::uint64_t cell, std::int64_t type) {
  std::string what;
  if (const char* name = name_in(std::begin(higher_order_3d), std::end(higher_order_3d), type))
    what = " (a second-order or higher-order 3D cell: " + std::string(name) + ")";
  else if (const char* linear = name_in(std::begin(linear_3d), std::end(linear_3d), type))
    what = " (" + std::string(linear) + ")";
  return "cell " + std::to_string(cell) + " has VTK type " + std::to_string(type) + what +
         "; among 3D cells only tetrahedra (10) and 10-node quadratic tetrahedra (24, read as their corners) are supported";
}

}  // namespace cmx::io
