#include "topology/shelling_counts.hpp"

#include <algorithm>

#include "topology/shelling_rule.hpp"

namespace cmx::topology {
namespace {

// Edge (k, l), k < l, of a tet as 0..5: (0,1) (0,2) (0,3) (1,2) (1,3) (2,3).
constexpr int pair_index(int k, int l) {
  return k == 0 ? l - 1 : k + l;
}
static_assert(pair_index(0, 1) == 0 && pair_index(0, 3) == 2 && pair_index(1, 2) == 3 &&
              pair_index(2, 3) == 5);

std::uint64_t edge_key(VertexId a, VertexId b) {
  return (std::uint64_t{std::min<std::uint32_t>(a, b)} << 32) | std::max<std::uint32_t>(a, b);
}

}  // namespace

ShellingCounts::ShellingCounts(const TetMesh& m, const TetAdjacency& adj)
    : m_(m), adj_(adj), remaining_(m.tet_capacity(), 0) {
  const std::vector<TetId> live = m.live_tets();
  std::vector<std::uint64_t> keys;
  keys.reserve(6 * live.size());
  for (TetId t : live) {
    const Tet& x = m.tet(t);
    for (int k = 0; k < 4; ++k)
      for (int l = k + 1; l < 4; ++l) keys.push_back(edge_key(x[k], x[l]));
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  vertex_tets_.assign(m.num_vertices(), 0);
  vertex_free_.assign(m.num_vertices(), 0);
  edge_tets_.assign(keys.size(), 0);
  edge_free_.assign(keys.size(), 0);
  auto edge_of = std::make_shared<std::vector<std::array<std::uint32_t, 6>>>(m.tet_capacity());
  for (TetId t : live) {
    const Tet& x = m.tet(t);
    for (int k = 0; k < 4; ++k)
      for (int l = k + 1; l < 4; ++l) {
        const auto e = std::lower_bound(keys.begin(), keys.end(), edge_key(x[k], x[l]));
        (*edge_of)[t][pair_index(k, l)] = static_cast<std::uint32_t>(e - keys.begin());
      }
  }
  edge_of_ = std::move(edge_of);
  for (TetId t : live) remaining_[t] = 1;
  count_ = live.size();
  for (TetId t : live) {
    for (int k = 0; k < 4; ++k) ++vertex_tets_[m_.tet(t)[k]];
    for (std::uint32_t e : (*edge_of_)[t]) ++edge_tets_[e];
    for (int i = 0; i < 4; ++i)
      if (!shared(t, i)) add_face(t, i, 1);
  }
}

bool ShellingCounts::shared(TetId t, int face) const {
  const TetId n = adj_.neighbor[t][face];
  return n != invalid_index && n < remaining_.size() && remaining_[n];
}

// Face `face` of t (every vertex but the face-th) counted as free with `delta`.
void ShellingCounts::add_face(TetId t, int face, int delta) {
  const Tet& x = m_.tet(t);
  for (int k = 0; k < 4; ++k) {
    if (k == face) continue;
    vertex_free_[x[k]] += delta;
    for (int l = k + 1; l < 4; ++l)
      if (l != face) edge_free_[(*edge_of_)[t][pair_index(k, l)]] += delta;
  }
}

// The rule of is_shelling_removable with its star walks replaced by the counts: a vertex or edge
// of t lies on the boundary of the remaining ball iff a free face contains it, and in another
// remaining tet iff more than one remaining tet (t) contains it.
bool ShellingCounts::removable(TetId t) const {
  if (t >= remaining_.size() || !remaining_[t] || !m_.is_alive(t)) return false;
  if (count_ == 1) return true;
  std::array<bool, 4> sh{};
  for (int i = 0; i < 4; ++i) sh[i] = shared(t, i);
  const Tet& x = m_.tet(t);
  return detail::shelling_rule(
      sh,
      [&](int k, int l) {
        return (l < 0 ? vertex_free_[x[k]] : edge_free_[(*edge_of_)[t][pair_index(k, l)]]) > 0;
      },
      [&](int k, int l) {
        return (l < 0 ? vertex_tets_[x[k]] : edge_tets_[(*edge_of_)[t][pair_index(k, l)]]) > 1;
      });
}

// A shared face of t becomes free (its other tet stays); a free one leaves the complex.
void ShellingCounts::remove(TetId t) {
  for (int i = 0; i < 4; ++i) add_face(t, i, shared(t, i) ? 1 : -1);
  for (int k = 0; k < 4; ++k) --vertex_tets_[m_.tet(t)[k]];
  for (std::uint32_t e : (*edge_of_)[t]) --edge_tets_[e];
  remaining_[t] = 0;
  --count_;
}

}  // namespace cmx::topology
