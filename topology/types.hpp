#pragma once
// Handles and small value types shared by the whole topology layer.
// Combinatorics only: no coordinates anywhere in topology/.

#include <array>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <span>
#include <vector>

#include "topology/handle.hpp"

namespace cmx::topology {

// Typed handles (topology/handle.hpp): a vertex id and a tet id are distinct types.
using VertexId = VertexHandle;
using TetId = TetHandle;

// Returned where a handle is absent (no such tet, edit refused, ...).
inline constexpr std::uint32_t invalid_index = std::numeric_limits<std::uint32_t>::max();
inline constexpr VertexHandle invalid_vertex{invalid_index};
inline constexpr TetHandle invalid_tet{invalid_index};

// A tet lists its vertices in the positive orientation of the source mesh:
// with positions p, det[p1-p0, p2-p0, p3-p0] > 0.
using Tet = std::array<VertexId, 4>;
using Triangle = std::array<VertexId, 3>;
using Edge = std::array<VertexId, 2>;

// Readers, generators and tests number vertices with integers; these make the handles.
using TetIndices = std::array<std::uint32_t, 4>;
constexpr Tet make_tet(const TetIndices& x) {
  return {VertexId{x[0]}, VertexId{x[1]}, VertexId{x[2]}, VertexId{x[3]}};
}
inline std::vector<Tet> make_tets(std::span<const TetIndices> list) {
  std::vector<Tet> tets;
  tets.reserve(list.size());
  for (const TetIndices& x : list) tets.push_back(make_tet(x));
  return tets;
}
inline std::vector<Tet> make_tets(std::initializer_list<TetIndices> list) {
  return make_tets(std::span<const TetIndices>(list.begin(), list.size()));
}
// The integers of handles, for callers outside the layers (the public API, file writers).
template <class Tag>
std::vector<std::uint32_t> indices_of(const std::vector<Handle<Tag>>& handles) {
  return {handles.begin(), handles.end()};
}
template <class Tag, std::size_t N>
std::array<std::uint32_t, N> indices_of(const std::array<Handle<Tag>, N>& handles) {
  std::array<std::uint32_t, N> out{};
  for (std::size_t i = 0; i < N; ++i) out[i] = handles[i];
  return out;
}

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
