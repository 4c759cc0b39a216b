// cmx generate-mesh --shape SHAPE [--perturb SEED] [--amplitude A] -o OUT: writes one of the
// project's own test domains (algorithm/domain_generators.hpp), so that tests and datasets need
// no external mesher:
//   grid:NX,NY,NZ      Freudenthal grid of NX*NY*NZ unit cells
//   ball:R             voxelised ball of radius R cells, centred at the origin
//   slab:NX,NY[,L]     NX*NY*L cells, L = 1 (default) or 2 layers
//   bings-house[:S]    a ball whose cluster mesh is Bing's house (a NOBUENOSS), S cells per unit
//   knotted-hole       Furch's knotted hole (its cluster mesh erodes to a NOBUENOSS)
// --perturb SEED jitters every vertex by a dyadic offset of at most A (default 0.25) per axis,
// keeping only offsets after which all its tets stay strictly positive (exact). OUT's extension
// picks the format (io::write_tet_mesh): .ovm keeps the exact positions (as "str_exact_position";
// they are doubles anyway unless A has a long mantissa), .vtk .vtu .mesh .msh get the nearest
// doubles. Written atomically. Exit: 0 written; 2 bad command line; 3 write error.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "algorithm/domain_generators.hpp"
#include "cli/command.hpp"
#include "io/io_error.hpp"
#include "io/write_mesh.hpp"

