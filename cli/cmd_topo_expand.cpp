// cmx topo-expand (MESH | --builtin NAME) [--order priority|index|random:SEED] [--json]:
// topological expansion (paper Sec. 5.1) of a mesh's interior vertices, by Eq. (1) alone.
//
// The mesh is read with its file's vertex order kept (no geometric orientation check: this is a
// combinatorial question), then validated by topology::check_ball, which also checks that the
// tets are consistently oriented across their faces. The cluster mesh starts as the interior
// vertices and topology::topological_expansion expands it greedily in the chosen order.
//
// Exit codes: 0 whenever the expansion ran, stuck or not (being stuck is a result, reported in
// the output, not an error); 2 bad command line; 3 unreadable or malformed file ("file:line:
// message"); 4 read, but not a ball (the reason on stderr). Nothing is printed on stdout unless
// the exit code is 0. `--builtin` builds a complex in memory (no data file needed): the
// knotted-hole ball and its unknotted control, Bing's house, a Freudenthal grid.
#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/command.hpp"
#include "io/io_error.hpp"
#include "io/read_mesh.hpp"
#include "topology/ball_check.hpp"
#include "topology/chords.hpp"
#include "topology/complex_queries.hpp"
#include "topology/mesh_edits.hpp"
#include "topology/generators.hpp"
#include "topology/nobuenoss.hpp"
#include "topology/topological_expansion.hpp"

namespace cmx::cli {
namespace {

using topology::TetMesh;

constexpr const char* usage =
    "usage: cmx topo-expand (MESH | --builtin NAME) [--order ORDER] [--raw] [--json]\n"
    "Topological expansion (paper Sec. 5.1): expands the cluster mesh of the interior vertices\n"
    "greedily by Eq. (1) alone (no geometry) and reports the sequence length, the expansions by\n"
    "kind (k-manifold k = 1, 2, 3, other Eq. (1), automatic), whether it got stuck, and when stuck\n"
    "the remaining cluster mesh (vertices, Euler characteristic, connected components).\n"
    "  MESH            .ovm .vtk .vtu .mesh .msh .node/.ele; must be a ball (tets consistently\n"
    "                  oriented across faces; geometric signs are not computed: see cmx info)\n"
    "  --builtin NAME  a complex built in memory instead of MESH: knotted-hole (Furch's ball with\n"
    "                  a knotted hole: gets stuck), unknotted-hole (its control), bings-house,\n"
    "                  grid:NX,NY,NZ (Freudenthal grid of NX*NY*NZ cells, 6 tets each)\n"
    "  --order ORDER   priority (default: k = 1, 2, 3, other; then more expanded neighbours;\n"
    "                  then lower id), index (lowest id), random:SEED (seeded permutation)\n"
    "  --raw           skip the chord splits that first make the interior mesh simply connected\n"
    "                  (by default chords are split as cmx map does: only those that disconnect\n"
    "                  the interior or are axes of its handles, then every chord if needed)\n"
    "  --json          one JSON object on stdout\n"
    "Exit status: 0 when the expansion ran, stuck or not (stuck is a result, not an error);\n"
    "2 bad command line; 3 unreadable or malformed MESH; 4 MESH is not a ball.\n";

// Freudenthal grids larger than this are refused (6 tets per cell; vertex ids are 32-bit).
constexpr std::uint64_t max_builtin_tets = 100'000'000;

struct Input {
  TetMesh mesh;
  std::string source;  // the path, or "builtin:NAME"
  std::size_t chord_splits = 0;
};

// The chord splits of topology/chords.hpp on the mesh itself, as cmx map's preprocessing does.
std::vector<char> simply_connected_interior(Input& in) {
  std::vector<char> boundary = topology::boundary_vertex_flags(in.mesh);
  std::vector<char> interior = topology::interior_vertex_flags(in.mesh);
  topology::ChordContext c{in.mesh, boundary, interior, [&](topology::VertexId a, topology::VertexId b, topology::VertexId f) {
                             const topology::SplitResult r = f == topology::invalid_index ? topology::split_edge(in.mesh, a, b)
                                                                                          : topology::split_face(in.mesh, a, b, f);
                             boundary.push_back(0);
                             interior.push_back(1);
                             return r.new_vertex;
                           }};
  in.chord_splits = topology::make_interior_simply_connected(c);
  return interior;
}

// "NX,NY,NZ" with each a positive decimal; nullopt when malformed or too large.
std::optional<std::array<std::uint32_t, 3>> parse_grid_size(const std::string& text) {
  std::array<std::uint32_t, 3> n{};
  std::size_t pos = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    std::uint64_t value = 0;
    const std::size_t start = pos;
    while (pos < text.size() && text[pos] >= '0' && text[pos] <= '9' && value <= max_builtin_tets)
      value = 10 * value + std::uint64_t(text[pos++] - '0');
    if (pos == start || value == 0 || value > max_builtin_tets) return std::nullopt;
    n[k] = std::uint32_t(value);
    if (k < 2 && (pos == text.size() || text[pos++] != ',')) return std::nullopt;
  }
  if (pos != text.size()) return std::nullopt;
  const std::uint64_t columns = std::uint64_t(n[0]) * n[1];  // each factor <= 1e8: no overflow
  if (columns > max_builtin_tets / 6 || 6 * columns * n[2] > max_builtin_tets) return std::nullopt;
  return n;
}

// The complex named by --builtin, or nullopt (with a message) when the name is unknown.
std::optional<TetMesh> builtin_mesh(const std::string& name) {
  if (name == "knotted-hole") return topology::knotted_hole_ball().mesh;
  if (name == "unknotted-hole") return topology::unknotted_hole_ball().mesh;
  if (name == "bings-house") return topology::bings_house_nobuenoss().mesh;
  if (name.rfind("grid:", 0) == 0) {
    if (const auto n = parse_grid_size(name.substr(5))) return topology::grid_complex((*n)[0], (*n)[1], (*n)[2]).mesh;
    std::fprintf(stderr, "cmx topo-expand: bad grid size '%s' (want grid:NX,NY,NZ, positive, at most %llu tets)\n",
                 name.c_str(), static_cast<unsigned long long>(max_builtin_tets));
    return std::nullopt;
  }
  std::fprintf(stderr, "cmx topo-expand: unknown builtin '%s' (knotted-hole, unknotted-hole, bings-house, grid:NX,NY,NZ)\n",
               name.c_str());
  return std::nullopt;
}

std::string json_escaped(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char code[8];
      std::snprintf(code, sizeof code, "\\u%04x", unsigned(static_cast<unsigned char>(c)));
      out += code;
    } else {
      out += c;
    }
  }
  out += '"';
  return out;
}

