// cmx_io_probe: a test-only program through which tests/io/meshio_interop.py drives the io API
// (it must not depend on the cmx program, whose command line is not the io layer's):
//   cmx_io_probe read MESH              read_tet_mesh; prints {"vertices", "tets", "positive",
//                                       "negative", "zero", "flipped", "dropped_higher_order_nodes"}
//   cmx_io_probe convert IN OUT         read_tet_mesh(IN), write_tet_mesh(OUT)
//   cmx_io_probe map IN OUT K           IN's nearest doubles as the source, their image under the
//                                       affine map below as the target; write_display_mesh(OUT)
//                                       with map_display_fields(source, target, tets, K)
// An IoError prints {"error": what(), "kind": kind} and exits 3; a bad command line exits 2.
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

#include "io/io_error.hpp"
#include "io/map_fields.hpp"
#include "io/orientation.hpp"
#include "io/read_mesh.hpp"
#include "io/write_mesh.hpp"

using namespace cmx::io;

namespace {

std::string json_text(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) c = ' ';
    out += c;
  }
  return out + "\"";
}

int read_command(const std::string& path) {
  const auto mesh = read_tet_mesh(path);
  const auto signs = count_orientations(mesh);
  std::cout << "{\"vertices\": " << mesh.positions.size() << ", \"tets\": " << mesh.tets.size() << ", \"positive\": " << signs.positive
            << ", \"negative\": " << signs.negative << ", \"zero\": " << signs.zero
            << ", \"flipped\": " << (mesh.orientation_flipped ? "true" : "false")
            << ", \"dropped_higher_order_nodes\": " << mesh.dropped_higher_order_nodes << "}\n";
  return 0;
}

// The target of the probe's map: x -> A x + b with det A = 1.5 > 0, so positive tets stay positive
// (meshio_interop.py applies the same formula).
DoublePoint affine_image(const DoublePoint& p) { return {2 * p[0] + 0.25 * p[1] + 1, 1.5 * p[1] - 2, 0.5 * p[2] + 0.5}; }

int map_command(const std::string& in, const std::string& out, std::size_t input_vertex_count) {
  const auto mesh = read_tet_mesh(in);
  const auto source = nearest_doubles(mesh.positions);
  std::vector<DoublePoint> target;
  for (const auto& p : source) target.push_back(affine_image(p));
  write_display_mesh(out, target, mesh.tets, map_display_fields(source, target, mesh.tets, input_vertex_count));
  return 0;
}

int run(int argc, char** argv) {
  const std::string command = argc > 1 ? argv[1] : "";
  if (command == "read" && argc == 3) return read_command(argv[2]);
  if (command == "convert" && argc == 4) {
    write_tet_mesh(argv[3], read_tet_mesh(argv[2]));
    return 0;
  }
  if (command == "map" && argc == 5) return map_command(argv[2], argv[3], std::stoul(argv[4]));
  std::cerr << "usage: cmx_io_probe read MESH | convert IN OUT | map IN OUT INPUT_VERTEX_COUNT\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const IoError& e) {
    std::cout << "{\"error\": " << json_text(e.what()) << ", \"kind\": " << json_text(kind_name(e.kind())) << "}\n";
    return 3;
  }
}
