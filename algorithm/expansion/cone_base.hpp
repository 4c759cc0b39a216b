#pragma once
// Queries on the base of a cluster vertex's expansion cone (its expanded link Lk°(v)), used by
// the refinement steps of the expansion loop: the base as a 2-complex, its dangling edges, the
// ring around a spoke, whether a push or a bend of a base vertex is possible, and the linear
// constraints of a bend. All read the embedding only (its current, possibly virtual, positions).
#include <array>
#include <unordered_map>
#include <utility>
#include <vector>

#include "algorithm/embedding.hpp"
#include "algorithm/expansion/expansion_cone.hpp"

namespace cmx::algorithm {

struct ConeBase {
  std::vector<VertexId> verts;                               // expanded neighbours of v, ascending
  std::unordered_map<VertexId, std::vector<VertexId>> adj;   // base edges (with repeats)
  std::unordered_map<VertexId, int> tets;                    // base triangles at each vertex
  std::vector<std::array<VertexId, 3>> triangles;
};

ConeBase cone_base(const Embedding& e, VertexId v);

// The witness of star-shapification: the base vertex in most base triangles (smallest id among
// equals), and one base triangle through it that refinement keeps. Precondition: a base triangle.
struct Witness {
  VertexId vertex;
  std::array<VertexId, 3> keep;
};
Witness choose_witness(const ConeBase& base);

// Distances in base edges from `from` to every base vertex it reaches.
std::unordered_map<VertexId, int> base_distances(const ConeBase& base, VertexId from);

// The centroid of a triangle of target positions: the aim point of star-shapification.
HPoint centroid(const Embedding& e, const std::array<VertexId, 3>& t);

// A base edge in no base triangle: its two Lk(v) triangles have cluster vertices, whose side
// planes through p_c face each other and flatten the kernel.
bool has_dangling_edge(const ConeBase& base);

// Base edges of v in no base triangle, with the cluster vertices of their two Lk(v) triangles:
// {a, b, u1, u2} (u2 = u1 when there is only one).
std::vector<std::array<VertexId, 4>> dangling_edges(const Embedding& e, VertexId v);

// The ring around spoke (v, b): the pairs of other vertices of the tets containing both.
std::vector<std::pair<VertexId, VertexId>> spoke_ring(const Embedding& e, VertexId v, VertexId b);

// b's neighbours in Lk(v) are one run of cluster vertices and one run of expanded vertices:
// pushing b keeps Eq. (1) for v (chi(Lk•(v)) changes by 1 - runs).
bool is_pushable(const Embedding& e, VertexId v, VertexId b);

// b is an ear of v's base disc: removing b's triangles leaves a disc (b's expanded neighbours in
// Lk(v) form an arc of at least two vertices whose inner vertices have no cluster neighbour in
// Lk(v); for an arc of two, their edge lies in a second base triangle).
bool is_ear(const Embedding& e, VertexId v, VertexId b);

// The cone of the vertex a bend of spoke (v, b) creates: the spoke's tets with it in place of v
// (it must see the face opposite v from inside) and with it in place of b, v at p_c (a constraint
// when v is their only cluster vertex). With v in the cluster this is a fan around b: it always
// has interior when b's base star is one fan.
ExpansionCone bend_cone(const Embedding& e, VertexId v, VertexId b);

// Constraints on the bent position q of b for v's side tets through b to show `aim` from inside
// (linear in q). With `only_violated`, just the first one b's current position violates.
void add_aim_constraints(ExpansionCone& cone, const Embedding& e, VertexId v, VertexId b, const HPoint& aim,
                         bool only_violated);

// Side constraints of v that the direction toward `aim` violates, counted per expanded endpoint:
// the planes through p_c and a base boundary edge that keep v from moving that way.
std::unordered_map<VertexId, int> blocking_endpoints(const Embedding& e, VertexId v, const HPoint& aim);

}  // namespace cmx::algorithm
