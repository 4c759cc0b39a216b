#pragma once
// The map under construction (paper Alg. 1): a tet mesh with, per vertex, an
// exact source position, an exact target position and whether it is still in the cluster
// (unexpanded, sitting at the shrink point p_c). Every edit goes through here so that each split
// is mirrored in the source mesh (invariant 5) and every new vertex gets both positions.
#include <array>
#include <cstdint>
#include <vector>

#include "algorithm/vertex_properties.hpp"
#include "kernel/coordinate_arith.hpp"
#include "kernel/filter_policy.hpp"
#include "kernel/homogeneous_point.hpp"
#include "topology/tet_mesh.hpp"

namespace cmx::algorithm {

using topology::TetId;
using topology::VertexId;

struct Embedding {
  topology::TetMesh mesh;
  std::vector<HPoint> source;    // one per vertex
  std::vector<HPoint> target;    // one per vertex (unexpanded vertices: at `center`)
  std::vector<char> unexpanded;  // 1 = in the cluster mesh
  std::vector<char> boundary;    // 1 = boundary vertex (prescribed, never moves)
  HPoint center;                 // p_c
  FilterPolicy filter;           // arithmetic of every predicate
  FilterStats* stats = nullptr;  // optional tier counters
  CoordinateArith arith;         // number system of every coordinate (--arith; default exact)
  // Per-vertex data of the map's users (the expansion loop's queue state), grown with every new
  // vertex (vertex_properties.hpp); a copy of the Embedding starts without them.
  VertexProperties properties;

  std::size_t num_vertices() const { return mesh.num_vertices(); }

  // Splits edge ab at a new vertex whose source position is the source midpoint (so the source
  // mesh stays a positive refinement) and whose target position is `at`; the new vertex is a
  // cluster vertex when `in_cluster`. Returns the new vertex. Throws MapError(internal) when the
  // edge does not exist. With a non-exact `arith` the source position is rounded, and a source tet
  // the rounding flattens or inverts throws PrecisionLost (phase "split").
  VertexId split_edge(VertexId a, VertexId b, const HPoint& at, bool in_cluster);
  // Same for face abc (1 -> 3), source position the source barycentre.
  VertexId split_face(VertexId a, VertexId b, VertexId c, const HPoint& at, bool in_cluster);

  // Orientation of a tet in the target (resp. source) positions, through the filter cascade.
  Sign orient_target(const topology::Tet& t) const;
  Sign orient_source(const topology::Tet& t) const;

  // Number of cluster vertices of t.
  int unexpanded_count(const topology::Tet& t) const;

 private:
  VertexId append_vertex(const HPoint& src, const HPoint& at, bool in_cluster);
  void check_rounded_split(VertexId v, const HPoint& exact_source) const;
};

}  // namespace cmx::algorithm
