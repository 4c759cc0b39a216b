#pragma once
// Giving refinement back (paper Sec. 4.2.2, applied once the map is complete): every vertex the
// method added (preprocessing splits, pushes, inflation) is collapsed into a neighbour when the
// collapse keeps the map valid: the link condition holds (the mesh stays a ball) and every tet
// that the collapse rewrites is strictly positive in the source and in the target, exactly.
// Added vertices are interior, so the boundary is untouched. The collapsed vertices are removed
// and the remaining added vertices renumbered; input vertices keep their ids.
#include <cstddef>
#include <optional>

#include "algorithm/embedding.hpp"

namespace cmx::algorithm {

// Collapses the expanded vertex `gone` into an expanded neighbour when that keeps every invariant
// (link condition; rewritten tets positive in the source, and in the target unless they have two
// or more cluster vertices). Valid mid-run: the cluster mesh does not change. Returns the
// neighbour kept, or nullopt (nothing changed).
std::optional<VertexId> try_collapse(Embedding& e, VertexId gone);

// Precondition: no cluster vertex left. `input_vertices`: the ids below it are never removed.
// Rounds of plain collapses until none is left. Returns the number of vertices removed.
// Collapsed vertices are left without tets: Embedding::compact_vertices removes them. Merges, which may
// follow, are in merge_pass.hpp.
std::size_t collapse_added_vertices(Embedding& e, std::size_t input_vertices);

}  // namespace cmx::algorithm
