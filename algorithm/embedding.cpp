#include "algorithm/embedding.hpp"

#include <string>

#include "algorithm/map_error.hpp"
#include "algorithm/verify/invariants.hpp"
#include "kernel/orient.hpp"
#include "topology/mesh_edits.hpp"

namespace cmx::algorithm {

VertexId Embedding::append_vertex(const HPoint& src, const HPoint& at, bool in_cluster,
                                  const std::array<std::uint32_t, 3>& from) {
  if (source_free) {
    origin.push_back(static_cast<std::uint32_t>(parents.size()));
    std::array<std::uint32_t, 3> by_creation = from;
    for (auto& p : by_creation)
      if (p != topology::invalid_index) p = origin[p];
    parents.push_back(by_creation);
  }
  source.push_back(arith.round(src));
  target.push_back(arith.round(at));
  unexpanded.push_back(in_cluster ? 1 : 0);
  boundary.push_back(0);
  properties.grow(source.size());
  return VertexId(source.size() - 1);
}

// A non-exact arith rounds the source midpoint (or barycentre) of a split: its tets may flatten.
void Embedding::check_rounded_split(VertexId v, const HPoint& exact_source) const {
  if (source_free || arith.exact() || source[v] == exact_source) return;
  if (const std::optional<InvalidTet> bad = first_invalid_tet_around(*this, v, true))
    throw PrecisionLost(precision_loss_at(
        *this, v, *bad, "split",
        "the rounded source position of new vertex " + std::to_string(v) + " flattens a source tet"));
}

VertexId Embedding::split_edge(VertexId a, VertexId b, const HPoint& at, bool in_cluster) {
  const HPoint src = midpoint(source[a], source[b]);
  const topology::SplitResult r = topology::split_edge(mesh, a, b);
  if (!r.ok) throw MapError(MapErrorKind::internal, "edge split refused: " + r.message);
  const VertexId v = append_vertex(src, at, in_cluster, {a.idx(), b.idx(), topology::invalid_index});
  if (v != r.new_vertex) throw MapError(MapErrorKind::internal, "edge split: vertex numbering out of step");
  check_rounded_split(v, src);
  return v;
}

VertexId Embedding::split_face(VertexId a, VertexId b, VertexId c, const HPoint& at, bool in_cluster) {
  const HPoint pts[3] = {source[a], source[b], source[c]};
  const Rational third(1, 3);
  const Rational w[3] = {third, third, third};
  const HPoint src = convex_combination(pts, w, 3);
  const topology::SplitResult r = topology::split_face(mesh, a, b, c);
  if (!r.ok) throw MapError(MapErrorKind::internal, "face split refused: " + r.message);
  const VertexId v = append_vertex(src, at, in_cluster, {a.idx(), b.idx(), c.idx()});
  if (v != r.new_vertex) throw MapError(MapErrorKind::internal, "face split: vertex numbering out of step");
  check_rounded_split(v, src);
  return v;
}

topology::CollapseResult Embedding::collapse_edge(VertexId keep, VertexId gone) {
  return topology::collapse_edge(mesh, keep, gone);
}

topology::FlipResult Embedding::apply_flip(const topology::FlipPlan& plan) {
  return topology::apply_flip(mesh, plan);
}

void Embedding::undo_flip(const topology::FlipResult& flip) {
  topology::undo_flip(mesh, flip);
}

void Embedding::compact_vertices(std::size_t input_vertices) {
  if (properties.live() != 0)
    throw MapError(MapErrorKind::internal, "compact_vertices: per-vertex properties are still live");
  const std::size_t n = num_vertices();
  std::vector<VertexId> new_id(n, topology::invalid_vertex);
  std::size_t next = 0;
  for (std::size_t v = 0; v < n; ++v)
    if (v < input_vertices || !mesh.tets_of(VertexId(v)).empty()) new_id[v] = VertexId(next++);
  std::vector<topology::Tet> tets;
  for (TetId t : mesh.live_tets()) {
    topology::Tet x = mesh.tet(t);
    for (auto& v : x) v = new_id[v];
    tets.push_back(x);
  }
  auto keep = [&](auto& vec) {
    for (std::size_t v = 0; v < n; ++v)
      if (new_id[v] != topology::invalid_index && new_id[v] != v) vec[new_id[v]] = std::move(vec[v]);
    vec.resize(next);
  };
  if (source_free) keep(origin);
  keep(source);
  keep(target);
  keep(unexpanded);
  keep(boundary);
  mesh = topology::TetMesh(next, tets);
}

Sign Embedding::orient_target(const topology::Tet& t) const {
  return orient3d(target[t[0]], target[t[1]], target[t[2]], target[t[3]], {filter, stats});
}

Sign Embedding::orient_source(const topology::Tet& t) const {
  if (source_free) return Sign::positive;
  return orient3d(source[t[0]], source[t[1]], source[t[2]], source[t[3]], {filter, stats});
}

int Embedding::unexpanded_count(const topology::Tet& t) const {
  return (unexpanded[t[0]] != 0) + (unexpanded[t[1]] != 0) + (unexpanded[t[2]] != 0) +
         (unexpanded[t[3]] != 0);
}

}  // namespace cmx::algorithm