void print_report(const Input& in, const topology::ExpansionOrder& order, const topology::TopologicalExpansionResult& r,
                  double seconds, bool json) {
  const auto& k = r.k_manifold_counts;
  const std::string order_name = topology::to_string(order);
  if (json) {
    std::printf("{\"source\": %s, \"vertices\": %zu, \"tets\": %zu, \"order\": %s,\n", json_escaped(in.source).c_str(),
                in.mesh.num_vertices(), in.mesh.num_tets(), json_escaped(order_name).c_str());
    std::printf(" \"chord_splits\": %zu, \"initial_cluster_vertices\": %zu, \"sequence_length\": %zu,\n", in.chord_splits,
                r.initial_cluster_vertices, r.length());
    std::printf(" \"k_manifold\": {\"1\": %zu, \"2\": %zu, \"3\": %zu, \"other\": %zu}, \"automatic\": %zu,\n", k[1], k[2], k[3],
                k[0], r.automatic);
    std::printf(" \"stuck\": %s, \"remaining_vertices\": %zu, \"remaining_euler\": %lld, \"remaining_components\": %zu,\n",
                r.stuck ? "true" : "false", r.remaining.size(), static_cast<long long>(r.remaining_euler), r.remaining_components);
    std::printf(" \"seconds\": %.6f}\n", seconds);
    return;
  }
  std::printf("mesh: %s (%zu vertices, %zu tets; a ball)\n", in.source.c_str(), in.mesh.num_vertices(), in.mesh.num_tets());
  std::printf("order: %s\n", order_name.c_str());
  std::printf("chord splits (to make the interior simply connected): %zu\n", in.chord_splits);
  std::printf("initial cluster vertices: %zu\n", r.initial_cluster_vertices);
  std::printf("sequence length: %zu\n", r.length());
  std::printf("expansions by kind: 1-manifold %zu, 2-manifold %zu, 3-manifold %zu, other Eq.(1) %zu, automatic %zu\n", k[1], k[2],
              k[3], k[0], r.automatic);
  if (r.stuck)
    std::printf("stuck: yes: %zu cluster vertices remain (Euler characteristic %lld, b0 %zu), none satisfies Eq. (1)\n",
                r.remaining.size(), static_cast<long long>(r.remaining_euler), r.remaining_components);
  else
    std::printf("stuck: no (every cluster vertex expanded)\n");
  std::printf("time: %.3f s (expansion)\n", seconds);
}

