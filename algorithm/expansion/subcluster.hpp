#pragma once
// Subcluster expansion (paper Sec. 4.2.5): when no single cluster vertex is simply expandable, a
// set S of 2 to 4 cluster vertices, v and cluster neighbours of v, may still be: S moves together
// to a point q in the kernel of the union of its cones (the tets with exactly one vertex of S,
// the other three corners at pairwise distinct positions, become positive; tets with two or more
// vertices of S stay degenerate, all of them at q), and then its vertices leave q one at a time,
// each to the Chebyshev centre of its own cone with the rest of S at q.
//
// The same rule builds every cone here: a tet constrains the moving vertex exactly when the
// other three corners are at pairwise distinct positions; coincident corners (two at p_c, or two
// of S still at q) leave it degenerate whatever the move. With S at p_c and one mover it is the
// ordinary expansion cone (expansion_cone.hpp).
//
// Why the result keeps every invariant: each move makes every tet around the mover either
// strictly positive or degenerate by coincident corners; when the last vertex of S has left q,
// the only coincident corners left are cluster vertices at p_c, so a tet is degenerate exactly
// when it has two or more cluster vertices (invariant 2). Invariant 3 holds because the order is
// chosen so that every vertex satisfies Eq. (1) when it leaves the cluster: topologically the
// result is a sequence of single expansions. Nothing is split, so the source is untouched.
//
// The plan is computed on the embedding itself (positions changed and restored), so a failed
// search leaves it exactly as it was. The caller commits a plan by setting every position and
// flag, then checks invariant 2 around S exactly.
#include <cstddef>
#include <optional>
#include <vector>

#include "algorithm/embedding.hpp"
#include "algorithm/expansion/placement.hpp"
#include "topology/cluster_links.hpp"
#include "topology/topological_expansion.hpp"

namespace cmx::algorithm {

struct SubclusterMove {
  VertexId v;
  Placement placement;  // where v goes
  int manifold_k;       // k-manifold expandability when it left the cluster
};

struct SubclusterCounters {
  std::size_t candidates = 0;  // sets screened by the float LP
  std::size_t exact_lps = 0;   // certified/exact LPs solved for sets that passed the screen
};

// The subclusters tried around v, in order: sizes 2, 3, 4 (up to max_size), v's cluster
// neighbours ranked by how many of v's side constraints (planes through p_c) they carry, since
// moving them with v removes those constraints. At most 14 sets. A neighbour the order defers
// (topology::ExpansionOrder::deferred) joins only a deferred v: the deferral is the caller's word.
std::vector<std::vector<VertexId>> subcluster_candidates(const Embedding& e, VertexId v, std::size_t max_size,
                                                         const topology::ExpansionOrder& order = {});

// The first candidate set that expands, as the moves in order; nullopt when none does. `e` is
// unchanged on return.
std::optional<std::vector<SubclusterMove>> plan_subcluster(Embedding& e, VertexId v, std::size_t max_size,
                                                           const PlacementOptions& options,
                                                           topology::ClusterLinkWorkspace& ws,
                                                           SubclusterCounters& counters,
                                                           const topology::ExpansionOrder& order = {});

// The cone of a common new position of `movers` under the coincidence rule above.
ExpansionCone coincidence_cone(const Embedding& e, const std::vector<VertexId>& movers);

}  // namespace cmx::algorithm
