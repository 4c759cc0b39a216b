// cmx/topology.hpp: ball check, boundary faces, topological expansion and the shelling replay over
// topology/.
#include "cmx/topology.hpp"

#include <optional>
#include <utility>

#include "topology/ball_check.hpp"
#include "topology/cluster_links.hpp"
#include "topology/complex_queries.hpp"
#include "topology/fixed_boundary_replay.hpp"
#include "topology/tet_mesh.hpp"
#include "topology/topological_expansion.hpp"

namespace cmx {
namespace {

// The first tet naming a vertex >= vertex_count, as a message; nullopt when every index is valid.
std::optional<std::string> bad_index(std::span<const Tet> tets, std::size_t vertex_count) {
  for (std::size_t i = 0; i < tets.size(); ++i)
    for (const std::uint32_t v : tets[i])
      if (v >= vertex_count)
        return "tet " + std::to_string(i) + " names vertex " + std::to_string(v) + ", out of range (" +
               std::to_string(vertex_count) + " vertices)";
  return std::nullopt;
}

topology::TetMesh indexed_mesh(const char* function, std::span<const Tet> tets, std::size_t vertex_count) {
  if (const auto why = bad_index(tets, vertex_count)) throw Error(std::string(function) + ": " + *why);
  return topology::TetMesh(vertex_count, tets);
}

topology::TetMesh ball_mesh(const char* function, std::span<const Tet> tets, std::size_t vertex_count) {
  topology::TetMesh mesh = indexed_mesh(function, tets, vertex_count);
  if (const auto v = topology::check_ball(mesh); !v.ok)
    throw Error(std::string(function) + ": not a ball: " + v.message);
  return mesh;
}

// One flag per vertex for the listed cluster vertices (empty list: the interior vertices).
std::vector<char> cluster_flags(const char* function, const topology::TetMesh& mesh,
                                std::span<const std::uint32_t> cluster_vertices) {
  if (cluster_vertices.empty()) return topology::interior_vertex_flags(mesh);
  std::vector<char> flags(mesh.num_vertices(), 0);
  for (const std::uint32_t v : cluster_vertices) {
    if (v >= flags.size())
      throw Error(std::string(function) + ": cluster vertex " + std::to_string(v) + " out of range (" +
                  std::to_string(flags.size()) + " vertices)");
    flags[v] = 1;
  }
  return flags;
}

}  // namespace

BallCheck is_ball(std::span<const Tet> tets, std::size_t vertex_count) {
  if (auto why = bad_index(tets, vertex_count)) return {false, std::move(*why)};
  topology::BallVerdict v = topology::check_ball(topology::TetMesh(vertex_count, tets));
  if (v.ok) return {true, ""};
  return {false, std::move(v.message)};
}

std::vector<std::array<std::uint32_t, 3>> boundary_faces(std::span<const Tet> tets,
                                                         std::size_t vertex_count) {
  std::vector<std::array<std::uint32_t, 3>> out;
  for (const topology::BoundaryFace& f :
       topology::boundary_faces(indexed_mesh("boundary_faces", tets, vertex_count)))
    out.push_back(topology::indices_of(f.face));
  return out;
}

bool is_expandable(std::span<const Tet> tets, std::size_t vertex_count,
                   std::span<const std::uint32_t> cluster_vertices, std::uint32_t vertex) {
  const topology::TetMesh mesh = ball_mesh("is_expandable", tets, vertex_count);
  if (cluster_vertices.empty()) throw Error("is_expandable: no cluster vertices given");
  const std::vector<char> unexpanded = cluster_flags("is_expandable", mesh, cluster_vertices);
  if (vertex >= unexpanded.size() || !unexpanded[vertex])
    throw Error("is_expandable: vertex " + std::to_string(vertex) + " is not a cluster vertex");
  topology::ClusterLinkWorkspace workspace;
  return topology::is_topologically_expandable(mesh, topology::VertexId{vertex}, unexpanded, workspace);
}

TopologicalExpansion expand_topologically(std::span<const Tet> tets, std::size_t vertex_count,
                                          std::span<const std::uint32_t> cluster_vertices,
                                          std::string_view order) {
  const auto parsed = topology::parse_expansion_order(order);
  if (!parsed)
    throw Error("expand_topologically: unknown order '" + std::string(order) + "' (" +
                std::string(topology::expansion_order_syntax) + ")");
  const topology::TetMesh mesh = ball_mesh("expand_topologically", tets, vertex_count);
  const std::vector<char> unexpanded = cluster_flags("expand_topologically", mesh, cluster_vertices);
  const topology::SubcomplexCounts initial = topology::cluster_mesh_counts(mesh, unexpanded);
  topology::TopologicalExpansionResult r = topology::topological_expansion(mesh, *parsed, unexpanded);
  TopologicalExpansion out;
  out.complete = !r.stuck;
  out.sequence = topology::indices_of(r.sequence);
  out.remaining = topology::indices_of(r.remaining);
  out.initially_simply_connected = initial.vertices == 0 || (initial.components == 1 && initial.euler == 1);
  return out;
}

ShellingReplay replay_shelling(std::span<const Tet> tets, std::size_t vertex_count, std::uint64_t seed,
                               std::size_t attempts, std::size_t check_every) {
  if (attempts == 0) throw Error("replay_shelling: attempts must be at least 1");
  topology::TetMesh mesh = ball_mesh("replay_shelling", tets, vertex_count);
  topology::ShellingOptions options;
  options.max_attempts = attempts;
  options.seed = seed;
  const topology::ShellingFallback f = topology::shelling_fallback(std::move(mesh), options, check_every);
  ShellingReplay out;
  out.shelling_found = f.shelling_found;
  out.attempts = f.attempts;
  out.best_removed = f.best_removed;
  out.completed = f.replayed && f.replay.ok;
  out.expansions = f.replay.expansions;
  out.input_expansions = f.replay.input_expansions;
  out.chord_expansions = f.chord_expansions;
  out.eq1_failures = f.replay.eq1_failures;
  out.left = f.replay.left;
  out.boundary_splits = f.replay.boundary_splits;
  out.cluster_splits = f.replay.cluster_splits;
  out.free_splits = f.replay.free_splits;
  out.empty_cone_edge_splits = f.replay.empty_cone_edge_splits;
  out.checks = f.replay.checks;
  out.check_failures = f.replay.check_failures;
  out.message = f.message;
  for (const topology::ChordSplit& c : f.chords) {
    ReplayStep step;
    step.kind = c.simplex[2] == topology::invalid_vertex ? ReplayStep::Kind::edge_split
                                                         : ReplayStep::Kind::face_split;
    step.split = topology::indices_of(c.simplex);
    step.vertex = c.vertex;
    out.chords.push_back(step);
  }
  for (std::size_t i = 0; i < f.steps.size(); ++i) {
    const topology::ExpansionStep& st = f.steps[i];
    ReplayStep step;
    step.kind = st.kind == topology::ExpansionStepKind::edge_split   ? ReplayStep::Kind::edge_split
                : st.kind == topology::ExpansionStepKind::face_split ? ReplayStep::Kind::face_split
                                                                     : ReplayStep::Kind::vertex;
    step.split = topology::indices_of(st.split);
    step.vertex = st.vertex;
    step.expanded = i < f.replay.step_expanded.size() && f.replay.step_expanded[i] != 0;
    out.steps.push_back(step);
  }
  return out;
}

}  // namespace cmx
