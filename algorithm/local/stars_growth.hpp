#pragma once
// One star while it grows (algorithm/local/stars.hpp): its tets, how many of them touch each
// vertex, and its boundary faces with their float inner rows, all kept up to date per added tet
// in O(valence), so that the shelling test and the kernel test never rescan the star.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "topology/complex_queries.hpp"
#include "topology/tet_mesh.hpp"

namespace cmx::algorithm::stars {

using topology::TetId;
using topology::VertexId;

inline constexpr std::int32_t no_star = -1;

// A face of a tet of the star, by the tet and the local index of the vertex opposite it.
struct FaceRef {
  TetId tet;
  std::uint8_t face;
};

class GrowingStar {
 public:
  // `owner[t]` is the star holding tet t (no_star: none); shared by all stars of one growth.
  // `approx`: the nearest doubles of the target positions.
  GrowingStar(const topology::TetMesh& mesh, const topology::TetAdjacency& adjacency,
              const std::vector<std::array<double, 3>>& approx, std::vector<std::int32_t>& owner);

  // Starts an empty star with this id (the previous one must have been released).
  void start(std::int32_t id);
  // Adds tet t (owned by no star, or by this one: then nothing happens). Keeps the boundary.
  void add(TetId t);
  // Empties the star, leaving its tets to whoever owns them now; returns its tets.
  std::vector<TetId> release();

  [[nodiscard]] std::int32_t id() const { return id_; }
  [[nodiscard]] bool contains(TetId t) const { return owner_[t] == id_; }
  [[nodiscard]] bool touches(VertexId v) const { return vertex_tets_[v] != 0; }
  [[nodiscard]] std::size_t vertex_tets(VertexId v) const { return vertex_tets_[v]; }
  [[nodiscard]] const std::vector<TetId>& tets() const { return tets_; }
  [[nodiscard]] const std::vector<FaceRef>& boundary() const { return boundary_; }
  // The inner side of each boundary face (same order) from the nearest doubles: a x + b y + c z <= d.
  [[nodiscard]] const std::vector<std::array<double, 4>>& rows() const { return rows_; }
  // The tet across a boundary face (topology::invalid_index on the domain boundary).
  [[nodiscard]] TetId behind(const FaceRef& f) const { return adjacency_.neighbor[f.tet][f.face]; }
  // The face's outward triangle (the star's tet on its negative side).
  [[nodiscard]] topology::Triangle triangle(const FaceRef& f) const;

  // True when t, outside the star and sharing a face with it, meets it in a disc of one to three
  // of its faces and nothing else: then the star with t is a ball again whenever it was one.
  [[nodiscard]] bool extends_ball(TetId t) const;
  // True when some tet of the star has both a and b.
  [[nodiscard]] bool has_edge(VertexId a, VertexId b) const;

  // Local manifold test (stars_manifold.cpp): what keeps the star from being a 3-manifold at v,
  // from v's tets alone: an edge {v, x} whose tets in the star are not one fan, or {v, v} when
  // v's link in the star is not connected or not a disc or a sphere; nullopt when it is a
  // manifold there (or v is not in the star).
  [[nodiscard]] std::optional<topology::Edge> pinch_at(VertexId v) const;
  // True when the boundary faces form one 2-sphere. Meaningful when the star is a 3-manifold (its
  // boundary then is a closed surface).
  [[nodiscard]] bool boundary_is_sphere() const;

 private:
  void add_face(TetId t, std::uint8_t i);
  void remove_face(TetId t, std::uint8_t i);

  const topology::TetMesh& mesh_;
  const topology::TetAdjacency& adjacency_;
  const std::vector<std::array<double, 3>>& approx_;
  std::vector<std::int32_t>& owner_;
  std::int32_t id_ = no_star;
  std::vector<TetId> tets_;
  std::vector<std::uint32_t> vertex_tets_;   // per vertex: tets of this star around it
  std::vector<FaceRef> boundary_;
  std::vector<std::array<double, 4>> rows_;
  std::vector<std::uint32_t> face_slot_;     // per tet face (4 t + i): index in boundary_, or none
};

}  // namespace cmx::algorithm::stars
