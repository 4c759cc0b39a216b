// cmx convert IN OUT: converts a tet mesh between formats, chosen by extension.
// IN: .ovm .vtk .vtu .mesh .msh .node/.ele; OUT: .ovm .vtu .vtk .mesh .msh. The input is read
// exactly and normalised to det[b-a, c-a, d-a] > 0 (a mixed-orientation or degenerate input is an
// error unless --keep-orientation). Display formats get the nearest doubles (17 digits); OVM
// additionally keeps exact positions in "str_exact_position". The output is written atomically.
// Exit: 0 done, 2 usage, 3 read or write error ("file:line: message").
#include <cstdio>

#include "cli/command.hpp"
#include "io/io_error.hpp"
#include "io/read_mesh.hpp"
#include "io/write_mesh.hpp"

namespace cmx::cli {
namespace {

constexpr const char* usage =
    "usage: cmx convert IN OUT [--keep-orientation]\n"
    "Converts a tetrahedral mesh by file extension. IN: .ovm .vtk .vtu .mesh .msh .node/.ele;\n"
    "OUT: .ovm .vtu .vtk .mesh .msh. Tets are normalised to det[b-a, c-a, d-a] > 0 unless\n"
    "--keep-orientation (then written as read, without checks).\n";

int run(const std::vector<std::string>& args) {
  std::vector<std::string> paths;
  io::ReadOptions options;
  for (const auto& a : args) {
    if (a == "--help" || a == "-h") {
      std::fputs(usage, stdout);
      return exit_ok;
    }
    if (a == "--keep-orientation") options.orientation = io::Orientation::keep;
    else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "cmx convert: unknown option '%s'\n%s", a.c_str(), usage);
      return exit_usage;
    } else paths.push_back(a);
  }
  if (paths.size() != 2) {
    std::fputs(usage, stderr);
    return exit_usage;
  }
  if (!io::is_writable_mesh_path(paths[1])) {
    std::fprintf(stderr, "cmx convert: cannot write '%s': unknown output format\n%s", paths[1].c_str(), usage);
    return exit_usage;
  }
  try {
    const auto mesh = io::read_tet_mesh(paths[0], options);
    io::write_tet_mesh(paths[1], mesh);
    std::fprintf(stderr, "wrote %s: %zu vertices, %zu tets%s\n", paths[1].c_str(), mesh.positions.size(), mesh.tets.size(),
                 mesh.orientation_flipped ? " (input listed tets negatively: reoriented)" : "");
  } catch (const io::IoError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return exit_bad_input;
  }
  return exit_ok;
}

[[maybe_unused]] const bool registered = register_command({"convert", "convert a tet mesh between file formats", &run});

}  // namespace
}  // namespace cmx::cli
