#include "io/map_fields.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "io/io_error.hpp"

namespace cmx::io {
namespace {

DoublePoint minus(const DoublePoint& p, const DoublePoint& q) { return {p[0] - q[0], p[1] - q[1], p[2] - q[2]}; }

DoublePoint cross(const DoublePoint& u, const DoublePoint& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

double dot(const DoublePoint& u, const DoublePoint& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }

double norm(const DoublePoint& u) { return std::sqrt(dot(u, u)); }

}  // namespace

double signed_volume(const DoublePoint& a, const DoublePoint& b, const DoublePoint& c, const DoublePoint& d) {
  return dot(minus(b, a), cross(minus(c, a), minus(d, a))) / 6;
}

double min_dihedral_angle_deg(const DoublePoint& a, const DoublePoint& b, const DoublePoint& c, const DoublePoint& d) {
  const DoublePoint p[4] = {a, b, c, d};
  // normal[k]: the normal of the face opposite vertex k, pointing away from vertex k (outward for
  // a positive tet, inward for a negative one: angles between normals do not depend on that).
  DoublePoint normal[4];
  for (int k = 0; k < 4; ++k) {
    const auto& u = p[(k + 1) % 4];
    auto n = cross(minus(p[(k + 2) % 4], u), minus(p[(k + 3) % 4], u));
    const double side = dot(n, minus(p[k], u));
    if (side == 0) return 0;  // vertex k in the plane of its opposite face: a flat tet
    if (side > 0) n = {-n[0], -n[1], -n[2]};
    normal[k] = n;
  }
  // The dihedral angle at the edge shared by faces k and l is pi minus the angle between their
  // normals; atan2 keeps it accurate near 0 and 180 degrees.
  double smallest = 180;
  for (int k = 0; k < 4; ++k)
    for (int l = k + 1; l < 4; ++l) {
      const double between = std::atan2(norm(cross(normal[k], normal[l])), dot(normal[k], normal[l]));
      smallest = std::min(smallest, 180 - between * 180 / std::numbers::pi);
    }
  return smallest;
}

DisplayFields map_display_fields(const std::vector<DoublePoint>& source, const std::vector<DoublePoint>& target,
                                 const std::vector<Tet>& tets, std::size_t input_vertex_count) {
  if (source.size() != target.size())
    throw IoError(ErrorKind::mismatch, "map fields", 0,
                  std::to_string(source.size()) + " source positions for " + std::to_string(target.size()) + " target positions");
  DisplayFields fields;
  fields.point_vectors.push_back({"source", source});
  CellScalarField added{"added", ScalarType::uint8, {}}, source_volume{"source_volume", ScalarType::float64, {}},
      target_volume{"target_volume", ScalarType::float64, {}}, dihedral{"min_dihedral_deg", ScalarType::float64, {}};
  for (std::size_t i = 0; i < tets.size(); ++i) {
    const auto& t = tets[i];
    for (auto v : t)
      if (v >= source.size())
        throw IoError(ErrorKind::index_out_of_range, "map fields", 0,
                      "tet " + std::to_string(i) + " uses vertex " + std::to_string(v) + " of " + std::to_string(source.size()));
    const bool refined = std::any_of(t.begin(), t.end(), [&](std::uint32_t v) { return v >= input_vertex_count; });
    added.values.push_back(refined ? 1 : 0);
    source_volume.values.push_back(signed_volume(source[t[0]], source[t[1]], source[t[2]], source[t[3]]));
    target_volume.values.push_back(signed_volume(target[t[0]], target[t[1]], target[t[2]], target[t[3]]));
    dihedral.values.push_back(min_dihedral_angle_deg(target[t[0]], target[t[1]], target[t[2]], target[t[3]]));
  }
  fields.cell_scalars = {std::move(added), std::move(source_volume), std::move(target_volume), std::move(dihedral)};
  return fields;
}

}  // namespace cmx::io
