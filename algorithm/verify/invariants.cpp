#include "algorithm/verify/invariants.hpp"

#include "algorithm/describe.hpp"
#include "topology/cluster_links.hpp"

namespace cmx::algorithm {

namespace {

std::string tet_text(const topology::Tet& t) { return "tet " + ids_text(t); }

std::string check_tet(const Embedding& e, const topology::Tet& t) {
  const std::optional<InvalidTet> bad = invalid_tet(e, t);
  if (!bad) return {};
  if (bad->in_source) return tet_text(t) + " is not positive in the source";
  return tet_text(t) + " has at most one cluster vertex but is not positive in the target";
}

}  // namespace

std::optional<InvalidTet> invalid_tet(const Embedding& e, const topology::Tet& t, bool source_only) {
  if (!source_only && e.unexpanded_count(t) <= 1)
    if (const Sign s = e.orient_target(t); s != Sign::positive) return InvalidTet{t, false, s};
  if (const Sign s = e.orient_source(t); s != Sign::positive) return InvalidTet{t, true, s};
  return std::nullopt;
}

std::optional<InvalidTet> first_invalid_tet_around(const Embedding& e, VertexId v, bool source_only) {
  for (TetId t : e.mesh.tets_of(v))
    if (auto bad = invalid_tet(e, e.mesh.tet(t), source_only)) return bad;
  return std::nullopt;
}

std::string check_invariants(const Embedding& e, const std::vector<HPoint>& prescribed) {
  std::size_t cluster = 0;
  for (VertexId v{0}; v < e.num_vertices(); ++v) {
    if (e.unexpanded[v]) {
      ++cluster;
      if (!(e.target[v] == e.center)) return "cluster vertex " + std::to_string(v) + " is not at p_c";
    }
    if (e.boundary[v] && !(e.target[v] == prescribed[v]))
      return "boundary vertex " + std::to_string(v) + " left its prescribed position";
  }
  for (TetId t : e.mesh.live_tets())
    if (std::string why = check_tet(e, e.mesh.tet(t)); !why.empty()) return why;
  if (cluster > 0) {
    const auto c = topology::cluster_mesh_counts(e.mesh, e.unexpanded);
    if (c.components != 1 || c.euler != 1)
      return "the cluster mesh is not simply connected (b0 = " + std::to_string(c.components) +
             ", chi = " + std::to_string(c.euler) + ")";
  }
  return {};
}

PrecisionLoss precision_loss_at(const Embedding& e, VertexId v, const InvalidTet& bad, std::string phase,
                                std::string what) {
  PrecisionLoss loss;
  loss.phase = std::move(phase);
  loss.vertex = v;
  loss.what = std::move(what);
  loss.tet = bad.tet;
  loss.in_source = bad.in_source;
  loss.orientation = bad.orientation;
  const std::vector<HPoint>& at = bad.in_source ? e.source : e.target;
  for (int i = 0; i < 4; ++i) loss.corners[std::size_t(i)] = at[bad.tet[std::size_t(i)]];
  return loss;
}

std::string check_local_invariant(const Embedding& e, VertexId v) {
  for (TetId t : e.mesh.tets_of(v))
    if (std::string why = check_tet(e, e.mesh.tet(t)); !why.empty()) return why;
  return {};
}

}  // namespace cmx::algorithm
