#include "cli/mesh_input.hpp"

#include "cli/command.hpp"
#include "cli/files.hpp"
#include "io/read_mesh.hpp"

namespace cmx::cli {

int mesh_error_code(const io::IoError& e, const std::string& path) {
  if (e.kind() != io::ErrorKind::degenerate_tet) return exit_code_of(e);
  // The reader finds repeated vertices (malformed) before zero volumes (a geometry that is not a
  // problem cmx can take): when the file reads without the geometric check, it was a zero volume.
  try {
    io::ReadOptions keep;
    keep.orientation = io::Orientation::keep;
    (void)io::read_tet_mesh(path, keep);
  } catch (const io::IoError&) {
    return exit_bad_input;
  }
  return exit_invalid_problem;
}

io::TetMeshData read_mesh(const std::string& path, const io::ReadOptions& options) {
  for (const std::string& file : mesh_files(path)) check_readable(file);
  try {
    return io::read_tet_mesh(path, options);
  } catch (const io::IoError& e) {
    throw Failure(mesh_error_code(e, path), e.what());
  }
}

io::TetMeshData read_mesh_or_map(const std::string& path, io::MapGeometry geometry, const io::ReadOptions& options) {
  if (!io::is_map_path(path)) return read_mesh(path, options);
  check_readable(path);
  try {
    return io::mesh_of_map(io::read_tmap(path, options.orientation != io::Orientation::keep), geometry);
  } catch (const io::IoError& e) {
    const bool orientation =
        e.kind() == io::ErrorKind::degenerate_tet || e.kind() == io::ErrorKind::inconsistent_orientation;
    throw Failure(orientation ? exit_invalid_problem : exit_code_of(e), e.what());
  }
}

}  // namespace cmx::cli
