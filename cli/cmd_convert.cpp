// cmx convert IN OUT: converts a tet mesh between formats, chosen by extension.
// IN: .ovm .vtk .vtu .mesh .msh .node/.ele .tmap (its target, or with --source its source
// geometry); OUT: .ovm .vtu .vtk .mesh .msh .node/.ele. The input is read
// exactly and normalised to det[b-a, c-a, d-a] > 0 (a mixed-orientation or degenerate input is an
// error unless --keep-orientation). Display formats get the nearest doubles (17 digits); OVM
// additionally keeps exact positions in "str_exact_position". The output is written atomically.
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "cli/command_line.hpp"
#include "cli/files.hpp"
#include "cli/mesh_input.hpp"
#include "cli/messages.hpp"
#include "io/read_mesh.hpp"
#include "io/write_mesh.hpp"

namespace cmx::cli::convert_command {
namespace {

const HelpText help = {
    "usage: cmx convert IN OUT [--keep-orientation] [--source]\n",
    "Converts a tetrahedral mesh by file extension. IN: .ovm .vtk .vtu .mesh .msh .node/.ele, or a\n"
    "map .tmap (its target geometry, or with --source its source geometry: exact either way);\n"
    "OUT: .ovm .vtu .vtk .mesh .msh (Gmsh 4.1 ASCII) .node/.ele (TetGen: both files written).\n"
    "Tets are normalised to det[b-a, c-a, d-a] > 0 unless --keep-orientation (then written as\n"
    "read, without checks). Display formats get the nearest doubles; .ovm also keeps the exact\n"
    "positions. OUT is written atomically: on any failure an existing OUT is left as it was.\n",
    "Exit status: 0 written; 2 bad command line (also: OUT is IN); 3 unreadable or malformed IN;\n"
    "4 IN has inverted or flat tets (without --keep-orientation); 9 OUT cannot be written.\n"};

struct ConvertArgs {
  std::string in, out;
  io::ReadOptions read;
  bool source = false;  // of a .tmap: its source geometry
};

// The files convert writes for OUT.
std::vector<std::string> output_files(const ConvertArgs& a) { return mesh_files(a.out); }

void write_output(const ConvertArgs& a, const io::TetMeshData& mesh) { io::write_tet_mesh(a.out, mesh); }

int run(const std::vector<std::string>& args) {
  ConvertArgs a;
  CommandLine line("convert", help);
  CLI::App& app = line.app();
  app.add_option("IN", a.in, "the mesh to read")->required()->type_name("");
  app.add_option("OUT", a.out, "the mesh to write; its extension chooses the format")->required()->type_name("");
  app.add_flag_callback("--keep-orientation", [&a] { a.read.orientation = io::Orientation::keep; },
                        "write the tets as read, without orientation checks");
  app.add_flag("--source", a.source, "of a .tmap: convert its source geometry (default: its target)");
  if (const auto done = line.parse(args)) return *done;
  if (a.source && !io::is_map_path(a.in)) usage_error("--source applies to a map (.tmap) only");
  if (!io::is_writable_mesh_path(a.out)) usage_error("cannot write '" + a.out + "': unknown output format");
  check_outputs_apart(output_files(a), mesh_files(a.in));
  check_writable(output_files(a));
  const io::TetMeshData mesh =
      read_mesh_or_map(a.in, a.source ? io::MapGeometry::source : io::MapGeometry::target, a.read);
  write_output(a, mesh);
  note("wrote " + a.out + ": " + std::to_string(mesh.positions.size()) + " vertices, " + std::to_string(mesh.tets.size()) +
       " tets" + (mesh.orientation_flipped ? " (input listed tets negatively: reoriented)" : ""));
  return exit_ok;
}

[[maybe_unused]] const bool registered = register_command({"convert", "convert a tet mesh between file formats", &run});

}  // namespace
}  // namespace cmx::cli::convert_command
