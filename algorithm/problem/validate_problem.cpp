#include "algorithm/problem/validate_problem.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "algorithm/describe.hpp"
#include "algorithm/expansion/expansion_cone.hpp"
#include "algorithm/map_error.hpp"
#include "kernel/orient.hpp"
#include "topology/ball_check.hpp"

namespace cmx::algorithm {

namespace {

std::string face_text(const topology::Triangle& f) { return "boundary triangle " + ids_text(f); }

// "1 boundary vertex has" / "17 boundary vertices have"
std::string count_text(std::size_t count, const char* one, const char* many) {
  return std::to_string(count) + " " + (count == 1 ? one : many);
}

void check_sizes(const MapProblem& p) {
  const std::size_t n = p.source.size();
  if (p.tets.empty()) throw MapError(MapErrorKind::invalid_input, "the mesh has no tetrahedra");
  for (std::size_t t = 0; t < p.tets.size(); ++t)
    for (auto v : p.tets[t])
      if (v >= n)
        throw MapError(MapErrorKind::invalid_input, "vertex index " + std::to_string(v) + " out of range (" +
                                                        std::to_string(n) + " vertices)", "tet " + std::to_string(t));
  if (p.boundary_positions.size() != p.boundary_vertices.size())
    throw MapError(MapErrorKind::invalid_input, "boundary vertex and position counts differ");
  std::vector<char> seen(n, 0);
  for (auto b : p.boundary_vertices) {
    if (b >= n) throw MapError(MapErrorKind::boundary_mismatch, "index out of range", "boundary vertex " + std::to_string(b));
    if (seen[b]++) throw MapError(MapErrorKind::boundary_mismatch, "position given twice", "boundary vertex " + std::to_string(b));
  }
}

std::vector<lp::HalfSpace> as_lp(const std::vector<InnerHalfSpace>& hs, std::size_t count) {
  std::vector<lp::HalfSpace> out;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i)
    out.push_back({Rational(hs[i].u[0]), Rational(hs[i].u[1]), Rational(hs[i].u[2]), Rational(hs[i].w)});
  return out;
}

bool has_interior(const std::vector<InnerHalfSpace>& hs, const lp::ChebyshevOptions& lp) {
  return lp::chebyshev_center(as_lp(hs, hs.size()), lp).status == lp::ChebyshevStatus::interior;
}

// A double next to each coordinate (the low end of its cached enclosure: no GMP, and near enough
// for a guess that is then checked exactly).
std::array<double, 3> near(const HPoint& p) { return {p.enclosure(0).lo, p.enclosure(1).lo, p.enclosure(2).lo}; }

// A point that sees every boundary triangle strictly from inside proves that the kernel has
// interior without the exact LP: the float Chebyshev centre of the triangles' planes (in doubles,
// with the origin moved to the boundary's centroid, where the float simplex starts), taken as an
// exact point and checked against every half-space exactly. Most valid boundaries pass; false
// leaves the verdict, and every message about a failure, to the exact LP.
bool seen_from_float_centre(const ValidatedProblem& v) {
  std::array<double, 3> o{0, 0, 0};
  for (const HPoint& p : v.boundary_positions)
    for (std::size_t k = 0; k < 3; ++k) o[k] += near(p)[k];
  for (double& x : o) x /= double(v.boundary_positions.size());
  std::vector<std::array<double, 4>> rows;
  rows.reserve(v.boundary_faces.size());
  for (const auto& f : v.boundary_faces) {
    const auto& c = f.face;
    std::array<double, 4> r = float_inner_row(near(v.prescribed[c[0]]), near(v.prescribed[c[1]]), near(v.prescribed[c[2]]));
    r[3] -= r[0] * o[0] + r[1] * o[1] + r[2] * o[2];
    rows.push_back(r);
  }
  const lp::FloatChebyshev c = lp::float_chebyshev(rows);
  if (!c.optimal || !(c.radius > 0)) return false;
  const std::array<double, 3> q{c.centre[0] + o[0], c.centre[1] + o[1], c.centre[2] + o[2]};
  if (!std::all_of(q.begin(), q.end(), [](double x) { return std::isfinite(x); })) return false;
  const HPoint centre = HPoint::from_doubles(q[0], q[1], q[2]);
  return std::all_of(v.kernel.begin(), v.kernel.end(),
                     [&](const InnerHalfSpace& h) { return side_of(h, centre) == Sign::negative; });
}

// The prescribed position of every boundary vertex; positions for exactly the boundary vertices
// (the messages count what is wrong and name the first vertex).
void prescribe_boundary(const MapProblem& p, ValidatedProblem& v) {
  const std::size_t n = p.source.size();
  v.prescribed.assign(n, HPoint());
  std::vector<char> given(n, 0);
  std::size_t off_boundary = 0, first_off = 0;
  for (std::size_t i = 0; i < p.boundary_vertices.size(); ++i) {
    const auto b = p.boundary_vertices[i];
    if (!v.boundary[b] && !off_boundary++) first_off = b;
    given[b] = 1;
    v.prescribed[b] = HPoint(p.boundary_positions[i][0], p.boundary_positions[i][1], p.boundary_positions[i][2]);
    v.boundary_positions.push_back(v.prescribed[b]);
  }
  if (off_boundary)
    throw MapError(MapErrorKind::boundary_mismatch,
                   count_text(off_boundary, "position is", "positions are") +
                       " prescribed for vertices that are not on the boundary; first: vertex " + std::to_string(first_off));
  std::size_t missing = 0, first_missing = 0;
  for (std::size_t b = 0; b < n; ++b)
    if (v.boundary[b] && !given[b] && !missing++) first_missing = b;
  if (missing)
    throw MapError(MapErrorKind::boundary_mismatch,
                   count_text(missing, "boundary vertex has", "boundary vertices have") +
                       " no prescribed position; first: vertex " + std::to_string(first_missing));
}

}  // namespace

