#pragma once
// Laplacian smoothing of one expanded vertex (paper Sec. 4.2.4), used by the expansion loop's
// `--smooth N`: the centroid of its *expanded* neighbours (cluster neighbours sit at p_c and would
// pull it back there), rounded to 53-bit dyadics, else halfway back toward the current position,
// at most four tries. A position is returned only when it is strictly inside the vertex's own
// cone (exact): every tet around it keeps its state, so every invariant holds.
#include <optional>
#include <vector>

#include "algorithm/embedding.hpp"

namespace cmx::algorithm {

std::optional<HPoint> laplacian_position(const Embedding& e, VertexId v);

// The vertices to smooth after `recent` were expanded: their expanded, non-boundary neighbours
// that still touch the cluster, in increasing order, each once.
std::vector<VertexId> smoothing_candidates(const Embedding& e, const std::vector<VertexId>& recent);

}  // namespace cmx::algorithm
