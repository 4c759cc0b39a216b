#include "algorithm/local/stars_growth.hpp"

#include <bit>
#include <utility>

#include "algorithm/expansion/expansion_cone.hpp"

namespace cmx::algorithm::stars {

namespace {
constexpr std::uint32_t no_slot = topology::invalid_index;
}  // namespace

GrowingStar::GrowingStar(const topology::TetMesh& mesh, const topology::TetAdjacency& adjacency,
                         const std::vector<std::array<double, 3>>& approx, std::vector<std::int32_t>& owner)
    : mesh_(mesh),
      adjacency_(adjacency),
      approx_(approx),
      owner_(owner),
      vertex_tets_(mesh.num_vertices(), 0),
      face_slot_(4 * mesh.tet_capacity(), no_slot) {}

void GrowingStar::start(std::int32_t id) { id_ = id; }

topology::Triangle GrowingStar::triangle(const FaceRef& f) const { return topology::tet_face(mesh_.tet(f.tet), f.face); }

void GrowingStar::add_face(TetId t, std::uint8_t i) {
  face_slot_[4 * std::size_t(t) + i] = std::uint32_t(boundary_.size());
  boundary_.push_back({t, i});
  const topology::Triangle tri = triangle({t, i});
  rows_.push_back(float_inner_row(approx_[tri[0]], approx_[tri[1]], approx_[tri[2]]));
}

void GrowingStar::remove_face(TetId t, std::uint8_t i) {
  // Swap with the last face: the order stays a function of the sequence of additions.
  const std::uint32_t slot = face_slot_[4 * std::size_t(t) + i];
  const FaceRef last = boundary_.back();
  boundary_[slot] = last;
  rows_[slot] = rows_.back();
  face_slot_[4 * std::size_t(last.tet) + last.face] = slot;
  boundary_.pop_back();
  rows_.pop_back();
  face_slot_[4 * std::size_t(t) + i] = no_slot;
}

void GrowingStar::add(TetId t) {
  if (owner_[t] == id_) return;
  owner_[t] = id_;
  tets_.push_back(t);
  const topology::Tet& tet = mesh_.tet(t);
  for (VertexId v : tet) ++vertex_tets_[v];
  for (std::uint8_t i = 0; i < 4; ++i) {
    const TetId nb = adjacency_.neighbor[t][i];
    if (nb != topology::invalid_index && owner_[nb] == id_) {
      for (std::uint8_t j = 0; j < 4; ++j)
        if (adjacency_.neighbor[nb][j] == t) remove_face(nb, j);
    } else {
      add_face(t, i);
    }
  }
}

std::vector<TetId> GrowingStar::release() {
  for (TetId t : tets_)
    for (VertexId v : mesh_.tet(t)) vertex_tets_[v] = 0;
  for (const FaceRef& f : boundary_) face_slot_[4 * std::size_t(f.tet) + f.face] = no_slot;
  boundary_.clear();
  rows_.clear();
  id_ = no_star;
  return std::exchange(tets_, {});
}

bool GrowingStar::has_edge(VertexId a, VertexId b) const {
  if (!touches(a) || !touches(b)) return false;
  for (TetId t : mesh_.tets_of(a))
    if (owner_[t] == id_ && topology::contains(mesh_.tet(t), b)) return true;
  return false;
}

bool GrowingStar::extends_ball(TetId t) const {
  if (owner_[t] == id_) return false;
  unsigned shared = 0;
  for (unsigned i = 0; i < 4; ++i) {
    const TetId nb = adjacency_.neighbor[t][i];
    if (nb != topology::invalid_index && owner_[nb] == id_) shared |= 1u << i;
  }
  const topology::Tet& tet = mesh_.tet(t);
  switch (std::popcount(shared)) {
    case 1:  // one face: the vertex opposite it must be new
      return !touches(tet[std::size_t(std::countr_zero(shared))]);
    case 2: {  // two faces: the edge that neither contains must be new
      const int i = std::countr_zero(shared), j = std::countr_zero(shared & (shared - 1));
      return !has_edge(tet[std::size_t(i)], tet[std::size_t(j)]);
    }
    case 3:  // three faces form a disc with every edge and vertex of t
      return true;
    default:  // not adjacent; four faces would close a sphere, which a ball in R^3 cannot
      return false;
  }
}

}  // namespace cmx::algorithm::stars
