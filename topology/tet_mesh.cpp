#include "topology/tet_mesh.hpp"

#include <algorithm>

namespace cmx::topology {

TetMesh::TetMesh(std::size_t num_vertices) : vertex_tets_(num_vertices) {}

TetMesh::TetMesh(std::size_t num_vertices, std::span<const TetIndices> tets)
    : TetMesh(num_vertices, make_tets(tets)) {}

TetMesh::TetMesh(std::size_t num_vertices, std::span<const Tet> tets) : vertex_tets_(num_vertices) {
  tets_.reserve(tets.size());
  alive_.reserve(tets.size());
  // Pre-size incidence lists to avoid repeated growth on large inputs.
  std::vector<std::uint32_t> count(num_vertices, 0);
  for (const Tet& t : tets)
    for (VertexId v : t)
      if (v < num_vertices) ++count[v];
  for (std::size_t v = 0; v < num_vertices; ++v) vertex_tets_[v].reserve(count[v]);
  for (const Tet& t : tets) add_tet(t);
}

VertexId TetMesh::add_vertex() {
  vertex_tets_.emplace_back();
  return static_cast<VertexId>(vertex_tets_.size() - 1);
}

TetId TetMesh::add_tet(const Tet& t) {
  for (VertexId v : t) {
    if (v >= vertex_tets_.size()) {
      ++skipped_;
      return invalid_tet;
    }
  }
  const auto id = static_cast<TetId>(tets_.size());
  tets_.push_back(t);
  alive_.push_back(1);
  ++live_tets_;
  link_tet(id);
  return id;
}

void TetMesh::link_tet(TetId id) {
  const Tet& t = tets_[id];
  for (int i = 0; i < 4; ++i) {
    // A degenerate tet with a repeated vertex is listed once per distinct vertex.
    bool seen = false;
    for (int j = 0; j < i; ++j) seen = seen || t[j] == t[i];
    if (!seen) vertex_tets_[t[i]].push_back(id);
  }
}

void TetMesh::unlink_tet(TetId id) {
  const Tet& t = tets_[id];
  for (int i = 0; i < 4; ++i) {
    bool seen = false;
    for (int j = 0; j < i; ++j) seen = seen || t[j] == t[i];
    if (seen) continue;
    auto& list = vertex_tets_[t[i]];
    auto it = std::find(list.begin(), list.end(), id);
    if (it != list.end()) {
      *it = list.back();
      list.pop_back();
    }
  }
}

void TetMesh::remove_tet(TetId t) {
  if (!is_alive(t)) return;
  unlink_tet(t);
  alive_[t] = 0;
  --live_tets_;
}

bool TetMesh::set_tet(TetId t, const Tet& vertices) {
  if (!is_alive(t)) return false;
  for (VertexId v : vertices)
    if (v >= vertex_tets_.size()) return false;
  unlink_tet(t);
  tets_[t] = vertices;
  link_tet(t);
  return true;
}

std::vector<TetId> TetMesh::compact() {
  std::vector<TetId> remap(tets_.size(), invalid_tet);
  std::size_t next = 0;
  for (std::size_t t = 0; t < tets_.size(); ++t) {
    if (!alive_[t]) continue;
    remap[t] = static_cast<TetId>(next);
    tets_[next] = tets_[t];
    ++next;
  }
  tets_.resize(next);
  alive_.assign(next, 1);
  for (auto& list : vertex_tets_) {
    for (TetId& t : list) t = remap[t];
  }
  return remap;
}

std::vector<TetId> TetMesh::live_tets() const {
  std::vector<TetId> out;
  out.reserve(live_tets_);
  for (std::size_t t = 0; t < tets_.size(); ++t)
    if (alive_[t]) out.push_back(static_cast<TetId>(t));
  return out;
}

Triangle tet_face(const Tet& t, int i) {
  switch (i) {
    case 0: return {t[1], t[2], t[3]};
    case 1: return {t[0], t[3], t[2]};
    case 2: return {t[0], t[1], t[3]};
    default: return {t[0], t[2], t[1]};
  }
}

bool same_orientation(const Triangle& a, const Triangle& b) {
  for (int r = 0; r < 3; ++r) {
    if (b[r] == a[0]) return b[(r + 1) % 3] == a[1] && b[(r + 2) % 3] == a[2];
  }
  return false;
}

}  // namespace cmx::topology
