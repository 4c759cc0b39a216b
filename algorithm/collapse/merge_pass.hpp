#pragma once
// Merges of added vertices (the second half of the collapse pass, collapse_pass.hpp): an added
// vertex `gone` is collapsed into an interior neighbour `keep`, which then moves to a point
// strictly inside its new star's kernel: in the source and in the target when `keep` is an added
// vertex too, in the target only when it is an input vertex (whose source position is kept).
//
// Why: the plain collapse keeps `keep` where it is, and on inputs without interior vertices
// (one-layer slabs) most added vertices are left because of that. The target position of any
// interior vertex is free, and so is the source position of an added one: it only has to keep the
// source tets positive, since the output's source mesh must tile the input domain, not refine
// the input tets (the verifier checks the boundary, input vertices in place, a ball, every tet
// positive). Measured in bench/RESULTS.md ("dataset").
//
// The point: keep's own position, gone's, or their midpoint when one is strictly inside (exact
// tests, no LP); else the precision-reduced Chebyshev centre when the float LP finds room. The
// source is tried first (its coordinates have few bits), the link condition next, the target last.
// A float screen only ever skips a merge, which is always safe; whatever is taken is checked
// exactly: every tet around `keep` is strictly positive in both afterwards (else MapError
// internal, which would be a bug).
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "algorithm/embedding.hpp"
#include "algorithm/expansion/placement.hpp"
#include "algorithm/run_control.hpp"

namespace cmx::algorithm {

// Below this float Chebyshev radius (relative to the rows' scale) a merge or a relocating
// collapse tries no exact LP: the float screen only ever skips a move, which is always safe.
inline constexpr double merge_min_float_radius = 1e-11;

struct MergeResult {
  std::size_t removed = 0;     // vertices left without tets (Embedding::compact_vertices removes them)
  std::size_t relocating = 0;  // of those, by relocating collapses (relocating_collapse.hpp)
  std::size_t flipping = 0;    // of those, by flip collapses (flip_collapse.hpp)
  bool stopped = false;        // told to stop first: `e` is partly merged (the caller undoes)
};

struct MergeSettings {
  RunControl* control = nullptr;  // polled before every removal attempt (phase "collapse")
  // Called after every removal with the vertices whose stars hold every tet it changed (the vertex
  // kept, the vertices moved, the vertices of the tets flips made): `--check` checks there.
  std::function<void(const std::vector<VertexId>&)> after_step;
  bool flip_collapses = true;  // `--no-flip-collapse` turns them off
};

// Merges, relocating collapses (relocating_collapse.hpp), flip collapses (flip_collapse.hpp) and
// the plain collapses they make possible, over the added vertices (ids >= input_vertices), highest id first,
// a vertex coming back only when a star it is in changed (or a vertex of it moved). Precondition: no cluster
// vertex left.
MergeResult merge_added_vertices(Embedding& e, std::size_t input_vertices, const PlacementOptions& options,
                                 const MergeSettings& settings = {});

}  // namespace cmx::algorithm
