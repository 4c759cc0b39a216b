#pragma once
// Handles and small value types shared by the whole topology layer.
// Combinatorics only: no coordinates anywhere in topology/.

#include <array>
#include <cstdint>
#include <limits>
#include <span>

#include "topology/handle.hpp"

namespace cmx::topology {

// A tet's handle is typed (topology/handle.hpp); vertex ids are still plain integers.
using VertexId = std::uint32_t;
using TetId = TetHandle;

// Returned where a handle is absent (no such tet, edit refused, ...).
inline constexpr std::uint32_t invalid_index = std::numeric_limits<std::uint32_t>::max();
inline constexpr TetHandle invalid_tet{invalid_index};

// A tet lists its vertices in the positive orientation of the source mesh:
// with positions p, det[p1-p0, p2-p0, p3-p0] > 0.
using Tet = std::array<VertexId, 4>;
using Triangle = std::array<VertexId, 3>;
using Edge = std::array<VertexId, 2>;

// A vertex subset view: a flag per vertex, nothing copied. `flags[v] != 0` means v is in the
// subset (e.g. "unexpanded"); `complement` flips membership. An empty view (default) contains
// every vertex. Vertices beyond flags.size() count as unflagged.
class VertexSubset {
 public:
  VertexSubset() = default;
  explicit VertexSubset(std::span<const char> flags, bool complement = false)
      : flags_(flags), complement_(complement), all_(false) {}

  [[nodiscard]] bool contains(VertexId v) const {
    if (all_) return true;
    const bool flagged = v < flags_.size() && flags_[v] != 0;
    return flagged != complement_;
  }
  [[nodiscard]] VertexSubset complemented() const {
    VertexSubset s = *this;
    if (all_) return s;  // the complement of "everything" is not needed anywhere
    s.complement_ = !complement_;
    return s;
  }

 private:
  std::span<const char> flags_{};
  bool complement_ = false;
  bool all_ = true;
};

}  // namespace cmx::topology
