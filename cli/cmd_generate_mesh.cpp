// cmx generate-mesh --shape SHAPE [--perturb SEED] [--amplitude A] -o OUT: writes one of the
// project's own test domains (generators/domain_generators.hpp), so that tests and datasets need
// no external mesher:
//   grid:NX,NY,NZ      Freudenthal grid of NX*NY*NZ unit cells
//   ball:R             voxelised ball of radius R cells, centred at the origin
//   slab:NX,NY[,L]     NX*NY*L cells, L = 1 (default) or 2 layers
//   bings-house[:S]    a ball whose cluster mesh is Bing's house (a NOBUENOSS), S cells per unit
//   bings-house-box[:S] the same house in a full box, its vertices numbered last (shellable;
//                      greedy `index` order meets the house as a NOBUENOSS), S even, default 2
//   compact-bings-house-box[:S] the same with a compact house (5 times fewer tets)
//   dunce-hat-ball[:C] a 90-tet shellable ball meeting a dunce hat (topology::dunce_hat_ball, C
//                      collars), combinatorial only: written as a facet list (.facets)
//   knotted-hole[:S]   Furch's knotted hole, S cells per lattice unit (its cluster mesh erodes to
//                      a NOBUENOSS)
//   fingers:F,W,L      a palm with F bent fingers of W x W cells and length L (thin parts)
// --perturb SEED jitters every vertex by a dyadic offset of at most A (default 0.25) per axis,
// keeping only offsets after which all its tets stay strictly positive (exact). OUT's extension
// picks the format (io::write_tet_mesh): .ovm keeps the exact positions (as "str_exact_position";
// they are doubles anyway unless A has a long mantissa), .vtk .vtu .mesh .msh get the nearest
// doubles; .facets writes the tets alone (io/write_facets.hpp). Written atomically. Exit: 0 written; 2 bad
// command line; 9 OUT cannot be written.
#include <charconv>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "cli/command.hpp"
#include "cli/command_line.hpp"
#include "cli/files.hpp"
#include "cli/messages.hpp"
#include "cli/option_values.hpp"
#include "generators/domain_generators.hpp"
#include "io/read_facets.hpp"
#include "io/write_facets.hpp"
#include "io/write_mesh.hpp"
#include "topology/nobuenoss.hpp"

namespace cmx::cli::generate_mesh_command {
namespace {

const HelpText help = {
    "usage: cmx generate-mesh --shape SHAPE [--perturb SEED] [--amplitude A] -o OUT\n",
    "Writes a ball-topology test mesh with all tets positively oriented (written atomically).\n",
    "Exit status: 0 written; 2 bad command line; 9 OUT cannot be written.\n"};

// Meshes beyond this many cells are refused: exact positions cost about 200 bytes per vertex.
constexpr std::uint64_t max_cells = 2'000'000;

// "a,b,c" -> numbers (each a decimal integer in [1, 2^32)); nullopt on anything else.
std::optional<std::vector<std::uint32_t>> parse_dimensions(std::string_view text) {
  std::vector<std::uint32_t> out;
  for (;;) {
    const auto comma = text.find(',');
    const std::string_view item = text.substr(0, comma);
    std::uint32_t value = 0;
    const auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), value);
    if (item.empty() || ec != std::errc() || end != item.data() + item.size() || value == 0) return std::nullopt;
    out.push_back(value);
    if (comma == std::string_view::npos) return out;
    text.remove_prefix(comma + 1);
  }
}

struct ShapeRequest {
  char kind = 0;  // 'g' grid, 'b' ball, 's' slab, 'h' Bing's house, 'H' in a box, 'C' compact in a box,
                  // 'k' knotted hole, 'f' fingers, 'd' the dunce-hat ball (no positions)
  std::vector<std::uint32_t> dims;
};

