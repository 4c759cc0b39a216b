#pragma once
// The removability rule of topology/shelling.hpp, kept up to date as tets are removed instead of
// recomputed from the stars each time: per vertex and per edge of the mesh, how many remaining
// tets contain it and how many free faces (faces of the remaining complex in one remaining tet)
// contain it. A greedy shelling asks the rule about every tet around each removed one, and the
// recomputation walked the stars of the tet's four vertices for each of its ten simplices: on
// Furch's knotted hole at scale 3 (1.6M tets) that was 12 s per attempt.
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "topology/complex_queries.hpp"
#include "topology/tet_mesh.hpp"

namespace cmx::topology {

class ShellingCounts {
 public:
  // Every live tet of `m` remaining. `adj` = tet_adjacency(m); both must outlive this object and
  // stay unchanged. O(T log T) (the edges are numbered by sorting). A copy shares the numbering
  // (read only) and has counts of its own, so that copies can run attempts on threads.
  ShellingCounts(const TetMesh& m, const TetAdjacency& adj);

  // The same answer as is_shelling_removable(m, adj, t, remaining(), remaining_count()), O(1).
  [[nodiscard]] bool removable(TetId t) const;
  // Precondition: remaining(t). O(1).
  void remove(TetId t);

  [[nodiscard]] bool remaining(TetId t) const { return remaining_[t] != 0; }
  [[nodiscard]] std::size_t remaining_count() const { return count_; }

 private:
  [[nodiscard]] bool shared(TetId t, int face) const;
  void add_face(TetId t, int face, int delta);

  const TetMesh& m_;
  const TetAdjacency& adj_;
  // Per tet slot, its edges in pair_index order.
  std::shared_ptr<const std::vector<std::array<std::uint32_t, 6>>> edge_of_;
  std::vector<char> remaining_;
  std::size_t count_ = 0;
  std::vector<std::int32_t> vertex_tets_, vertex_free_, edge_tets_, edge_free_;
};

}  // namespace cmx::topology
