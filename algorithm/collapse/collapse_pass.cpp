#include "algorithm/collapse/collapse_pass.hpp"

#include <algorithm>

#include "topology/complex_queries.hpp"
#include "topology/mesh_edits.hpp"

namespace cmx::algorithm {

namespace {

// Every tet around `gone` that does not contain `keep`, with `gone` replaced by `keep`, keeps the
// invariants: strictly positive in the source, and in the target unless it has two or more
// cluster vertices (degenerate by design; none are left at the end of a run).
bool collapse_keeps_map_valid(const Embedding& e, VertexId keep, VertexId gone) {
  for (TetId t : e.mesh.tets_of(gone)) {
    topology::Tet x = e.mesh.tet(t);
    if (topology::contains(x, keep)) continue;
    x[topology::local_index(x, gone)] = keep;
    if (e.orient_source(x) != Sign::positive) return false;
    if (e.unexpanded_count(x) <= 1 && e.orient_target(x) != Sign::positive) return false;
  }
  return true;
}

}  // namespace

std::optional<VertexId> try_collapse(Embedding& e, VertexId gone) {
  if (e.unexpanded[gone]) return std::nullopt;
  for (VertexId keep : topology::vertex_neighbors(e.mesh, gone)) {
    // Into an expanded vertex only: the cluster mesh (simplices of cluster vertices) is untouched.
    if (e.unexpanded[keep] || !collapse_keeps_map_valid(e, keep, gone)) continue;
    if (e.collapse_edge(keep, gone).ok) return keep;
  }
  return std::nullopt;
}

std::size_t collapse_added_vertices(Embedding& e, std::size_t input_vertices) {
  std::size_t removed = 0;
  for (bool progress = true; progress;) {
    progress = false;
    for (std::size_t v = e.num_vertices(); v-- > input_vertices;) {
      if (e.mesh.tets_of(VertexId(v)).empty()) continue;
      if (try_collapse(e, VertexId(v))) {
        ++removed;
        progress = true;
      }
    }
  }
  return removed;
}

}  // namespace cmx::algorithm
