#pragma once
// Mesh writers. Display formats (VTU, legacy VTK, Medit, Gmsh, TetGen) take doubles — the caller
// decides which doubles (nearest, or a verified rounding) — and OVM additionally stores exact
// positions as the string property "str_exact_position" ("x;y;z", each p/q), like
// Shrink-and-Expand's outputs. Every writer writes the tets as given (cmx convention
// det[b-a, c-a, d-a] > 0 is expected and is what each format's convention asks for, see
// docs/formats.md), doubles with 17 significant digits, and commits the file atomically
// (io/atomic_file.hpp): on failure nothing is written and an existing file is kept.
// Errors: IoError (write_failed; index_out_of_range for a tet index >= the point count; not_finite
// for a NaN or infinite coordinate or field value; mismatch for a field of the wrong length;
// syntax for a field name that is empty, repeated or not made of [A-Za-z0-9_.-]).
#include <array>
#include <iosfwd>
#include <string>
#include <vector>

#include "io/tet_mesh_data.hpp"

namespace cmx::io {

using DoublePoint = std::array<double, 3>;

// Data that VTU, legacy VTK and Gmsh 4.1 files carry beside the mesh, for viewers: named 3-vectors
// per vertex and scalars per tet. (io/map_fields.hpp computes the fields of a map.)
struct PointVectorField {
  std::string name;
  std::vector<DoublePoint> values;  // one per point
};
enum class ScalarType {
  float64,
  uint8,  // values must be integers in [0, 255]; written as UInt8 (VTU), unsigned_char (VTK)
};
struct CellScalarField {
  std::string name;
  ScalarType type = ScalarType::float64;
  std::vector<double> values;  // one per tet
};
struct DisplayFields {
  std::vector<PointVectorField> point_vectors;
  std::vector<CellScalarField> cell_scalars;
  bool empty() const { return point_vectors.empty() && cell_scalars.empty(); }
};

// VTU (VTK XML), ASCII: Float64 points, Int64 connectivity/offsets, UInt8 types (10); fields as
// PointData (Float64, 3 components) and CellData (Float64 or UInt8) arrays.
void write_vtu(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets,
               const DisplayFields& fields = {});
// Legacy VTK 4.2 ASCII (the layout every VTK reader understands); fields as POINT_DATA VECTORS
// (double) and CELL_DATA SCALARS (double or unsigned_char, LOOKUP_TABLE default).
void write_vtk(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets,
               const DisplayFields& fields = {});
// Medit .mesh, MeshVersionFormatted 2, 1-based, references 0... (1 for tets).
void write_medit(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets);
// Gmsh MSH 4.1 ASCII, as Gmsh 4 writes a discrete volume: $Entities with one volume (tag 1, the
// points' bounding box, no physical tags, no bounding surfaces), one node block on it (tags 1..N),
// one element block of type 4 (tags 1..M); fields as $NodeData (3 components) and $ElementData
// (1 component; uint8 fields as their values in doubles), time step 0.
void write_gmsh41(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets,
                  const DisplayFields& fields = {});
// Gmsh MSH 2.2 ASCII (for older readers): nodes tagged 1..N, tets element type 4 with tags `1 1`.
void write_gmsh(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets);
// TetGen: `path` ends in .node or .ele (any case) and both files are written (tetgen_paths,
// io/read_mesh.hpp), 0-based so that indices are cmx's vertex indices: .node "N 3 0 0" then
// "i x y z"; .ele "M 4 0" then "i a b c d". Both are written to temporaries first and renamed into
// place only when both are complete. IoError(unsupported) for another extension.
void write_tetgen(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets);
// OVM ASCII with a half-edge/half-face structure in which every cell's first half-face's vertex
// cycle followed by the remaining vertex is the tet as given. With `exact` (one per point) the
// VProp string "str_exact_position" is added; `properties` (one value per point each) are written
// as further VProp string blocks (a property named str_exact_position is skipped when `exact` is
// given).
void write_ovm(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets,
               const std::vector<Point3>* exact = nullptr, const std::vector<StringProperty>& properties = {});

// The nearest doubles of exact positions (round to nearest even).
std::vector<DoublePoint> nearest_doubles(const std::vector<Point3>& positions);

// Writes doubles in the display format of the extension of `path`: vtu, vtk and msh (Gmsh 4.1)
// with `fields`; mesh, node and ele without them (those formats have no place for them; see
// carries_display_fields). Throws IoError(unsupported) for other extensions (ovm: use write_ovm,
// which takes the exact positions too).
void write_display_mesh(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets,
                        const DisplayFields& fields = {});
bool is_display_mesh_path(const std::string& path);  // vtu vtk msh mesh node ele
bool carries_display_fields(const std::string& path);  // vtu vtk msh

// Writes `mesh` in the format given by the extension of `path`: ovm (nearest doubles + exact
// property + the mesh's string properties), vtu, vtk, mesh, msh (Gmsh 4.1 ASCII), node or ele
// (TetGen, both files). Throws IoError(unsupported) for other extensions.
void write_tet_mesh(const std::string& path, const TetMeshData& mesh);
bool is_writable_mesh_path(const std::string& path);

// Text of a double with 17 significant digits (round-trips exactly).
std::string format_double(double x);

namespace detail {
// The writers' shared precondition: finite coordinates, tet indices < points.size().
void check_writable(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets);
// Fields: one value per point / tet, finite, uint8 values integral in [0, 255], names unique and
// made of [A-Za-z0-9_.-] (safe in every format's syntax).
void check_fields(const std::string& path, std::size_t points, std::size_t tets, const DisplayFields& fields);
// "x y z", each with format_double.
void write_point(std::ostream& out, const DoublePoint& p);
}  // namespace detail

}  // namespace cmx::io