int run(const std::vector<std::string>& args) {
  std::string path, builtin, order_text = "priority";
  bool json = false, raw = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    // "--name VALUE" or "--name=VALUE"
    const auto value_of = [&](const std::string& name, std::string& value) -> std::optional<bool> {
      if (a.rfind(name + "=", 0) == 0) {
        value = a.substr(name.size() + 1);
        return true;
      }
      if (a != name) return std::nullopt;
      if (i + 1 == args.size()) {
        std::fprintf(stderr, "cmx topo-expand: %s needs a value\n%s", name.c_str(), usage);
        return false;
      }
      value = args[++i];
      return true;
    };
    if (a == "--help" || a == "-h") {
      std::fputs(usage, stdout);
      return exit_ok;
    }
    if (a == "--json") {
      json = true;
    } else if (a == "--raw") {
      raw = true;
    } else if (const auto got = value_of("--order", order_text)) {
      if (!*got) return exit_usage;
    } else if (const auto got_builtin = value_of("--builtin", builtin)) {
      if (!*got_builtin) return exit_usage;
    } else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "cmx topo-expand: unknown option '%s'\n%s", a.c_str(), usage);
      return exit_usage;
    } else if (path.empty()) {
      path = a;
    } else {
      std::fprintf(stderr, "cmx topo-expand: more than one MESH given\n%s", usage);
      return exit_usage;
    }
  }
  const auto order = topology::parse_expansion_order(order_text);
  if (!order) {
    std::fprintf(stderr, "cmx topo-expand: unknown order '%s' (priority, index or random:SEED)\n", order_text.c_str());
    return exit_usage;
  }
  if (path.empty() == builtin.empty()) {
    std::fprintf(stderr, "cmx topo-expand: give either MESH or --builtin NAME\n%s", usage);
    return exit_usage;
  }

  Input in;
  if (!builtin.empty()) {
    auto mesh = builtin_mesh(builtin);
    if (!mesh) return exit_usage;
    in.mesh = std::move(*mesh);
    in.source = "builtin:" + builtin;
  } else {
    try {
      io::ReadOptions keep;
      keep.orientation = io::Orientation::keep;
      const io::TetMeshData data = io::read_tet_mesh(path, keep);
      in.mesh = TetMesh(data.positions.size(), data.tets);
    } catch (const io::IoError& e) {
      std::fprintf(stderr, "%s\n", e.what());
      return exit_bad_input;
    }
    in.source = path;
  }
  const topology::BallVerdict ball = topology::check_ball(in.mesh);
  if (!ball.ok) {
    std::fprintf(stderr, "cmx topo-expand: %s is not a ball: %s\n", in.source.c_str(), ball.message.c_str());
    return exit_invalid_problem;
  }
  const std::vector<char> interior = raw ? std::vector<char>{} : simply_connected_interior(in);
  const auto start = std::chrono::steady_clock::now();
  const topology::TopologicalExpansionResult result = topology::topological_expansion(in.mesh, *order, interior);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  print_report(in, *order, result, seconds, json);
  std::fflush(stdout);
  return exit_ok;
}

[[maybe_unused]] const bool registered =
    register_command({"topo-expand", "topological expansion by Eq. (1) of a mesh's interior (reports stuck)", &run});

}  // namespace
}  // namespace cmx::cli
