#pragma once
// Reading the mesh a command works on, with the errors sorted as README's exit codes have them.
#include <string>

#include "io/io_error.hpp"
#include "io/tet_mesh_data.hpp"
#include "io/tmap.hpp"

namespace cmx::cli {

// The exit code of an IoError raised while reading mesh `path`: 4 when the file was read but its
// tets are inverted (both orientations) or flat (zero volume), exit_code_of(e) otherwise.
int mesh_error_code(const io::IoError& e, const std::string& path);

// io::read_tet_mesh after check_readable of each of its files; errors are Failure with the code
// of mesh_error_code and the reader's "file:line: message".
io::TetMeshData read_mesh(const std::string& path, const io::ReadOptions& options = {});

// read_mesh, or for a .tmap the exact `geometry` of the map (io/tmap.hpp), its tets as stored.
// The map's tets must be positive in source and target, as the .tmap format says, unless
// options.orientation is keep (then only its combinatorics are checked); a tet that is not is
// exit 4, like a mesh with inverted or flat tets.
io::TetMeshData read_mesh_or_map(const std::string& path, io::MapGeometry geometry, const io::ReadOptions& options = {});

}  // namespace cmx::cli
