// cmx boundary MESH --shape SHAPE -o B.txt [--seed N]: prescribed boundary positions for a mapping
// problem, generated on a tetrahedron, a stiff tetrahedron, the unit sphere or a random star shape
// (algorithm/boundary_shapes.hpp describes the construction).
//
// MESH is read exactly (io::read_tet_mesh, orientation normalised) and must be a ball
// (topology::check_ball). The generator works on the nearest doubles of the positions. The result
// is verified (exact predicates on the doubles: every boundary face sees the origin strictly on its
// inner side) and written atomically as one line "index x y z" per boundary vertex, ascending
// index, each coordinate the exact decimal expansion of its double (arith/exact_decimal.hpp), so an
// exact reader gets the very values that were verified. On any failure no file is written.
// Exit: 0 written; 2 bad command line; 3 unreadable MESH or failed write ("file:line: message");
// 4 MESH is not a ball, or no valid boundary was found (the reason on stderr); 10 the generated
// boundary failed verification (a bug).
#include <cstdio>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "algorithm/boundary_shapes.hpp"
#include "arith/exact_decimal.hpp"
#include "cli/command.hpp"
#include "io/atomic_file.hpp"
#include "io/io_error.hpp"
#include "io/read_mesh.hpp"
#include "io/write_mesh.hpp"
#include "topology/ball_check.hpp"

namespace cmx::cli {
namespace {

constexpr const char* usage =
    "usage: cmx boundary MESH --shape SHAPE -o B.txt [--seed N]\n"
    "Generates prescribed positions for the boundary vertices of MESH (a ball), star-shaped about\n"
    "the origin, and writes 'index x y z' per boundary vertex (exact decimal doubles).\n"
    "  MESH           .ovm .vtk .vtu .mesh .msh .node/.ele\n"
    "  --shape SHAPE  tet (regular tetrahedron inscribed in the unit sphere), stiff-tet (the same,\n"
    "                 one face being a single boundary triangle), sphere (tet projected to the\n"
    "                 unit sphere), star[:SEED] (sphere scaled per vertex by factors in [1, 10))\n"
    "  -o, --output   the boundary file to write (atomically; nothing is written on failure)\n"
    "  --seed N       seed of the random corner choice (and of star's radii); default 1234\n"
    "Exit status: 0 written; 2 bad command line; 3 unreadable MESH or write error; 4 MESH is not\n"
    "a ball or no valid boundary was found.\n";

int usage_error(const char* what, const std::string& detail) {
  std::fprintf(stderr, "cmx boundary: %s%s\n%s", what, detail.c_str(), usage);
  return exit_usage;
}

std::optional<std::uint64_t> parse_seed(const std::string& text) {
  // The shape parser reads seeds; reuse it rather than a second integer parser.
  const auto spec = algorithm::parse_boundary_shape("tet:" + text);
  if (!spec) return std::nullopt;
  return spec->seed;
}

int run(const std::vector<std::string>& args) {
  std::string path, shape_text, output, seed_text;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      std::fputs(usage, stdout);
      return exit_ok;
    }
    std::string* target = a == "--shape" ? &shape_text : (a == "-o" || a == "--output") ? &output : a == "--seed" ? &seed_text : nullptr;
    if (target) {
      if (i + 1 == args.size()) return usage_error("missing value after ", a);
      *target = args[++i];
    } else if (!a.empty() && a[0] == '-') {
      return usage_error("unknown option ", a);
    } else if (path.empty()) {
      path = a;
    } else {
      return usage_error("more than one MESH: ", a);
    }
  }
  if (path.empty()) return usage_error("no MESH given", "");
  if (shape_text.empty()) return usage_error("no --shape given", "");
  if (output.empty()) return usage_error("no output file given (-o B.txt)", "");
  auto spec = algorithm::parse_boundary_shape(shape_text);
  if (!spec) return usage_error("unknown shape ", "'" + shape_text + "' (tet, stiff-tet, sphere, star, star:SEED)");
  if (!seed_text.empty()) {
    const auto seed = parse_seed(seed_text);
    if (!seed) return usage_error("--seed needs a non-negative integer below 2^64, not ", seed_text);
    if (shape_text.find(':') != std::string::npos && *seed != spec->seed)
      return usage_error("two different seeds given: ", shape_text + " and --seed " + seed_text);
    spec->seed = *seed;
  }

  io::TetMeshData data;
  try {
    data = io::read_tet_mesh(path);
  } catch (const io::IoError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return exit_bad_input;
  }
  const topology::TetMesh mesh(data.positions.size(), data.tets);
  if (const auto ball = topology::check_ball(mesh); !ball.ok) {
    std::fprintf(stderr, "cmx boundary: %s is not a ball: %s\n", path.c_str(), ball.message.c_str());
    return exit_invalid_problem;
  }
  const auto boundary = algorithm::generate_boundary(mesh, io::nearest_doubles(data.positions), *spec);
  if (!boundary.ok) {
    std::fprintf(stderr, "cmx boundary: %s\n", boundary.message.c_str());
    return exit_invalid_problem;
  }
  if (const auto why = algorithm::check_star_shaped_about_origin(mesh, boundary); !why.empty()) {
    std::fprintf(stderr, "cmx boundary: internal error: the generated boundary fails verification: %s\n", why.c_str());
    return exit_internal;
  }
  try {
    io::write_file_atomically(output, [&](std::ostream& out) {
      for (std::size_t i = 0; i < boundary.vertices.size(); ++i) {
        const auto& p = boundary.positions[i];
        out << boundary.vertices[i] << ' ' << exact_decimal(p[0]) << ' ' << exact_decimal(p[1]) << ' '
            << exact_decimal(p[2]) << '\n';
      }
    });
  } catch (const io::IoError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return exit_bad_input;
  }
  std::fprintf(stderr, "wrote %s: %zu boundary vertices, shape %s, %d attempt%s\n", output.c_str(), boundary.vertices.size(),
               algorithm::to_string(*spec).c_str(), boundary.attempts, boundary.attempts == 1 ? "" : "s");
  return exit_ok;
}

[[maybe_unused]] const bool registered =
    register_command({"boundary", "generate star-shaped boundary positions (tet, stiff-tet, sphere, star)", &run});

}  // namespace
}  // namespace cmx::cli
