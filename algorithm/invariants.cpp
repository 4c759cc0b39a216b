#include "algorithm/invariants.hpp"

#include "algorithm/describe.hpp"
#include "topology/cluster_links.hpp"

namespace cmx::algorithm {

namespace {

std::string tet_text(const topology::Tet& t) { return "tet " + ids_text(t); }

std::string check_tet(const Embedding& e, const topology::Tet& t) {
  if (e.unexpanded_count(t) <= 1 && e.orient_target(t) != Sign::positive)
    return tet_text(t) + " has at most one cluster vertex but is not positive in the target";
  if (e.orient_source(t) != Sign::positive) return tet_text(t) + " is not positive in the source";
  return {};
}

}  // namespace

std::string check_invariants(const Embedding& e, const std::vector<HPoint>& prescribed) {
  std::size_t cluster = 0;
  for (VertexId v = 0; v < e.num_vertices(); ++v) {
    if (e.unexpanded[v]) {
      ++cluster;
      if (!(e.target[v] == e.center)) return "cluster vertex " + std::to_string(v) + " is not at p_c";
    }
    if (e.boundary[v] && !(e.target[v] == prescribed[v]))
      return "boundary vertex " + std::to_string(v) + " left its prescribed position";
  }
  for (TetId t : e.mesh.live_tets())
    if (std::string why = check_tet(e, e.mesh.tet(t)); !why.empty()) return why;
  if (cluster > 0) {
    const auto c = topology::cluster_mesh_counts(e.mesh, e.unexpanded);
    if (c.components != 1 || c.euler != 1)
      return "the cluster mesh is not simply connected (b0 = " + std::to_string(c.components) +
             ", chi = " + std::to_string(c.euler) + ")";
  }
  return {};
}

std::string check_local_invariant(const Embedding& e, VertexId v) {
  for (TetId t : e.mesh.tets_of(v))
    if (std::string why = check_tet(e, e.mesh.tet(t)); !why.empty()) return why;
  return {};
}

}  // namespace cmx::algorithm