std::size_t first_emptying_halfspace(const std::vector<InnerHalfSpace>& hs, const lp::ChebyshevOptions& lp) {
  std::optional<HPoint> centre;
  for (std::size_t i = 0; i < hs.size(); ++i) {
    if (hs[i].is_degenerate()) return i;
    if (centre && side_of(hs[i], *centre) == Sign::negative) continue;
    const lp::ChebyshevResult r = lp::chebyshev_center(as_lp(hs, i + 1), lp);
    if (r.status == lp::ChebyshevStatus::interior) centre = HPoint(r.center[0], r.center[1], r.center[2]);
    else if (r.status != lp::ChebyshevStatus::unbounded) return i;
    else centre.reset();  // a few half-spaces: unbounded interior, no centre to test with
  }
  return SIZE_MAX;
}

ValidatedProblem validate_problem(const MapProblem& p, const FilterPolicy& filter, const lp::ChebyshevOptions& lp,
                                  bool combinatorial) {
  check_sizes(p);
  ValidatedProblem v;
  v.combinatorial = combinatorial;
  const std::size_t n = p.source.size();
  v.mesh = topology::TetMesh(n, p.tets);
  const topology::BallVerdict ball = topology::check_ball(v.mesh);
  if (!ball.ok) throw MapError(MapErrorKind::not_ball, ball.message);

  v.source.reserve(n);
  for (const auto& q : p.source) v.source.emplace_back(q[0], q[1], q[2]);
  for (std::size_t t = 0; !combinatorial && t < p.tets.size(); ++t) {
    const auto& x = p.tets[t];
    const Sign s =
        orient3d(v.source[x[0]], v.source[x[1]], v.source[x[2]], v.source[x[3]], {filter, nullptr});
    if (s != Sign::positive)
      throw MapError(MapErrorKind::source_not_positive,
                     std::string(s == Sign::zero ? "flat (zero volume)" : "inverted (negatively oriented)") + " in the source mesh",
                     "tet " + std::to_string(t));
  }

  v.boundary_faces = topology::boundary_faces(v.mesh);
  v.boundary.assign(n, 0);
  for (const auto& f : v.boundary_faces)
    for (auto b : f.face) v.boundary[b] = 1;
  prescribe_boundary(p, v);

  for (const auto& f : v.boundary_faces) {
    InnerHalfSpace h = inner_halfspace(v.prescribed[f.face[0]], v.prescribed[f.face[1]], v.prescribed[f.face[2]]);
    if (h.is_degenerate())
      throw MapError(MapErrorKind::degenerate_boundary, "its prescribed corners are collinear", face_text(f.face));
    v.kernel.push_back(std::move(h));
  }
  if (!seen_from_float_centre(v) && !has_interior(v.kernel, lp)) {
    // Mirrored: every face seen from the wrong side has a kernel with interior.
    std::vector<InnerHalfSpace> flipped = v.kernel;
    for (auto& h : flipped) {
      for (auto& c : h.u) c = -c;
      h.w = -h.w;
    }
    if (has_interior(flipped, lp))
      throw MapError(MapErrorKind::boundary_orientation,
                     "the prescribed boundary is mirrored (inside out): every triangle faces inward");
    const std::size_t k = first_emptying_halfspace(v.kernel, lp);
    const std::string where = k < v.boundary_faces.size() ? face_text(v.boundary_faces[k].face) : "boundary";
    throw MapError(MapErrorKind::not_star_shaped,
                   "the prescribed boundary is not star-shaped: no point sees this triangle and all triangles "
                   "listed before it from inside (the kernel has no interior)",
                   where);
  }
  return v;
}

}  // namespace cmx::algorithm
