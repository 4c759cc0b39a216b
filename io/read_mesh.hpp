#pragma once
// Tetrahedral mesh readers. Each format has an in-memory entry point (bytes + a name used in
// error messages; what the fuzzers call) and every reader validates and normalises the result as
// documented in io/tet_mesh_data.hpp and docs/formats.md. Errors: IoError naming file and line.
//
// Formats (docs/formats.md has the details and each format's orientation convention):
//   .ovm   OpenVolumeMesh ASCII (property blocks skipped, VProp strings kept; the exact
//          `str_exact_position` property replaces the double positions by default)
//   .vtk   legacy VTK UNSTRUCTURED_GRID, 4.2 CELLS and 5.1 OFFSETS/CONNECTIVITY, ASCII or BINARY
//   .vtu   VTK XML UnstructuredGrid: ascii, inline base64 ("binary"), appended raw or base64;
//          uncompressed or zlib-compressed (vtkZLibDataCompressor); UInt32/UInt64 headers
//   .mesh  Medit ASCII
//   .msh   Gmsh 2.2 ASCII/binary and 4.1 ASCII/binary
//   .node/.ele  TetGen
// Cells of dimension < 3 (vertices, lines, triangles, quads) are skipped; 10-node (second-order)
// tetrahedra are read as their corners, their mid-edge nodes dropped (io/second_order.hpp);
// other 3D cells are rejected (IoError non_tet_cell, the message names the cell type).
#include <string>
#include <string_view>

#include "io/tet_mesh_data.hpp"

namespace cmx::io {

TetMeshData read_ovm(std::string_view bytes, const std::string& name, const ReadOptions& options = {});
TetMeshData read_vtk(std::string_view bytes, const std::string& name, const ReadOptions& options = {});
TetMeshData read_vtu(std::string_view bytes, const std::string& name, const ReadOptions& options = {});
TetMeshData read_medit(std::string_view bytes, const std::string& name, const ReadOptions& options = {});
TetMeshData read_gmsh(std::string_view bytes, const std::string& name, const ReadOptions& options = {});
// TetGen needs both files: the .node text and the .ele text.
TetMeshData read_tetgen(std::string_view node_bytes, const std::string& node_name, std::string_view ele_bytes,
                        const std::string& ele_name, const ReadOptions& options = {});

// Reads `path`, choosing the reader by extension (case-insensitive): ovm, vtk, vtu, mesh, msh,
// node or ele (TetGen: the sibling file with the other extension is read too). Throws IoError
// (unsupported) for other extensions, (open_failed) when a file cannot be read. A `.tmap` is
// refused (unsupported) with a message saying so: it holds two geometries, and which one a
// mesh is taken from is the caller's choice (read_tmap and mesh_of_map, io/tmap.hpp).
TetMeshData read_tet_mesh(const std::string& path, const ReadOptions& options = {});

// True when read_tet_mesh knows the extension of `path` (false for .tmap).
bool is_readable_mesh_path(const std::string& path);

// The two files of a TetGen mesh named by a path ending in .node or .ele (any case): the given
// file and its sibling with the same stem and the other extension (lower case). Throws
// IoError(unsupported) for other paths.
struct TetgenPaths {
  std::string node, ele;
};
TetgenPaths tetgen_paths(const std::string& path);

}  // namespace cmx::io
