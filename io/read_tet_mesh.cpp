// Dispatch by file extension.
#include "io/read_mesh.hpp"
#include "io/scanner.hpp"

namespace cmx::io {

bool is_readable_mesh_path(const std::string& path) {
  const auto ext = extension_of(path);
  return ext == "ovm" || ext == "vtk" || ext == "vtu" || ext == "mesh" || ext == "msh" || ext == "node" || ext == "ele";
}

TetMeshData read_tet_mesh(const std::string& path, const ReadOptions& options) {
  const auto ext = extension_of(path);
  if (ext == "node" || ext == "ele") {
    const std::string stem = path.substr(0, path.size() - ext.size());
    const std::string node = stem + (ext == "node" ? path.substr(path.size() - 4) : "node");
    const std::string ele = stem + (ext == "ele" ? path.substr(path.size() - 3) : "ele");
    return read_tetgen(read_file_bytes(node), node, read_file_bytes(ele), ele, options);
  }
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
