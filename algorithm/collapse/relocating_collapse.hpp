#pragma once
// The third way the merge pass (merge_pass.hpp) gives refinement back: an added vertex `gone` is
// collapsed into a neighbour `keep` that stays where it is (a boundary vertex too), although some
// tets the collapse rewrites would not be positive, because each of those tets has another added
// vertex that can move out of the way. Those "movers" (at most three) go, one after the other, to
// a point strictly inside the kernel of their star as it will be after the collapse, in the
// source and in the target (an added vertex's two positions are both free; merge_pass.hpp says
// why), and the collapse is made only when every tet it rewrites and every tet around a mover is
// then strictly positive in both (exact). Otherwise nothing changes.
//
// Why: on inputs without interior vertices (one-layer slabs) the vertices left after the plain
// collapses and the merges are mostly blocked by one to three rewritten tets, each holding another
// added vertex, rarely by a tet of boundary vertices only; moving that vertex unblocks them.
#include <cstddef>
#include <optional>
#include <vector>

#include "algorithm/embedding.hpp"
#include "algorithm/expansion/placement.hpp"

namespace cmx::algorithm {

struct RelocatingCollapse {
  VertexId keep{0};
  std::vector<VertexId> movers;  // the added vertices that moved (at least one)
};

// Tries the neighbours of `gone` in the order of topology::vertex_neighbors. Only added vertices
// (ids >= input_vertices, not boundary) are collapsed or moved. Precondition: no cluster vertex
// left. Throws MapError(internal) if a made collapse left a tet that is not positive (a bug).
std::optional<RelocatingCollapse> try_relocating_collapse(Embedding& e, VertexId gone,
                                                          std::size_t input_vertices,
                                                          const PlacementOptions& options);

}  // namespace cmx::algorithm
