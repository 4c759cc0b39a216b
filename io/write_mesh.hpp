#pragma once
// Mesh writers. Display formats (VTU, legacy VTK, Medit, Gmsh) take doubles — the caller decides
// which doubles (nearest, or a verified rounding) — and OVM additionally stores exact positions as
// the string property "str_exact_position" ("x;y;z", each p/q), like Shrink-and-Expand's outputs.
// Every writer writes the tets as given (cmx convention det[b-a, c-a, d-a] > 0 is expected and
// is what each format's convention asks for, see docs/formats.md), doubles with 17 significant
// digits, and commits the file atomically (io/atomic_file.hpp): on failure nothing is written and
// an existing file is kept. Errors: IoError (write_failed; index_out_of_range for a tet index
// >= the point count; not_finite for a NaN or infinite coordinate).
#include <array>
#include <string>
#include <vector>

#include "io/tet_mesh_data.hpp"

namespace cmx::io {

using DoublePoint = std::array<double, 3>;

void write_vtu(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets);
// Legacy VTK 4.2 ASCII (the layout every VTK reader understands).
void write_vtk(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets);
// Medit .mesh, MeshVersionFormatted 2, 1-based, references 0... (1 for tets).
void write_medit(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets);
// Gmsh MSH 2.2 ASCII: nodes tagged 1..N, tets element type 4.
void write_gmsh(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets);
// OVM ASCII with a half-edge/half-face structure in which every cell's first half-face's vertex
// cycle followed by the remaining vertex is the tet as given. With `exact` (one per point) the
// VProp string "str_exact_position" is added; `properties` (one value per point each) are written
// as further VProp string blocks (a property named str_exact_position is skipped when `exact` is
// given).
void write_ovm(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets,
               const std::vector<Point3>* exact = nullptr, const std::vector<StringProperty>& properties = {});

// The nearest doubles of exact positions (round to nearest even).
std::vector<DoublePoint> nearest_doubles(const std::vector<Point3>& positions);

// Writes `mesh` in the format given by the extension of `path`: ovm (nearest doubles + exact
// property + the mesh's string properties), vtu, vtk, mesh, msh. Throws IoError(unsupported) for
// other extensions.
void write_tet_mesh(const std::string& path, const TetMeshData& mesh);
bool is_writable_mesh_path(const std::string& path);

// Text of a double with 17 significant digits (round-trips exactly).
std::string format_double(double x);

namespace detail {
// The writers' shared precondition: finite coordinates, tet indices < points.size().
void check_writable(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets);
}  // namespace detail

}  // namespace cmx::io
