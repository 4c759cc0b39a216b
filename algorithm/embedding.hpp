#pragma once
// The map under construction (paper Alg. 1): a tet mesh with, per vertex, an
// exact source position, an exact target position and whether it is still in the cluster
// (unexpanded, sitting at the shrink point p_c). Every edit of the mesh goes through here: splits
// (so that each is mirrored in the source mesh, invariant 5, every new vertex gets both positions
// and every per-vertex property grows), collapses, flips and the final compaction. Positions and
// flags are plain arrays that the method's steps read and move.
#include <array>
#include <cstdint>
#include <vector>

#include "algorithm/vertex_properties.hpp"
#include "kernel/coordinate_arith.hpp"
#include "kernel/filter_policy.hpp"
#include "kernel/homogeneous_point.hpp"
#include "topology/mesh_edits.hpp"
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
  // A ball given by its tets alone (MapOptions::combinatorial): the source positions carry no
  // geometry, every tet counts as positive in the source, and every vertex ever made records the
  // two or three vertices whose edge or face its split divided (invalid_index three times for an
  // input vertex), from which the verifier recomputes its barycentric coordinates in the input
  // complex. `parents` is indexed by creation number and never compacted (a vertex dropped at the
  // end, a push undone, may be a parent of one that stays); `origin` gives each vertex's creation
  // number and is compacted with the vertices. Both empty unless source_free.
  bool source_free = false;
  std::vector<std::array<std::uint32_t, 3>> parents;
  std::vector<std::uint32_t> origin;
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

  // The edits that change connectivity and keep vertex positions (topology/mesh_edits.hpp). The
  // caller has checked that the new tets are positive: these only apply them.
  // Edge (keep, gone) contracted into keep; gone is left without tets (compact_vertices drops it).
  topology::CollapseResult collapse_edge(VertexId keep, VertexId gone);
  // A 2-3 or 3-2 flip, and its exact undo.
  topology::FlipResult apply_flip(const topology::FlipPlan& plan);
  void undo_flip(const topology::FlipResult& flip);
  // Drops the added vertices (index >= input_vertices) that no tet uses; the others keep their
  // order. Precondition: no live property (properties index by the old numbering).
  void compact_vertices(std::size_t input_vertices);

  // Orientation of a tet in the target (resp. source) positions, through the filter cascade.
  Sign orient_target(const topology::Tet& t) const;
  Sign orient_source(const topology::Tet& t) const;

  // Number of cluster vertices of t.
  int unexpanded_count(const topology::Tet& t) const;

 private:
  VertexId append_vertex(const HPoint& src, const HPoint& at, bool in_cluster, const std::array<std::uint32_t, 3>& from);
  void check_rounded_split(VertexId v, const HPoint& exact_source) const;
};

}  // namespace cmx::algorithm
