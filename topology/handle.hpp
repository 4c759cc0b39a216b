#pragma once
// Typed handles (OpenVolumeMesh's idea): an index that knows what it indexes.
// A handle is made from an integer only explicitly (`TetHandle{i}`), reads as its index wherever
// an index is expected (`tets[t]`, `t < n`, printing), and a handle of one kind never converts to
// another: passing a vertex's handle where a tet's is expected does not compile.

#include <cstdint>
#include <functional>

namespace cmx::topology {

template <class Tag>
class Handle {
 public:
  constexpr Handle() = default;
  constexpr explicit Handle(std::uint32_t index) : index_(index) {}
  template <class OtherTag>
  Handle(Handle<OtherTag>) = delete;  // the point of the type

  // Implicit on purpose: a handle indexes the mesh's arrays and the stages' vectors.
  constexpr operator std::uint32_t() const { return index_; }  // NOLINT(google-explicit-constructor)
  [[nodiscard]] constexpr std::uint32_t idx() const { return index_; }

  constexpr Handle& operator++() {
    ++index_;
    return *this;
  }

 private:
  std::uint32_t index_ = 0;
};

struct VertexTag {};
struct TetTag {};
using VertexHandle = Handle<VertexTag>;
using TetHandle = Handle<TetTag>;

// Literals for hand-built meshes (tests, examples): `vertex_link(m, 0_v)`, `m.tet(2_tet)`.
namespace literals {
constexpr VertexHandle operator""_v(unsigned long long index) {
  return VertexHandle{static_cast<std::uint32_t>(index)};
}
constexpr TetHandle operator""_tet(unsigned long long index) {
  return TetHandle{static_cast<std::uint32_t>(index)};
}
}  // namespace literals

}  // namespace cmx::topology

template <class Tag>
struct std::hash<cmx::topology::Handle<Tag>> {
  std::size_t operator()(cmx::topology::Handle<Tag> h) const noexcept {
    return std::hash<std::uint32_t>{}(h.idx());
  }
};
