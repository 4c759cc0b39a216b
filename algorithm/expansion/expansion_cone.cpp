#include "algorithm/expansion/expansion_cone.hpp"

#include "topology/tet_mesh.hpp"

namespace cmx::algorithm {

ExpansionCone gather_expansion_cone(const Embedding& e, VertexId v) {
  ExpansionCone cone;
  cone.apex = v;
  for (TetId t : e.mesh.tets_of(v)) {
    const topology::Tet& tet = e.mesh.tet(t);
    const int others = e.unexpanded_count(tet) - (e.unexpanded[v] ? 1 : 0);
    if (others >= 2) continue;
    InnerHalfSpace h = cone_halfspace(e, v, t);
    if (h.is_degenerate()) cone.degenerate = true;
    (others == 0 ? cone.base_tets : cone.side_tets) += 1;
    cone.halfspaces.push_back(std::move(h));
  }
  return cone;
}

InnerHalfSpace cone_halfspace(const Embedding& e, VertexId v, TetId t) {
  const topology::Tet& tet = e.mesh.tet(t);
  const topology::Triangle f = topology::tet_face(tet, topology::local_index(tet, v));
  // Cluster vertices other than v sit at p_c: e.target holds exactly that position.
  return inner_halfspace(e.target[f[0]], e.target[f[1]], e.target[f[2]]);
}

FloatCone float_expansion_cone(const Embedding& e, VertexId v) {
  FloatCone cone;
  for (TetId t : e.mesh.tets_of(v)) {
    const topology::Tet& tet = e.mesh.tet(t);
    const int others = e.unexpanded_count(tet) - (e.unexpanded[v] ? 1 : 0);
    if (others >= 2) continue;
    const topology::Triangle f = topology::tet_face(tet, topology::local_index(tet, v));
    cone.rows.push_back(float_inner_row(e.target[f[0]], e.target[f[1]], e.target[f[2]]));
    cone.tets.push_back(t);
    if (others == 0) ++cone.base_tets;
  }
  return cone;
}

std::array<double, 4> float_inner_row(const HPoint& a, const HPoint& b, const HPoint& c) {
  return float_inner_row(a.approx(), b.approx(), c.approx());
}

std::array<double, 4> float_inner_row(const std::array<double, 3>& p, const std::array<double, 3>& q,
                                      const std::array<double, 3>& r) {
  // Inner side of (p, q, r): orient3d(p, q, r, x) < 0, i.e. n . x < n . p with n = (q-p) x (r-p).
  const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, w[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
  const double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  return {n[0], n[1], n[2], n[0] * p[0] + n[1] * p[1] + n[2] * p[2]};
}

std::vector<lp::HalfSpace> lp_halfspaces(const ExpansionCone& cone) {
  std::vector<lp::HalfSpace> out;
  out.reserve(cone.halfspaces.size());
  for (const InnerHalfSpace& h : cone.halfspaces)
    out.push_back({Rational(h.u[0]), Rational(h.u[1]), Rational(h.u[2]), Rational(h.w)});
  return out;
}

bool strictly_inside(const ExpansionCone& cone, const HPoint& x) {
  if (cone.degenerate) return false;
  for (const InnerHalfSpace& h : cone.halfspaces)
    if (side_of(h, x) != Sign::negative) return false;
  return true;
}

}  // namespace cmx::algorithm
