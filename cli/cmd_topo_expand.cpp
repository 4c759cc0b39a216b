// cmx topo-expand (MESH | --builtin NAME) [--order priority|index|strict-index|random:SEED]
// [--fallback shelling|always|none] [--check] [--json]: topological expansion (paper Sec. 5.1) of a mesh's
// interior vertices, by Eq. (1) alone, and when it is stuck the shelling fallback of paper Sec. 4.3.
//
// The mesh is read with its file's vertex order kept (no geometric orientation check: this is a
// combinatorial question), then validated by topology::check_ball, which also checks that the
// tets are consistently oriented across their faces. The cluster mesh starts as the interior
// vertices and topology::topological_expansion expands it greedily in the chosen order. When that
// gets stuck, topology::shelling_fallback looks for a shelling and replays it by Alg. 2 from the
// start with the boundary in place (topology/fixed_boundary_replay.hpp), topology only.
//
// Exit codes: 0 whenever the expansion ran, stuck or not (being stuck is a result, reported in
// the output, not an error); 2 bad command line; 3 unreadable or malformed file ("file:line:
// message"); 4 read, but not a ball (the reason on stderr). Nothing is printed on stdout unless
// the exit code is 0. `--builtin` builds a complex in memory (no data file needed): the
// knotted-hole ball and its unknotted control, Bing's house (alone, and in a box), a Freudenthal
// grid.
#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/command.hpp"
#include "cli/command_line.hpp"
#include "cli/common_options.hpp"
#include "cli/json.hpp"
#include "cli/mesh_input.hpp"
#include "cmx_version.hpp"
#include "io/read_facets.hpp"
#include "topology/ball_check.hpp"
#include "topology/chords.hpp"
#include "topology/coherent_orientation.hpp"
#include "topology/complex_queries.hpp"
#include "topology/fixed_boundary_replay.hpp"
#include "topology/generators.hpp"
#include "topology/nobuenoss.hpp"
#include "topology/topological_expansion.hpp"

