// cmx/topology.hpp: ball check, boundary faces and topological expansion over topology/.
#include "cmx/topology.hpp"

#include <optional>

#include "topology/ball_check.hpp"
#include "topology/cluster_links.hpp"
#include "topology/complex_queries.hpp"
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
    throw Error("expand_topologically: unknown order '" + std::string(order) +
                "' (priority, index or random:SEED)");
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

}  // namespace cmx
