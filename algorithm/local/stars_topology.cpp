#include "algorithm/local/stars_topology.hpp"

namespace cmx::algorithm::stars {

topology::BallVerdict check_ball_of(const topology::TetMesh& mesh, const std::vector<topology::TetId>& tets) {
  std::vector<topology::VertexId> local(mesh.num_vertices(), topology::invalid_vertex), global;
  std::vector<topology::Tet> renumbered;
  renumbered.reserve(tets.size());
  for (topology::TetId t : tets) {
    topology::Tet r = mesh.tet(t);
    for (topology::VertexId& v : r) {
      if (local[v] == topology::invalid_index) {
        local[v] = topology::VertexId(global.size());
        global.push_back(v);
      }
      v = local[v];
    }
    renumbered.push_back(r);
  }
  topology::BallVerdict verdict = topology::check_ball(topology::TetMesh(global.size(), renumbered));
  for (topology::VertexId& v : verdict.simplex)
    if (v < global.size()) v = global[v];
  return verdict;
}

}  // namespace cmx::algorithm::stars
