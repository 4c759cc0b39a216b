#pragma once
// The fourth way the merge pass (merge_pass.hpp) gives refinement back: an added vertex `gone`
// that no collapse, merge or relocating collapse removes is made collapsible by flips of its star.
// The flips change how gone's star polyhedron is cut into tets without moving any vertex:
//   - a 2-3 flip of an inner face (gone, b, c): the link edge bc becomes the edge de joining the
//     two apexes (one new tet de-bc leaves the star);
//   - a 3-2 flip of an edge (gone, x) in three tets: x leaves gone's link (one new tet leaves the
//     star);
//   - a 2-3 flip of a link face abc with the tet (e, a, b, c) beyond it: e joins gone's link (the
//     star grows by that tet).
// A flip is a candidate only when every tet it makes is strictly positive in the source and in the
// target (exact predicates), so the map stays valid after each one. The search is greedy: for
// every neighbour k, count the tets the collapse gone -> k would rewrite into non-positive ones;
// take the flip that makes the smallest count over all k smallest (sideways moves allowed, a flip
// never undone by a later one), at most `max_flips` flips, and none when the count starts above
// flip_collapse_max_failures; when the count reaches 0 the collapse
// is made (try_collapse, which also checks the link condition). Otherwise every flip is undone and
// the mesh is as it was.
//
// Why: on inputs without interior vertices (one-layer slabs) the added vertices left after the
// other three ways are blocked by rewritten tets made of input vertices only, which no vertex move
// can fix; only a different cut of the star can (figures: bench/RESULTS.md, "dataset").
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "algorithm/embedding.hpp"

namespace cmx::algorithm {

inline constexpr std::size_t flip_collapse_max_flips = 30;
// A vertex whose best neighbour would get more non-positive rewritten tets than this is not
// searched: such searches rarely succeed and cost about half the pass's time, for a growth
// that stays the same within 0.001 on one-layer slabs.
inline constexpr std::size_t flip_collapse_max_failures = 8;

struct FlipCollapse {
  VertexId keep{0};
  std::size_t flips = 0;
  std::vector<VertexId> touched;  // the vertices moved and those of the tets the flips made, but gone (sorted)
};

// Precondition: no cluster vertex left; `gone` interior. Throws MapError(internal) when a flip it
// made left a tet that is not positive (a bug).
// What else may remove gone once the flips are made but the plain collapse is still blocked (the
// merge pass passes its merges and relocating collapses, which move vertices): the neighbour kept
// and the vertices moved, or nullopt with nothing changed.
struct Removal {
  VertexId keep{0};
  std::vector<VertexId> moved;
};
using Remover = std::function<std::optional<Removal>()>;

std::optional<FlipCollapse> try_flip_collapse(Embedding& e, VertexId gone, const Remover& remover = {},
                                              std::size_t max_flips = flip_collapse_max_flips);

}  // namespace cmx::algorithm
