#include "io/second_order.hpp"

namespace cmx::io {
namespace {

template <class T>
void keep_marked(std::vector<T>& values, const std::vector<bool>& keep) {
  std::size_t out = 0;
  for (std::size_t i = 0; i < values.size() && i < keep.size(); ++i)
    if (keep[i]) values[out++] = std::move(values[i]);
  values.resize(out);
}

}  // namespace

void HigherOrderNodes::drop_unused(TetMeshData& mesh) const {
  if (nodes_.empty()) return;
  const std::size_t n = mesh.positions.size();
  std::vector<bool> corner(n, false), keep(n, true);
  for (const auto& t : mesh.tets)
    for (auto v : t) corner[v] = true;
  for (auto v : nodes_)
    if (v < n && !corner[v]) keep[v] = false;
  std::vector<std::uint32_t> renumbered(n, 0);
  std::uint32_t next = 0;
  for (std::size_t v = 0; v < n; ++v)
    if (keep[v]) renumbered[v] = next++;
  mesh.dropped_higher_order_nodes = n - next;
  for (auto& t : mesh.tets)
    for (auto& v : t) v = renumbered[v];
  keep_marked(mesh.positions, keep);
  for (auto& property : mesh.vertex_string_properties) keep_marked(property.values, keep);
}

}  // namespace cmx::io
