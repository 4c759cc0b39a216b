#include "topology/consistency.hpp"

#include <algorithm>

namespace cmx::topology {

ConsistencyVerdict check_incidences(const TetMesh& m) {
  ConsistencyVerdict v;
  auto bad = [&](std::string msg) {
    v.ok = false;
    v.message = std::move(msg);
    return v;
  };
  std::size_t live = 0;
  std::size_t expected_entries = 0;
  for (std::size_t t = 0; t < m.tet_capacity(); ++t) {
    const auto id = static_cast<TetId>(t);
    if (!m.is_alive(id)) continue;
    ++live;
    const Tet& x = m.tet(id);
    for (int i = 0; i < 4; ++i) {
      if (x[i] >= m.num_vertices()) return bad("tet " + std::to_string(t) + " has vertex out of range");
      bool repeated = false;
      for (int j = 0; j < i; ++j) repeated = repeated || x[j] == x[i];
      if (repeated) continue;
      ++expected_entries;
      const auto list = m.tets_of(x[i]);
      const auto n = std::count(list.begin(), list.end(), id);
      if (n != 1)
        return bad("tet " + std::to_string(t) + " appears " + std::to_string(n) + " times in the list of vertex " +
                   std::to_string(x[i]));
    }
  }
  if (live != m.num_tets()) return bad("live tet count mismatch");
  std::size_t entries = 0;
  for (VertexId a{0}; a < m.num_vertices(); ++a) {
    for (TetId t : m.tets_of(a)) {
      ++entries;
      if (!m.is_alive(t)) return bad("vertex " + std::to_string(a) + " lists dead tet " + std::to_string(t));
      if (!contains(m.tet(t), a))
        return bad("vertex " + std::to_string(a) + " lists tet " + std::to_string(t) + " which does not contain it");
    }
  }
  if (entries != expected_entries) return bad("incidence list sizes do not match the tets");
  return v;
}

}  // namespace cmx::topology
