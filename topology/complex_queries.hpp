#pragma once
// Incidence, star, link and closure queries on a TetMesh, optionally restricted to a vertex
// subset view (the full subcomplex induced by the subset: a simplex belongs to it when all its
// vertices do). All per-vertex/per-edge queries cost O(d log d) where d is the number of tets
// around the vertex (edge); whole-mesh queries cost O(T log d_max).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "topology/tet_mesh.hpp"

namespace cmx::topology {

// A set of simplices, each stored with ascending vertices; every list sorted and unique.
// Used for stars (not closed under faces), links and closures (closed).
struct SimplexSet {
  std::vector<VertexId> vertices;
  std::vector<Edge> edges;
  std::vector<Triangle> triangles;
  std::vector<Tet> tets;
};

// Euler characteristic #V - #E + #F - #T of the listed simplices.
[[nodiscard]] std::int64_t euler_characteristic(const SimplexSet& s);
// Number of connected components (b0) of the complex made of the listed simplices. Precondition:
// every vertex of a listed simplex is in s.vertices (true for links and closures).
[[nodiscard]] std::size_t connected_components(const SimplexSet& s);

// Live tets containing all given vertices (edge: 2, face: 3).
[[nodiscard]] std::vector<TetId> tets_around_edge(const TetMesh& m, VertexId a, VertexId b);
[[nodiscard]] std::vector<TetId> tets_around_face(const TetMesh& m, VertexId a, VertexId b,
                                                  VertexId c);
// Edge ab lies on the boundary: some face through it is in one live tet only.
[[nodiscard]] bool edge_on_boundary(const TetMesh& m, VertexId a, VertexId b);
// Vertices sharing a tet with v (v excluded), ascending.
[[nodiscard]] std::vector<VertexId> vertex_neighbors(const TetMesh& m, VertexId v);

// St(v), Cl(v), Lk(v) restricted to `subset` (a simplex is kept when all its vertices are in the
// subset; the star/closure of a vertex outside the subset is empty).
[[nodiscard]] SimplexSet vertex_star(const TetMesh& m, VertexId v, VertexSubset subset = {});
[[nodiscard]] SimplexSet vertex_closure(const TetMesh& m, VertexId v, VertexSubset subset = {});
[[nodiscard]] SimplexSet vertex_link(const TetMesh& m, VertexId v, VertexSubset subset = {});
// Same for an edge ab (the link of an edge is at most 1-dimensional).
[[nodiscard]] SimplexSet edge_star(const TetMesh& m, VertexId a, VertexId b, VertexSubset subset = {});
[[nodiscard]] SimplexSet edge_closure(const TetMesh& m, VertexId a, VertexId b,
                                      VertexSubset subset = {});
[[nodiscard]] SimplexSet edge_link(const TetMesh& m, VertexId a, VertexId b, VertexSubset subset = {});

// Counts of the full subcomplex induced by `subset` (vertices without any live tet are ignored).
struct SubcomplexCounts {
  std::size_t vertices = 0, edges = 0, triangles = 0, tets = 0;
  std::int64_t euler = 0;      // V - E + F - T
  std::size_t components = 0;  // b0
};
[[nodiscard]] SubcomplexCounts subcomplex_counts(const TetMesh& m, VertexSubset subset = {});

// Faces lying in exactly one live tet, oriented outward (see tet_face), with the tet and the
// local index of the opposite vertex. Meaningful when every face is in at most two tets.
struct BoundaryFace {
  Triangle face;
  TetId tet;
  std::uint8_t opposite;
};
[[nodiscard]] std::vector<BoundaryFace> boundary_faces(const TetMesh& m);
// 1 for vertices on a boundary face, 0 otherwise (size num_vertices()).
[[nodiscard]] std::vector<char> boundary_vertex_flags(const TetMesh& m);
// 1 for vertices with at least one tet and on no boundary face: the initial cluster mesh.
[[nodiscard]] std::vector<char> interior_vertex_flags(const TetMesh& m);

// neighbor[t][i] = the live tet across the face opposite local vertex i, invalid_index on the
// boundary. `nonmanifold_face` is set (and the table partial) when a face lies in 3+ tets.
struct TetAdjacency {
  std::vector<std::array<TetId, 4>> neighbor;
  bool manifold = true;
  Triangle nonmanifold_face{};
};
[[nodiscard]] TetAdjacency tet_adjacency(const TetMesh& m);

}  // namespace cmx::topology
