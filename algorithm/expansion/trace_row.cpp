#include "algorithm/expansion/trace_row.hpp"

#include <algorithm>

#include "topology/cluster_links.hpp"

namespace cmx::algorithm {

TraceRow state_row(const Embedding& e, std::size_t input_vertices) {
  TraceRow row;
  double total = 0;
  std::size_t live = 0;
  for (VertexId w{0}; w < e.num_vertices(); ++w) {
    if (e.mesh.tets_of(w).empty()) continue;
    const std::size_t b = e.target[w].bit_size();
    row.max_bits = std::max(row.max_bits, b);
    total += double(b);
    ++live;
  }
  row.mean_bits = live ? total / double(live) : 0;
  row.added_vertices = e.num_vertices() - input_vertices;
  row.degenerate_left = topology::count_degenerate_tets(e.mesh, e.unexpanded);
  return row;
}

}  // namespace cmx::algorithm
