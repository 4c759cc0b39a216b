#pragma once
// The growth rule of algorithm/local/stars.hpp (docs/algorithm/local.md, "Stars of a local repair"):
// stars grown one after another from the non-positive tets in handle order, each until it is a
// ball with a star-shaped boundary, absorbing whatever finished star it grows into.
#include <array>
#include <cstdint>
#include <set>
#include <vector>

#include "algorithm/local/stars.hpp"
#include "algorithm/local/stars_growth.hpp"

namespace cmx::algorithm::stars {

class StarGrowth {
 public:
  // `out.states` must hold the classification; growth counts go to `out`.
  StarGrowth(const topology::TetMesh& mesh, const std::vector<HPoint>& target, const std::vector<char>& boundary_vertex,
             const StarOptions& options, StarSet& out);

  // Grows the star of `seed` (a non-positive tet of no star) until (a) to (c) hold, and, with
  // free_defects, until each of its non-positive tets has an interior vertex; false when growth
  // must stop (out.message says why).
  bool grow_from(TetId seed);

  [[nodiscard]] bool owned(TetId t) const { return owner_[t] != no_star; }
  [[nodiscard]] std::int32_t owner(TetId t) const { return owner_[t]; }
  // By star id; a star absorbed by another is empty.
  [[nodiscard]] const std::vector<std::vector<TetId>>& finished() const { return finished_; }
  [[nodiscard]] const topology::TetAdjacency& adjacency() const { return adjacency_; }
  // Tets in stars now, the growing one included.
  [[nodiscard]] std::size_t held() const { return in_finished_ + star_.tets().size(); }

 private:
  void add(TetId t);
  void absorb(std::int32_t other);
  void finish();
  bool may_go_on();
  bool grow_step(const std::vector<TetId>& candidates, bool one);
  bool repair(TetId t);
  std::vector<TetId> pinch_fixes(const std::set<VertexId>& dirty) const;
  std::vector<TetId> outer_layer() const;
  std::vector<TetId> tets_freeing_a_defect() const;
  VertexId vertex_to_free(TetId defect) const;

  const topology::TetMesh& mesh_;
  const std::vector<HPoint>& target_;
  std::vector<char> fixed_;                    // flagged boundary vertices and those on the mesh boundary
  const StarOptions& options_;
  StarSet& out_;
  topology::TetAdjacency adjacency_;
  std::vector<std::array<double, 3>> approx_;  // the target's nearest doubles, for float rows
  std::vector<std::int32_t> owner_;
  GrowingStar star_;
  std::vector<std::vector<TetId>> finished_;
  std::size_t in_finished_ = 0;
  std::set<TetId> pending_;                    // non-positive tets of no star next to the growing star
  std::vector<TetId> defects_;                 // the growing star's non-positive tets
};

}  // namespace cmx::algorithm::stars
