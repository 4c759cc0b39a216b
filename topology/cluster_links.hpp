#pragma once
// Cluster-mesh combinatorics (paper Sec. 3): for the unexpanded vertex set U (a flag per vertex)
// and v in U,
//   Lk•(v) = simplices of Lk(v) whose vertices are all unexpanded (the link of v in M•),
//   Lk°(v) = simplices of Lk(v) whose vertices are all expanded (the expansion cone base).
// Eq. (1): v is topologically expandable iff b0(Lk•(v)) = 1 and chi(Lk•(v)) = 1; by Prop. 3
// this is equivalent to b0(Lk°(v)) = 1 and chi(Lk°(v)) = 1 when v is interior (Lk(v) a sphere).
// k-manifold expandability (Sec. 3.2): 1 when Lk•(v) is a single vertex (v on one cluster edge),
// 2 when Lk•(v) is a path with >= 1 edge and no triangle (v on the boundary of one open triangle
// fan), 3 when Lk•(v) is a 2-disc (v on the boundary of one open half-ball); 0 otherwise
// (possibly still expandable by Eq. (1), e.g. Lk• a branching tree).
// Every query costs O(d log d) with d the number of tets around v; no mesh-sized memory.

#include <cstdint>
#include <span>
#include <vector>

#include "topology/complex_queries.hpp"
#include "topology/tet_mesh.hpp"

namespace cmx::topology {

struct LinkStats {
  std::uint32_t vertices = 0, edges = 0, triangles = 0;
  std::int32_t euler = 0;       // V - E + F
  std::uint32_t components = 0; // b0 (0 for an empty link)
  [[nodiscard]] bool simply_connected() const { return components == 1 && euler == 1; }
};

struct ClusterVertexStatus {
  LinkStats unexpanded_link;       // Lk•(v)
  std::uint32_t expanded_neighbors = 0;  // #vertices of Lk°(v)
  bool expandable = false;         // Eq. (1)
  int manifold_k = 0;              // 1, 2, 3, or 0 (not k-manifold-expandable)
};

// Reusable scratch buffers, so that repeated queries allocate nothing. Not thread-safe: one per
// thread. Holds no state between calls.
class ClusterLinkWorkspace {
 public:
  std::vector<VertexId> verts;
  std::vector<std::uint64_t> edges;
  std::vector<std::array<std::uint32_t, 3>> tris;  // local indices
  std::vector<std::uint32_t> parent;
  std::vector<std::uint32_t> degree;
  std::vector<std::uint32_t> scratch;
  std::vector<std::uint32_t> fan_nodes, fan_parent, fan_degree;
  std::uint32_t all_neighbors = 0;  // #distinct neighbours of the last vertex gathered
};

// `unexpanded` has one flag per vertex (non-zero = in U). Precondition: v < m.num_vertices().
[[nodiscard]] LinkStats unexpanded_link_stats(const TetMesh& m, VertexId v, std::span<const char> unexpanded,
                                              ClusterLinkWorkspace& ws);
[[nodiscard]] LinkStats expanded_link_stats(const TetMesh& m, VertexId v, std::span<const char> unexpanded,
                                            ClusterLinkWorkspace& ws);
// Eq. (1).
[[nodiscard]] bool is_topologically_expandable(const TetMesh& m, VertexId v, std::span<const char> unexpanded,
                                               ClusterLinkWorkspace& ws);
// 1, 2, 3 or 0, as above.
[[nodiscard]] int manifold_expandability(const TetMesh& m, VertexId v, std::span<const char> unexpanded,
                                         ClusterLinkWorkspace& ws);
// Everything above in one pass over v's star.
[[nodiscard]] ClusterVertexStatus classify_cluster_vertex(const TetMesh& m, VertexId v,
                                                          std::span<const char> unexpanded,
                                                          ClusterLinkWorkspace& ws);
// Vertices b of Lk°(v) whose star in Lk°(v) is not a single triangle fan: b lies on no triangle
// of Lk°(v), or on an edge of Lk°(v) that is in no triangle, or its triangles form 2+ fans.
// These are the vertices inflation splits around (paper Sec. 4.2.1). Ascending.
[[nodiscard]] std::vector<VertexId> expanded_link_cut_vertices(const TetMesh& m, VertexId v,
                                                               std::span<const char> unexpanded);

// The cluster mesh M• (full subcomplex on the unexpanded vertices): counts, chi and b0.
// O(T log d). The method keeps b0 = 1 and chi = 1 (algorithm/verify/invariants.hpp).
[[nodiscard]] SubcomplexCounts cluster_mesh_counts(const TetMesh& m, std::span<const char> unexpanded);
// A tet is degenerate exactly when it has two or more unexpanded vertices (invariant 2).
[[nodiscard]] bool is_degenerate_tet(const Tet& t, std::span<const char> unexpanded);
[[nodiscard]] std::size_t count_degenerate_tets(const TetMesh& m, std::span<const char> unexpanded);

// The links themselves as explicit simplex sets (for inspection and tests).
[[nodiscard]] SimplexSet unexpanded_link(const TetMesh& m, VertexId v, std::span<const char> unexpanded);
[[nodiscard]] SimplexSet expanded_link(const TetMesh& m, VertexId v, std::span<const char> unexpanded);

}  // namespace cmx::topology
