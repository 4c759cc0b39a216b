// The local ball test of a growing star (stars_growth.hpp). A set of tets of a manifold mesh is a
// 3-manifold with boundary when the link of each of its vertices in it is a disc or a sphere.
// That link is a subcomplex of v's link in the mesh (a sphere or a disc), so it is one exactly
// when it is connected, a surface (the star's tets around each edge vx form one fan) and has
// Euler characteristic 1 or 2 (a connected planar surface with h boundary circles has 2 - h).
// A connected 3-manifold in R^3 whose boundary is one 2-sphere is a ball (Alexander).
#include <algorithm>

#include "algorithm/local/stars_growth.hpp"
#include "topology/union_find.hpp"

namespace cmx::algorithm::stars {

namespace {

template <class Index>
std::uint32_t index_in(const std::vector<Index>& sorted, Index x) {
  return std::uint32_t(std::lower_bound(sorted.begin(), sorted.end(), x) - sorted.begin());
}

}  // namespace

std::optional<topology::Edge> GrowingStar::pinch_at(VertexId v) const {
  std::vector<TetId> around;
  for (TetId t : mesh_.tets_of(v))
    if (contains(t)) around.push_back(t);
  if (around.empty()) return std::nullopt;
  std::sort(around.begin(), around.end());
  std::vector<VertexId> link;  // the link's vertices: the other vertices of the tets around v
  for (TetId t : around)
    for (VertexId x : mesh_.tet(t))
      if (x != v) link.push_back(x);
  std::sort(link.begin(), link.end());
  link.erase(std::unique(link.begin(), link.end()), link.end());
  // Per link vertex x: the star's tets around edge vx, and the faces with vx that two of them share.
  std::vector<std::uint32_t> fan_tets(link.size(), 0), fan_shared(link.size(), 0);
  topology::UnionFind triangles(around.size());
  std::size_t pieces = around.size();  // of the link triangles, joined across shared edges
  std::size_t shared = 0;  // link edges in two link triangles
  for (std::uint32_t k = 0; k < around.size(); ++k) {
    const topology::Tet& tet = mesh_.tet(around[k]);
    for (std::uint8_t i = 0; i < 4; ++i) {
      if (tet[i] == v) continue;
      ++fan_tets[index_in(link, tet[i])];
      const TetId nb = adjacency_.neighbor[around[k]][i];  // across the face opposite tet[i], which has v
      if (nb == topology::invalid_index || !contains(nb) || nb < around[k]) continue;
      ++shared;
      if (triangles.unite(k, index_in(around, nb))) --pieces;
      for (std::uint8_t j = 0; j < 4; ++j)
        if (j != i && tet[j] != v) ++fan_shared[index_in(link, tet[j])];
    }
  }
  for (std::size_t x = 0; x < link.size(); ++x)
    if (fan_tets[x] > fan_shared[x] + 1) return topology::Edge{v, link[x]};  // two runs or more
  const std::int64_t chi = std::int64_t(link.size()) - std::int64_t(3 * around.size() - shared) + std::int64_t(around.size());
  if (pieces != 1 || (chi != 1 && chi != 2)) return topology::Edge{v, v};
  return std::nullopt;
}

bool GrowingStar::boundary_is_sphere() const {
  if (boundary_.size() % 2 != 0) return false;
  std::vector<VertexId> corners;
  for (const FaceRef& f : boundary_)
    for (VertexId x : triangle(f)) corners.push_back(x);
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  // A closed surface has 3F/2 edges: chi = V - F/2.
  if (std::int64_t(corners.size()) - std::int64_t(boundary_.size() / 2) != 2) return false;
  topology::UnionFind uf(corners.size());
  std::size_t pieces = corners.size();
  for (const FaceRef& f : boundary_) {
    const topology::Triangle t = triangle(f);
    if (uf.unite(index_in(corners, t[0]), index_in(corners, t[1]))) --pieces;
    if (uf.unite(index_in(corners, t[0]), index_in(corners, t[2]))) --pieces;
  }
  return pieces == 1;
}

}  // namespace cmx::algorithm::stars