namespace cmx::cli::topo_expand_command {
namespace {

using topology::TetMesh;

const HelpText help = {
    "usage: cmx topo-expand (MESH | --builtin NAME) [--order ORDER] [--fallback KIND] [--check] [--raw]\n"
    "                       [--json]\n",
    "Topological expansion (paper Sec. 5.1): expands the cluster mesh of the interior vertices\n"
    "greedily by Eq. (1) alone (no geometry) and reports the sequence length, the expansions by\n"
    "kind (k-manifold k = 1, 2, 3, other Eq. (1), automatic), whether it got stuck, and when stuck\n"
    "the remaining cluster mesh (vertices, Euler characteristic, connected components). When it is\n"
    "stuck, the fallback of paper Sec. 4.3 splits every chord (an interior edge or face with all its\n"
    "vertices on the boundary), looks for a shelling (8 greedy attempts) and replays it as an\n"
    "expansion sequence (Alg. 2) from the start, with the boundary in place, checking Eq. (1) at\n"
    "every step; it reports whether the replay expands every interior vertex.\n",
    "Exit status: 0 when the expansion ran, stuck or not (stuck is a result, not an error);\n"
    "2 bad command line; 3 unreadable or malformed MESH; 4 MESH is not a ball.\n"};

// Freudenthal grids larger than this are refused (6 tets per cell; vertex ids are 32-bit).
constexpr std::uint64_t max_builtin_tets = 100'000'000;

struct Input {
  TetMesh mesh;
  std::string source;  // the path, or "builtin:NAME"
  std::size_t chord_splits = 0;
};

// The chord splits of topology/chords.hpp on the mesh itself, as cmx map's preprocessing does.
std::vector<char> simply_connected_interior(Input& in) {
  topology::ChordSplits c = topology::make_interior_simply_connected(in.mesh);
  in.chord_splits = c.splits;
  return std::move(c.interior);
}

// "C", a decimal from 1 to 64; nullopt otherwise.
std::optional<std::uint32_t> parse_collars(const std::string& text) {
  if (text.empty() || text.size() > 2 || text.find_first_not_of("0123456789") != std::string::npos)
    return std::nullopt;
  const auto c = static_cast<std::uint32_t>(std::stoul(text));
  return c >= 1 && c <= 64 ? std::optional(c) : std::nullopt;
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

// The complex named by --builtin; an unknown name is a bad command line.
TetMesh builtin_mesh(const std::string& name) {
  if (name == "knotted-hole") return topology::knotted_hole_ball().mesh;
  if (name == "unknotted-hole") return topology::unknotted_hole_ball().mesh;
  if (name == "bings-house") return topology::bings_house_nobuenoss().mesh;
  if (name == "bings-house-box") return topology::bings_house_in_box().mesh;
  if (name == "compact-bings-house-box") return topology::compact_bings_house_in_box().mesh;
  if (name == "dunce-hat-ball") return topology::dunce_hat_ball();
  if (name.rfind("dunce-hat-ball:", 0) == 0) {
    if (const auto c = parse_collars(name.substr(15))) return topology::dunce_hat_ball(nullptr, *c);
    usage_error("--builtin: bad collar count '" + name + "' (want dunce-hat-ball:C, C from 1 to 64)");
  }
  if (name.rfind("grid:", 0) == 0) {
    if (const auto n = parse_grid_size(name.substr(5)))
      return topology::grid_complex((*n)[0], (*n)[1], (*n)[2]).mesh;
    usage_error("--builtin: bad grid size '" + name + "' (want grid:NX,NY,NZ, positive, at most " +
                std::to_string(max_builtin_tets) + " tets)");
  }
  usage_error("--builtin: unknown builtin '" + name +
              "' (knotted-hole, unknotted-hole, bings-house, bings-house-box, compact-bings-house-box, "
              "dunce-hat-ball[:C], grid:NX,NY,NZ)");
}

void print_fallback_json(const std::optional<topology::ShellingFallback>& f) {
  if (!f) {
    std::printf(" \"fallback\": null,\n");
    return;
  }
  const topology::FixedBoundaryReplay& r = f->replay;
  std::printf(
      " \"fallback\": {\"split_chords\": %zu, \"shelling_found\": %s, \"attempts\": %zu,"
      " \"best_removed\": %zu, \"tets\": %zu, \"replayed\": %s,\n"
      "  \"completed\": %s, \"expansions\": %zu, \"input_expansions\": %zu, \"chord_expansions\": %zu,"
      " \"eq1_failures\": %zu,"
      " \"left\": %zu,\n"
      "  \"boundary_splits\": %zu, \"cluster_splits\": %zu, \"free_splits\": %zu,"
      " \"empty_cone_edge_splits\": %zu,\n"
      "  \"checks\": %zu, \"check_failures\": %zu,\n"
      "  \"message\": %s},\n",
      f->chords.size(), f->shelling_found ? "true" : "false", f->attempts, f->best_removed, f->tets,
      f->replayed ? "true" : "false", f->replayed && r.ok ? "true" : "false", r.expansions,
      r.input_expansions, f->chord_expansions, r.eq1_failures, r.left, r.boundary_splits, r.cluster_splits,
      r.free_splits, r.empty_cone_edge_splits, r.checks, r.check_failures, json_quote(f->message).c_str());
}

void print_fallback_text(const std::optional<topology::ShellingFallback>& f, double seconds) {
  if (!f) return;
  std::printf("fallback (paper Sec. 4.3, topology only): %s\n", f->message.c_str());
  if (f->replayed) {
    const topology::FixedBoundaryReplay& r = f->replay;
    std::printf(
        "replay: %zu expansions (%zu input vertices, %zu chord vertices, %zu split vertices), %zu failing "
        "Eq. (1), %zu cluster vertices left\n",
        r.expansions, r.input_expansions, f->chord_expansions,
        r.expansions - r.input_expansions - f->chord_expansions, r.eq1_failures, r.left);
    std::printf(
        "replay splits: %zu of boundary simplices, %zu with a cluster vertex, %zu of expanded simplices; %zu "
        "expansions split a cluster edge facing a mirrored pair (an empty geometric cone)\n",
        r.boundary_splits, r.cluster_splits, r.free_splits, r.empty_cone_edge_splits);
    if (r.checks > 0)
      std::printf("replay checks (--check): %zu cluster meshes, %zu not simply connected\n", r.checks,
                  r.check_failures);
  }
  std::printf("time: %.3f s (fallback)\n", seconds);
}

void print_report(const Input& in, const topology::ExpansionOrder& order,
                  const topology::TopologicalExpansionResult& r, double seconds,
                  const std::optional<topology::ShellingFallback>& fallback, double fallback_seconds,
                  bool json) {
  const auto& k = r.k_manifold_counts;
  const std::string order_name = topology::to_string(order);
  if (json) {
    std::printf("{\"cmx_version\": %s, \"source\": %s, \"vertices\": %zu, \"tets\": %zu, \"order\": %s,\n",
                json_quote(cmx_version).c_str(), json_quote(in.source).c_str(), in.mesh.num_vertices(),
                in.mesh.num_tets(), json_quote(order_name).c_str());
    std::printf(" \"chord_splits\": %zu, \"initial_cluster_vertices\": %zu, \"sequence_length\": %zu,\n",
                in.chord_splits, r.initial_cluster_vertices, r.length());
    std::printf(
        " \"k_manifold\": {\"1\": %zu, \"2\": %zu, \"3\": %zu, \"other\": %zu}, \"automatic\": %zu,\n", k[1],
        k[2], k[3], k[0], r.automatic);
    std::printf(
        " \"stuck\": %s, \"remaining_vertices\": %zu, \"remaining_euler\": %lld, \"remaining_components\": "
        "%zu,\n",
        r.stuck ? "true" : "false", r.remaining.size(), static_cast<long long>(r.remaining_euler),
        r.remaining_components);
    print_fallback_json(fallback);
    std::printf(" \"seconds\": %.6f, \"fallback_seconds\": %.6f}\n", seconds, fallback_seconds);
    return;
  }
  std::printf("mesh: %s (%zu vertices, %zu tets; a ball)\n", in.source.c_str(), in.mesh.num_vertices(),
              in.mesh.num_tets());
  std::printf("order: %s\n", order_name.c_str());
  std::printf("chord splits (to make the interior simply connected): %zu\n", in.chord_splits);
  std::printf("initial cluster vertices: %zu\n", r.initial_cluster_vertices);
  std::printf("sequence length: %zu\n", r.length());
  std::printf(
      "expansions by kind: 1-manifold %zu, 2-manifold %zu, 3-manifold %zu, other Eq.(1) %zu, automatic %zu\n",
      k[1], k[2], k[3], k[0], r.automatic);
  if (r.stuck)
    std::printf(
        "stuck: yes: %zu cluster vertices remain (Euler characteristic %lld, b0 %zu), none satisfies Eq. "
        "(1)\n",
        r.remaining.size(), static_cast<long long>(r.remaining_euler), r.remaining_components);
  else
    std::printf("stuck: no (every cluster vertex expanded)\n");
  std::printf("time: %.3f s (expansion)\n", seconds);
  print_fallback_text(fallback, fallback_seconds);
}

Input read_input(const std::string& path, const std::string& builtin) {
  Input in;
  if (!builtin.empty()) {
    in.mesh = builtin_mesh(builtin);
    in.source = "builtin:" + builtin;
    return in;
  }
  in.source = path;
  if (io::is_facet_list_path(path)) {
    // A facet list carries no orientation: give the tets one, as cmx map --combinatorial does.
    const io::FacetList list = io::read_facet_list_file(path);
    in.mesh = TetMesh(list.vertex_count, list.tets);
    if (const auto o = topology::orient_coherently(in.mesh); !o.ok)
      throw Failure(exit_invalid_problem,
                    path + " is not a ball: its tets cannot be oriented alike: " + o.message);
    return in;
  }
  io::ReadOptions keep;
  keep.orientation = io::Orientation::keep;
  const io::TetMeshData data = read_mesh(path, keep);
  in.mesh = TetMesh(data.positions.size(), data.tets);
  return in;
}

int run(const std::vector<std::string>& args) {
  std::string path, builtin;
  topology::ExpansionOrder order = *topology::parse_expansion_order("priority");
  bool json = false, raw = false, check = false;
  std::string fallback_name = "shelling";
  CommandLine line("topo-expand", help);
  CLI::App& app = line.app();
  app.add_option("MESH", path,
                 ".ovm .vtk .vtu .mesh .msh .node/.ele; must be a ball (tets consistently\n"
                 "oriented across faces; geometric signs are not computed: see cmx info),\n"
                 "or a facet list .facets (its tets are oriented alike first)")
      ->type_name("");
  app.add_option("--builtin", builtin,
                 "a complex built in memory instead of MESH: knotted-hole (Furch's ball\n"
                 "with a knotted hole: gets stuck), unknotted-hole (its control),\n"
                 "bings-house, bings-house-box (the house in a shellable box, stuck on\n"
                 "the house in index order only), compact-bings-house-box (the same,\n"
                 "compact: 6720 tets, the house on ids 1176-1484), dunce-hat-ball[:C]\n"
                 "(90 tets, stuck on a dunce hat, ids 19-26, in index order; shellable;\n"
                 "C collars, 1-64, each 6 vertices more, the hat on the last 8 ids),\n"
                 "grid:NX,NY,NZ\n"
                 "(Freudenthal grid of NX*NY*NZ cells, 6 tets each)")
      ->type_name("NAME");
  add_order_option(app, order,
                   "priority (default: k = 1, 2, 3, other; then more expanded neighbours;\n"
                   "then lower id), index (lowest id; strict-index is the same here),\n"
                   "random:SEED (seeded permutation); any of them followed by\n"
                   "',defer:A-B' expands ids A to B-1 only when no other vertex can be");
  app.add_option("--fallback", fallback_name,
                 "shelling (default: when stuck, look for a shelling of the mesh and replay\n"
                 "it by Alg. 2 from the start, boundary in place), always (the same even\n"
                 "when the greedy run completes: to study Alg. 2 on any ball) or none")
      ->check(CLI::IsMember({"shelling", "always", "none"}))
      ->type_name("KIND");
  app.add_flag("--check", check,
               "check before and after every expansion of the fallback's replay that the\n"
               "cluster mesh is simply connected (Corollary 1); O(T) per expansion: about\n"
               "2 minutes on bings-house-box");
  app.add_flag("--raw", raw,
               "skip the chord splits that first make the interior mesh simply\n"
               "connected (by default chords are split as cmx map does: only those\n"
               "that disconnect the interior or are axes of its handles, then every\n"
               "chord if needed; the fallback splits every chord in any case)");
  app.add_flag("--json", json, "one JSON object on stdout (with cmx_version)");
  line.quiet_flag()->description("accepted for uniformity: topo-expand prints only its results");
  if (const auto done = line.parse(args)) return *done;
  if (path.empty() == builtin.empty()) usage_error("give either MESH or --builtin NAME");
  Input in = read_input(path, builtin);
  const topology::BallVerdict ball = topology::check_ball(in.mesh);
  if (!ball.ok) throw Failure(exit_invalid_problem, in.source + " is not a ball: " + ball.message);
  const std::vector<char> interior = raw ? std::vector<char>{} : simply_connected_interior(in);
  const auto start = std::chrono::steady_clock::now();
  const topology::TopologicalExpansionResult result =
      topology::topological_expansion(in.mesh, order, interior);
  const auto expanded = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(expanded - start).count();
  std::optional<topology::ShellingFallback> fallback;
  if (fallback_name == "always" || (result.stuck && fallback_name == "shelling"))
    fallback = topology::shelling_fallback(in.mesh, {}, check ? 1 : 0);
  const double fallback_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - expanded).count();
  print_report(in, order, result, seconds, fallback, fallback_seconds, json);
  std::fflush(stdout);
  return exit_ok;
}

[[maybe_unused]] const bool registered = register_command(
    {"topo-expand", "topological expansion by Eq. (1) of a mesh's interior (reports stuck)", &run});

}  // namespace
}  // namespace cmx::cli::topo_expand_command
