#pragma once
// TetMesh: a tetrahedral complex with integer handles.
//
// Storage: an array of tets (4 vertex handles each, positive orientation of the source mesh),
// a tombstone flag per tet slot, and per vertex the list of live tets incident to it.
// Edges and faces are not stored: they are found through vertex stars (valence-bounded).
// Removing a tet tombstones its slot (handles of other tets stay valid); compact() renumbers.

#include <cstddef>
#include <span>
#include <vector>

#include "topology/types.hpp"

namespace cmx::topology {

class TetMesh {
 public:
  TetMesh() = default;
  explicit TetMesh(std::size_t num_vertices);
  // Builds from a tet list. Vertices >= num_vertices are a precondition violation: such tets are
  // skipped (and counted by skipped_tets()), never stored. Repeated vertices inside one tet are
  // stored as is (check_ball reports them).
  TetMesh(std::size_t num_vertices, std::span<const Tet> tets);
  // The same from integer vertex indices (a reader's or a caller's tet list).
  TetMesh(std::size_t num_vertices, std::span<const TetIndices> tets);

  [[nodiscard]] std::size_t num_vertices() const { return vertex_tets_.size(); }
  [[nodiscard]] std::size_t num_tets() const { return live_tets_; }       // live tets
  [[nodiscard]] std::size_t tet_capacity() const { return tets_.size(); }  // slots incl. tombstones
  [[nodiscard]] std::size_t skipped_tets() const { return skipped_; }

  [[nodiscard]] bool is_alive(TetId t) const { return t < tets_.size() && alive_[t] != 0; }
  // Precondition: t < tet_capacity(). The vertices of a dead slot are its last ones.
  [[nodiscard]] const Tet& tet(TetId t) const { return tets_[t]; }
  // Live tets incident to v, in no particular order. Precondition: v < num_vertices().
  [[nodiscard]] std::span<const TetId> tets_of(VertexId v) const { return vertex_tets_[v]; }

  VertexId add_vertex();
  // Returns the new handle, or invalid_index when a vertex is out of range (nothing stored).
  TetId add_tet(const Tet& t);
  // Tombstones t and removes it from its vertices' lists. No-op on a dead slot.
  void remove_tet(TetId t);
  // Replaces the vertices of live tet t, keeping its handle; incidences are updated.
  // Returns false (nothing changed) when t is dead or a vertex is out of range.
  bool set_tet(TetId t, const Tet& vertices);

  // Drops tombstones; returns old handle -> new handle (invalid_index for dead slots).
  // Vertex handles are unchanged.
  std::vector<TetId> compact();

  // Live tet handles in increasing order.
  [[nodiscard]] std::vector<TetId> live_tets() const;

 private:
  void link_tet(TetId t);
  void unlink_tet(TetId t);

  std::vector<Tet> tets_;
  std::vector<char> alive_;
  std::vector<std::vector<TetId>> vertex_tets_;
  std::size_t live_tets_ = 0;
  std::size_t skipped_ = 0;
};

// Small helpers on a single tet.
// Local index (0..3) of v in t, or -1. Inline: every adjacency query calls it per tet.
[[nodiscard]] inline int local_index(const Tet& t, VertexId v) {
  for (int i = 0; i < 4; ++i)
    if (t[i] == v) return i;
  return -1;
}
[[nodiscard]] inline bool contains(const Tet& t, VertexId v) { return local_index(t, v) >= 0; }
// Face opposite local vertex i, ordered so that its normal points out of the tet (for a
// positively oriented tet): i=0 -> (1,2,3), 1 -> (0,3,2), 2 -> (0,1,3), 3 -> (0,2,1).
[[nodiscard]] Triangle tet_face(const Tet& t, int i);
// True when the two triangles have the same vertex set and the same cyclic orientation.
[[nodiscard]] bool same_orientation(const Triangle& a, const Triangle& b);

}  // namespace cmx::topology
