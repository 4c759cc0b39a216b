#pragma once
// Second-order (10-node) tetrahedra — TetGen `.ele` with 10 nodes per tet, VTK type 24, Gmsh type
// 11, Medit TetrahedraP2 — are read as linear tets: their first four nodes are the corners (every
// one of these formats lists corners first, in the orientation of its linear tet) and the six
// mid-edge nodes are dropped. A node is dropped when it is a mid-edge node of some tet and a corner
// of none; the other vertices keep their file order and are renumbered consecutively, so every
// vertex that remains is the corner of a tet or was unreferenced in the file (as in a linear file).
// TetMeshData::dropped_higher_order_nodes counts what was dropped (boundary files written for the
// file's numbering do not apply to the renumbered mesh).
#include <cstdint>
#include <vector>

#include "io/tet_mesh_data.hpp"

namespace cmx::io {

class HigherOrderNodes {
 public:
  // Records `node` (an index into the mesh's positions) as a mid-edge node of a tet.
  void add(std::uint32_t node) { nodes_.push_back(node); }
  // True when every recorded node is < n (for readers that check indices after the fact).
  bool all_below(std::size_t n) const {
    for (auto v : nodes_)
      if (v >= n) return false;
    return true;
  }
  // Removes the recorded nodes that no tet of `mesh` uses as a corner and renumbers the rest
  // (positions, tets and vertex string properties). Call before validate_and_orient.
  void drop_unused(TetMeshData& mesh) const;

 private:
  std::vector<std::uint32_t> nodes_;
};

}  // namespace cmx::io