std::optional<ShapeRequest> parse_shape(const std::string& text) {
  if (text == "bings-house") return ShapeRequest{'h', {4}};
  if (text == "bings-house-box") return ShapeRequest{'H', {2}};
  if (text == "compact-bings-house-box") return ShapeRequest{'C', {2}};
  if (text == "knotted-hole") return ShapeRequest{'k', {1}};
  if (text == "dunce-hat-ball") return ShapeRequest{'d', {1}};
  const auto colon = text.find(':');
  if (colon == std::string::npos) return std::nullopt;
  const std::string name = text.substr(0, colon);
  auto dims = parse_dimensions(std::string_view(text).substr(colon + 1));
  if (!dims) return std::nullopt;
  const std::size_t n = dims->size();
  if (name == "grid" && n == 3) return ShapeRequest{'g', *dims};
  if (name == "ball" && n == 1) return ShapeRequest{'b', *dims};
  if (name == "bings-house" && n == 1) return ShapeRequest{'h', *dims};
  if (name == "bings-house-box" && n == 1) return ShapeRequest{'H', *dims};
  if (name == "compact-bings-house-box" && n == 1) return ShapeRequest{'C', *dims};
  if (name == "knotted-hole" && n == 1) return ShapeRequest{'k', *dims};
  if (name == "dunce-hat-ball" && n == 1 && (*dims)[0] <= 64) return ShapeRequest{'d', *dims};
  if (name == "fingers" && n == 3) return ShapeRequest{'f', *dims};
  if (name == "slab" && (n == 2 || (n == 3 && (*dims)[2] <= 2))) return ShapeRequest{'s', *dims};
  return std::nullopt;
}

std::uint64_t cell_count(const ShapeRequest& s) {
  const auto& d = s.dims;
  if (s.kind == 'd') return 1;
  if (s.kind == 'b') return 8 * std::uint64_t{d[0]} * d[0] * d[0];  // the bounding grid
  if (s.kind == 'h' || s.kind == 'H') return 400 * std::uint64_t{d[0]} * d[0] * d[0];  // the bounding box, roughly
  if (s.kind == 'C')
    return (5 * std::uint64_t{d[0]} + 4) * (3 * std::uint64_t{d[0]} + 4) * (2 * std::uint64_t{d[0]} + 4);
  if (s.kind == 'k') return 12'000 * std::uint64_t{d[0]} * d[0] * d[0];  // the bounding box, about
  if (s.kind == 'f') return (2 * std::uint64_t{d[0]} + 1) * d[1] * (4 * std::uint64_t{d[1]} + d[2] + 2) * (4 * std::uint64_t{d[1]} + d[2]);
  std::uint64_t cells = std::uint64_t{d[0]} * d[1];
  return cells * (d.size() == 3 ? d[2] : 1);
}

struct GenerateArgs {
  ShapeRequest shape;
  std::string shape_text, output;
  std::optional<std::uint64_t> seed;
  std::optional<double> amplitude;
};

void add_options(CLI::App& app, GenerateArgs& a) {
  const auto shape = [&a](const std::string& text) {
    const auto s = parse_shape(text);
    if (!s)
      throw std::invalid_argument(
          "bad shape '" + text +
          "' (grid:NX,NY,NZ, ball:R, slab:NX,NY[,1|2], bings-house[:S], bings-house-box[:S], "
          "compact-bings-house-box[:S], dunce-hat-ball[:C], knotted-hole[:S] or fingers:F,W,L)");
    if (cell_count(*s) > max_cells) throw std::invalid_argument("'" + text + "' has more than " + std::to_string(max_cells) + " cells");
    a.shape_text = text;
    return *s;
  };
  add_parsed(app, "--shape", a.shape, shape,
             "grid:NX,NY,NZ (Freudenthal grid of unit cells), ball:R (voxelised ball\n"
             "of radius R cells), slab:NX,NY[,LAYERS] (1 or 2 layers of cells),\n"
             "bings-house[:S] (a ball whose interior is Bing's house, S even in\n"
             "[4,64], default 4), knotted-hole[:S] (Furch's knotted hole, S cells\n"
             "per lattice unit, 1-5, default 1); these two\n"
             "get stuck in a NOBUENOSS under plain greedy expansion;\n"
             "bings-house-box[:S] (the house in a full box, S even in [2,64],\n"
             "default 2: shellable, its house vertices numbered last, so that\n"
             "greedy expansion in index order meets the house as a NOBUENOSS);\n"
             "compact-bings-house-box[:S] (the same with a compact house, 6720\n"
             "tets at S = 2, the last 309 vertices on the house);\n"
             "dunce-hat-ball[:C] (90 tets, shellable, stuck on a dunce hat on ids\n"
             "19-26 in index order; C collars, 1-64, default 1, each adding 6\n"
             "vertices and 24 tets, the hat on the last 8 ids; no positions: OUT\n"
             "must be .facets, for cmx map --combinatorial and cmx topo-expand);\n"
             "fingers:F,W,L (a palm with F bent fingers of W x W cells, length L;\n"
             "F 1-16, W 2-8, L 1-400); at most 2000000 cells (of the bounding grid)")
      ->type_name("SHAPE")
      ->required();
  add_parsed(app, "--perturb", a.seed, [](const std::string& t) { return std::optional(parse_seed(t)); },
             "jitter every vertex (seeded, dyadic offsets, kept only when its tets\n"
             "stay positive); without it the vertices are integer points; 0 to 2^64-1")
      ->type_name("SEED");
  add_parsed(app, "--amplitude", a.amplitude, [](const std::string& t) { return std::optional(parse_nonnegative(t)); },
             "largest jitter per axis, in cells (default 0.25; needs --perturb)")
      ->type_name("A");
  const auto output = [](const std::string& text) {
    if (!io::is_writable_mesh_path(text) && !io::is_facet_list_path(text))
      throw std::invalid_argument("cannot write '" + text + "': unknown format");
    return text;
  };
  add_parsed(app, "-o,--output", a.output, output,
             ".ovm (exact positions kept) .vtk .vtu .mesh .msh, or .facets\n"
             "(the tets alone, 0-based)")
      ->type_name("OUT")
      ->required();
}