namespace cmx::cli {
namespace {

constexpr const char* usage =
    "usage: cmx generate-mesh --shape SHAPE [--perturb SEED] [--amplitude A] -o OUT\n"
    "Writes a ball-topology test mesh with all tets positively oriented.\n"
    "  --shape SHAPE   grid:NX,NY,NZ (Freudenthal grid of unit cells), ball:R (voxelised ball of\n"
    "                  radius R cells), slab:NX,NY[,LAYERS] (1 or 2 layers of cells),\n"
    "                  bings-house[:S] (a ball whose interior is Bing's house, S even in [4,64],\n"
    "                  default 4), knotted-hole (Furch's knotted hole); the last two get stuck\n"
    "                  in a NOBUENOSS under plain greedy expansion\n"
    "  --perturb SEED  jitter every vertex (seeded, dyadic offsets, kept only when its tets stay\n"
    "                  positive); without it the vertices are integer points\n"
    "  --amplitude A   largest jitter per axis, in cells (default 0.25)\n"
    "  -o, --output    OUT: .ovm (exact positions kept) .vtk .vtu .mesh .msh\n"
    "Exit status: 0 written; 2 bad command line; 3 write error.\n";

// Meshes beyond this many cells are refused: exact positions cost about 200 bytes per vertex.
constexpr std::uint64_t max_cells = 2'000'000;

int usage_error(const std::string& message) {
  std::fprintf(stderr, "cmx generate-mesh: %s\n%s", message.c_str(), usage);
  return exit_usage;
}

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
  char kind = 0;  // 'g' grid, 'b' ball, 's' slab, 'h' Bing's house, 'k' knotted hole
  std::vector<std::uint32_t> dims;
};

std::optional<ShapeRequest> parse_shape(const std::string& text) {
  if (text == "bings-house") return ShapeRequest{'h', {4}};
  if (text == "knotted-hole") return ShapeRequest{'k', {}};
  const auto colon = text.find(':');
  if (colon == std::string::npos) return std::nullopt;
  const std::string name = text.substr(0, colon);
  auto dims = parse_dimensions(std::string_view(text).substr(colon + 1));
  if (!dims) return std::nullopt;
  const std::size_t n = dims->size();
  if (name == "grid" && n == 3) return ShapeRequest{'g', *dims};
  if (name == "ball" && n == 1) return ShapeRequest{'b', *dims};
  if (name == "bings-house" && n == 1) return ShapeRequest{'h', *dims};
  if (name == "slab" && (n == 2 || (n == 3 && (*dims)[2] <= 2))) return ShapeRequest{'s', *dims};
  return std::nullopt;
}

std::uint64_t cell_count(const ShapeRequest& s) {
  const auto& d = s.dims;
  if (s.kind == 'b') return 8 * std::uint64_t{d[0]} * d[0] * d[0];  // the bounding grid
  if (s.kind == 'h') return 400 * std::uint64_t{d[0]} * d[0] * d[0];  // the bounding box, roughly
  if (s.kind == 'k') return 0;  // fixed, about 10,000 cells
  std::uint64_t cells = std::uint64_t{d[0]} * d[1];
  return cells * (d.size() == 3 ? d[2] : 1);
}

int run(const std::vector<std::string>& args) {
  std::string shape_text, output, seed_text, amplitude_text;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      std::fputs(usage, stdout);
      return exit_ok;
    }
    std::string* value = a == "--shape" ? &shape_text
                         : (a == "-o" || a == "--output") ? &output
                         : a == "--perturb"               ? &seed_text
                         : a == "--amplitude"             ? &amplitude_text
                                                          : nullptr;
    if (!value) return usage_error("unexpected argument '" + a + "'");
    if (i + 1 == args.size()) return usage_error(a + " needs a value");
    *value = args[++i];
  }
  if (shape_text.empty() || output.empty()) return usage_error("--shape and -o are required");
  const auto shape = parse_shape(shape_text);
  if (!shape) return usage_error("bad shape '" + shape_text + "' (grid:NX,NY,NZ, ball:R, slab:NX,NY[,1|2], bings-house[:S] or knotted-hole)");
  if (cell_count(*shape) > max_cells)
    return usage_error("'" + shape_text + "' has more than " + std::to_string(max_cells) + " cells");
  if (!io::is_writable_mesh_path(output)) return usage_error("cannot write '" + output + "': unknown format");
  std::uint64_t seed = 0;
  double amplitude = 0;
  if (!seed_text.empty()) {
    const auto [end, ec] = std::from_chars(seed_text.data(), seed_text.data() + seed_text.size(), seed);
    if (ec != std::errc() || end != seed_text.data() + seed_text.size())
      return usage_error("--perturb needs a non-negative integer below 2^64, not '" + seed_text + "'");
    amplitude = algorithm::default_perturb_amplitude;
  }
  if (!amplitude_text.empty()) {
    if (seed_text.empty()) return usage_error("--amplitude needs --perturb SEED");
    char* end = nullptr;
    amplitude = std::strtod(amplitude_text.c_str(), &end);
    if (end != amplitude_text.c_str() + amplitude_text.size() || !std::isfinite(amplitude) || amplitude < 0)
      return usage_error("--amplitude needs a finite number >= 0, not '" + amplitude_text + "'");
  }

  algorithm::GeneratedDomain domain;
  try {
    const auto& d = shape->dims;
    if (shape->kind == 'g') domain = algorithm::perturbed_grid(d[0], d[1], d[2], seed, amplitude);
    else if (shape->kind == 'b') domain = algorithm::voxel_ball(d[0], seed, amplitude);
    else if (shape->kind == 'h') domain = algorithm::bings_house(d[0], seed, amplitude);
    else if (shape->kind == 'k') domain = algorithm::knotted_hole(seed, amplitude);
    else domain = algorithm::thin_slab(d[0], d[1], seed, d.size() == 3 ? d[2] : 1, amplitude);
  } catch (const std::invalid_argument& e) {
    return usage_error(e.what());
  }
  io::TetMeshData data;
  data.positions = std::move(domain.positions);
  for (auto t : domain.mesh.live_tets()) data.tets.push_back(domain.mesh.tet(t));
  try {
    io::write_tet_mesh(output, data);
  } catch (const io::IoError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return exit_bad_input;
  }
  std::fprintf(stderr, "wrote %s: %zu vertices, %zu tets\n", output.c_str(), data.positions.size(), data.tets.size());
  return exit_ok;
}

[[maybe_unused]] const bool registered =
    register_command({"generate-mesh", "write a test mesh: perturbed grid, voxel ball or thin slab", &run});

}  // namespace
}  // namespace cmx::cli
