// cmx boundary MESH --shape SHAPE -o B.txt [--seed N]: prescribed boundary positions for a mapping
// problem, generated on a tetrahedron, a stiff tetrahedron, the unit sphere or a random star shape
// (generators/boundary_shapes.hpp describes the construction).
//
// MESH is read exactly (io::read_tet_mesh, orientation normalised) and must be a ball
// (topology::check_ball). The generator works on the nearest doubles of the positions. The result
// is verified (exact predicates on the doubles: every boundary face sees the origin strictly on its
// inner side) and written atomically as one line "index x y z" per boundary vertex, ascending
// index, each coordinate the exact decimal expansion of its double (arith/exact_decimal.hpp), so an
// exact reader gets the very values that were verified. On any failure no file is written.
#include <ostream>
#include <string>
#include <vector>

#include "generators/boundary_shapes.hpp"
#include "arith/exact_decimal.hpp"
#include "cli/command.hpp"
#include "cli/command_line.hpp"
#include "cli/common_options.hpp"
#include "cli/files.hpp"
#include "cli/mesh_input.hpp"
#include "cli/messages.hpp"
#include "cli/option_values.hpp"
#include "io/atomic_file.hpp"
#include "io/write_mesh.hpp"
#include "topology/ball_check.hpp"

namespace cmx::cli::boundary_command {
namespace {

const HelpText help = {
    "usage: cmx boundary MESH --shape SHAPE -o B.txt [--seed N] [--spread N]\n"
    "                    [--corners random|farthest] [--threads N]\n",
    "Generates prescribed positions for the boundary vertices of MESH (a ball), star-shaped about\n"
    "the origin, and writes 'index x y z' per boundary vertex (exact decimal doubles).\n",
    "Exit status: 0 written; 2 bad command line (also: B.txt is MESH); 3 unreadable MESH; 4 MESH is\n"
    "not a ball, has inverted or flat tets, or no valid boundary was found; 9 B.txt cannot be written;\n"
    "10 the generated boundary failed verification (a bug).\n"};

struct BoundaryArgs {
  std::string mesh, output, shape_text;
  generators::BoundaryShapeSpec shape;
  std::optional<std::uint64_t> seed;
  int spread = 0;
  generators::CornerChoice corners = generators::CornerChoice::random;
  unsigned threads = 0;
};

void add_options(CLI::App& app, BoundaryArgs& a) {
  app.add_option("MESH", a.mesh, ".ovm .vtk .vtu .mesh .msh .node/.ele")->required()->type_name("");
  const auto shape = [&a](const std::string& text) {
    const auto spec = generators::parse_boundary_shape(text);
    if (!spec) throw std::invalid_argument("unknown shape '" + text + "' (tet, stiff-tet, sphere, star, star:SEED)");
    a.shape_text = text;
    return *spec;
  };
  add_parsed(app, "--shape", a.shape, shape,
             "tet (regular tetrahedron inscribed in the unit sphere), stiff-tet (the\n"
             "same, one face being a single boundary triangle), sphere (tet projected\n"
             "to the unit sphere), star[:SEED] (sphere scaled per vertex by factors\n"
             "in [1, 10))")
      ->type_name("SHAPE")
      ->required();
  app.add_option("-o,--output", a.output, "the boundary file to write (atomically; nothing is written on\nfailure)")
      ->type_name("B.txt")
      ->required();
  add_parsed(app, "--seed", a.seed, [](const std::string& t) { return std::optional(parse_seed(t)); },
             "seed of the random corner choice (and of star's radii); default 1234;\n0 to 2^64-1")
      ->type_name("N");
  app.add_option("--spread", a.spread,
                 "spreading steps after the Tutte embedding (default 0): each reweights it\n"
                 "against crowding (stretch minimisation), so that long thin parts\n"
                 "(fingers, tunnels) get a fair share of the shape; an attempt stops\n"
                 "sooner once spread enough, or once its solves stop converging; 0 to 100")
      ->type_name("N")
      ->check(CLI::Range(0, 100));
  add_corners_option(app, a.corners);
  add_parsed(
      app, "--threads", a.threads, [](const std::string& t) { return unsigned(parse_integer(t, 0, 1024)); },
      "corner attempts made at once (default 0: the machine's cores); the\n"
      "boundary written is the same for every count")
      ->type_name("N");
}

// The shape with --seed applied; two different seeds are a contradiction.
generators::BoundaryShapeSpec shape_with_seed(const BoundaryArgs& a) {
  generators::BoundaryShapeSpec spec = a.shape;
  spec.spread = a.spread;
  spec.corners = a.corners;
  spec.threads = a.threads;
  if (!a.seed) return spec;
  if (a.shape_text.find(':') != std::string::npos && *a.seed != spec.seed)
    usage_error("two different seeds given: " + a.shape_text + " and --seed " + std::to_string(*a.seed));
  spec.seed = *a.seed;
  return spec;
}

void write_boundary(const std::string& path, const generators::GeneratedBoundary& boundary) {
  io::write_file_atomically(path, [&](std::ostream& out) {
    for (std::size_t i = 0; i < boundary.vertices.size(); ++i) {
      const auto& p = boundary.positions[i];
      out << boundary.vertices[i] << ' ' << exact_decimal(p[0]) << ' ' << exact_decimal(p[1]) << ' ' << exact_decimal(p[2])
          << '\n';
    }
  });
}

int run(const std::vector<std::string>& args) {
  BoundaryArgs a;
  CommandLine line("boundary", help);
  add_options(line.app(), a);
  if (const auto done = line.parse(args)) return *done;
  const generators::BoundaryShapeSpec spec = shape_with_seed(a);
  check_outputs_apart({a.output}, mesh_files(a.mesh));
  check_writable({a.output});
  const io::TetMeshData data = read_mesh(a.mesh);
  const topology::TetMesh mesh(data.positions.size(), data.tets);
  if (const auto ball = topology::check_ball(mesh); !ball.ok)
    throw Failure(exit_invalid_problem, a.mesh + " is not a ball: " + ball.message);
  const auto boundary = generators::generate_boundary(mesh, io::nearest_doubles(data.positions), spec);
  if (!boundary.ok) throw Failure(exit_invalid_problem, a.mesh + ": no valid '" + a.shape_text + "' boundary: " + boundary.message);
  if (const auto why = generators::check_star_shaped_about_origin(mesh, boundary); !why.empty())
    throw Failure(exit_internal, "internal error: the generated boundary fails verification: " + why);
  write_boundary(a.output, boundary);
  note("wrote " + a.output + ": " + std::to_string(boundary.vertices.size()) + " boundary vertices, shape " +
       generators::to_string(spec) + ", " + std::to_string(boundary.attempts) + " attempt" + (boundary.attempts == 1 ? "" : "s"));
  return exit_ok;
}

[[maybe_unused]] const bool registered =
    register_command({"boundary", "generate star-shaped boundary positions (tet, stiff-tet, sphere, star)", &run});

}  // namespace
}  // namespace cmx::cli::boundary_command
