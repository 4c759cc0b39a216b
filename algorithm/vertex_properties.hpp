#pragma once
// Per-vertex properties that grow with the mesh (the idea of OpenVolumeMesh's ResourceManager):
// a property made by VertexProperties::make is resized by VertexProperties::grow, which the owner
// of the mesh calls whenever it adds a vertex (Embedding::split_edge, split_face), so a user of
// the mesh never resizes its own per-vertex arrays and never reads past them.
//
// Ownership: the property holds its values; the registry only knows which properties are still
// alive. A copy of a registry starts empty (the copied mesh has no properties of its own: those
// of the original stay with the original), a moved registry takes its properties along, and a
// property that is destroyed simply drops out.
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include "topology/types.hpp"

namespace cmx::algorithm {

namespace property_detail {

struct Storage {
  virtual ~Storage() = default;
  virtual void resize(std::size_t n) = 0;
};

template <class T>
struct TypedStorage final : Storage {
  TypedStorage(std::size_t n, T fill_value) : values(n, fill_value), fill(std::move(fill_value)) {}
  void resize(std::size_t n) override { values.resize(n, fill); }
  std::vector<T> values;
  T fill;
};

}  // namespace property_detail

// One value of type T per vertex; new vertices get the property's fill value.
template <class T>
class VertexProperty {
 public:
  VertexProperty(const VertexProperty&) = delete;  // two owners of one property would surprise
  VertexProperty& operator=(const VertexProperty&) = delete;
  VertexProperty(VertexProperty&&) noexcept = default;
  VertexProperty& operator=(VertexProperty&&) noexcept = default;

  // Precondition: v < size() (every vertex of the mesh the property was made for).
  T& operator[](topology::VertexId v) { return storage_->values[v]; }
  const T& operator[](topology::VertexId v) const { return storage_->values[v]; }
  [[nodiscard]] std::size_t size() const { return storage_->values.size(); }

 private:
  friend class VertexProperties;
  explicit VertexProperty(std::shared_ptr<property_detail::TypedStorage<T>> s) : storage_(std::move(s)) {}
  std::shared_ptr<property_detail::TypedStorage<T>> storage_;
};

class VertexProperties {
 public:
  VertexProperties() = default;
  VertexProperties(const VertexProperties&) {}
  VertexProperties& operator=(const VertexProperties&) { return *this; }  // keeps its own properties
  VertexProperties(VertexProperties&&) noexcept = default;
  VertexProperties& operator=(VertexProperties&&) noexcept = default;

  // A property of `vertices` values `fill`, grown from now on with the mesh.
  template <class T>
  VertexProperty<T> make(std::size_t vertices, T fill = T{}) {
    auto s = std::make_shared<property_detail::TypedStorage<T>>(vertices, std::move(fill));
    live_.push_back(s);
    return VertexProperty<T>(std::move(s));
  }

  // Every live property to `vertices` values (the mesh's new vertex count); forgets dead ones.
  void grow(std::size_t vertices) {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < live_.size(); ++i)
      if (const std::shared_ptr<property_detail::Storage> s = live_[i].lock()) {
        s->resize(vertices);
        if (kept != i) live_[kept] = std::move(live_[i]);
        ++kept;
      }
    live_.resize(kept);
  }

  [[nodiscard]] std::size_t live() const {
    std::size_t n = 0;
    for (const auto& weak : live_) n += weak.expired() ? 0 : 1;
    return n;
  }

 private:
  std::vector<std::weak_ptr<property_detail::Storage>> live_;
};

}  // namespace cmx::algorithm
