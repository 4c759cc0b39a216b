// Dispatch by file extension.
#include "io/read_mesh.hpp"
#include "io/scanner.hpp"

namespace cmx::io {

bool is_readable_mesh_path(const std::string& path) {
  const auto ext = extension_of(path);
  return ext == "ovm" || ext == "vtk" || ext == "vtu" || ext == "mesh" || ext == "msh" || ext == "node" || ext == "ele";
}

TetgenPaths tetgen_paths(const std::string& path) {
  const auto ext = extension_of(path);
  if (ext != "node" && ext != "ele") throw IoError(ErrorKind::unsupported, path, 0, "a TetGen mesh is named by its .node or .ele file");
  const std::string stem = path.substr(0, path.size() - ext.size());
  return {ext == "node" ? path : stem + "node", ext == "ele" ? path : stem + "ele"};
}

TetMeshData read_tet_mesh(const std::string& path, const ReadOptions& options) {
  const auto ext = extension_of(path);
  if (ext == "node" || ext == "ele") {
    const auto files = tetgen_paths(path);
    return read_tetgen(read_file_bytes(files.node), files.node, read_file_bytes(files.ele), files.ele, options);
  }
  if (ext == "tmap")
    throw IoError(ErrorKind::unsupported, path, 0,
                  "a .tmap is an exact map with a source and a target geometry, not a mesh; the caller picks one "
                  "(read_tmap, then mesh_of_map)");
  using Reader = TetMeshData (*)(std::string_view, const std::string&, const ReadOptions&);
  Reader reader = nullptr;
  if (ext == "ovm") reader = &read_ovm;
  else if (ext == "vtk") reader = &read_vtk;
  else if (ext == "vtu") reader = &read_vtu;
  else if (ext == "mesh") reader = &read_medit;
  else if (ext == "msh") reader = &read_gmsh;
  else
    throw IoError(ErrorKind::unsupported, path, 0,
                  "unknown mesh format '." + ext + "' (known: .ovm .vtk .vtu .mesh .msh .node/.ele)");
  const std::string bytes = read_file_bytes(path);
  return reader(bytes, path, options);
}

}  // namespace cmx::io