generators::GeneratedDomain generate(const GenerateArgs& a) {
  const std::uint64_t seed = a.seed.value_or(0);
  const double amplitude = a.seed ? a.amplitude.value_or(generators::default_perturb_amplitude) : 0;
  const auto& d = a.shape.dims;
  try {
    switch (a.shape.kind) {
      case 'g': return generators::perturbed_grid(d[0], d[1], d[2], seed, amplitude);
      case 'b': return generators::voxel_ball(d[0], seed, amplitude);
      case 'h': return generators::bings_house(d[0], seed, amplitude);
      case 'H': return generators::bings_house_box(d[0], seed, amplitude);
      case 'C':
        return generators::compact_bings_house_box(d[0], seed, amplitude);
      case 'k': return generators::knotted_hole(seed, amplitude, d[0]);
      case 'f': return generators::thin_fingers(d[0], d[1], d[2], seed, amplitude);
      default: return generators::thin_slab(d[0], d[1], seed, d.size() == 3 ? d[2] : 1, amplitude);
    }
  } catch (const std::invalid_argument& e) {
    usage_error(e.what());
  }
}

int run(const std::vector<std::string>& args) {
  GenerateArgs a;
  CommandLine line("generate-mesh", help);
  add_options(line.app(), a);
  if (const auto done = line.parse(args)) return *done;
  if (a.amplitude && !a.seed) usage_error("--amplitude needs --perturb SEED");
  const bool facets = io::is_facet_list_path(a.output);
  if (a.shape.kind == 'd' && !facets)
    usage_error("dunce-hat-ball has no positions: write it as a .facets file");
  if (a.shape.kind == 'd' && a.seed) usage_error("--perturb needs positions, which dunce-hat-ball has not");
  check_writable({a.output});
  generators::GeneratedDomain domain;
  if (a.shape.kind == 'd')
    domain.mesh = topology::dunce_hat_ball(nullptr, a.shape.dims[0]);  // no positions
  else
    domain = generate(a);
  io::TetMeshData data;
  data.positions = std::move(domain.positions);
  for (auto t : domain.mesh.live_tets()) data.tets.push_back(topology::indices_of(domain.mesh.tet(t)));
  if (facets)
    io::write_facet_list(a.output, data.tets);
  else
    io::write_tet_mesh(a.output, data);
  note("wrote " + a.output + ": " + std::to_string(domain.mesh.num_vertices()) + " vertices, " +
       std::to_string(data.tets.size()) + " tets");
  return exit_ok;
}

[[maybe_unused]] const bool registered =
    register_command({"generate-mesh", "write a test mesh: perturbed grid, voxel ball or thin slab", &run});

}  // namespace
}  // namespace cmx::cli::generate_mesh_command
