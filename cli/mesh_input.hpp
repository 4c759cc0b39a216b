#pragma once
// Reading the mesh a command works on, with the errors sorted as README's exit codes have them.
#include <string>

#include "io/io_error.hpp"
#include "io/tet_mesh_data.hpp"

namespace cmx::cli {

// The exit code of an IoError raised while reading mesh `path`: 4 when the file was read but its
// tets are inverted (both orientations) or flat (zero volume), exit_code_of(e) otherwise.
int mesh_error_code(const io::IoError& e, const std::string& path);

// io::read_tet_mesh after check_readable of each of its files; errors are Failure with the code
// of mesh_error_code and the reader's "file:line: message".
io::TetMeshData read_mesh(const std::string& path, const io::ReadOptions& options = {});

}  // namespace cmx::cli
