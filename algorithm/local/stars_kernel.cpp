#include "algorithm/local/stars_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numeric>

#include "kernel/orient.hpp"
#include "kernel/plane.hpp"

namespace cmx::algorithm::stars {

namespace {

double norm3(const std::array<double, 4>& r) { return std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]); }

// Signed distance of p to the wrong side of row r; +infinity for a zero normal (never seen from
// inside) and for anything the doubles cannot tell, so that the order below stays a strict one.
double wrong_side(const std::array<double, 4>& r, const std::array<double, 3>& p) {
  const double n = norm3(r);
  const double d = (r[0] * p[0] + r[1] * p[1] + r[2] * p[2] - r[3]) / n;
  return n > 0 && std::isfinite(d) ? d : std::numeric_limits<double>::infinity();
}

// The average of the boundary triangles' corners in the target (a corner once per triangle).
std::array<double, 3> boundary_centroid(const GrowingStar& star, const std::vector<std::array<double, 3>>& approx) {
  std::array<double, 3> sum{0, 0, 0};
  std::size_t count = 0;
  for (const FaceRef& f : star.boundary())
    for (VertexId v : star.triangle(f)) {
      const std::array<double, 3>& p = approx[v];
      for (int k = 0; k < 3; ++k) sum[std::size_t(k)] += p[std::size_t(k)];
      ++count;
    }
  for (double& x : sum) x /= double(count);
  return sum;
}

struct Viewpoint {
  std::array<double, 3> point{};
  bool float_kernel = false;  // the float LP found a kernel: worth the exact LP if the point fails
};

// The rows with the origin moved to o: the float simplex starts at the origin, and from the
// star's centroid it has fewer pivots to make than from wherever the target's origin lies.
std::vector<std::array<double, 4>> shifted(const std::vector<std::array<double, 4>>& rows, const std::array<double, 3>& o) {
  std::vector<std::array<double, 4>> out = rows;
  for (auto& r : out) r[3] -= r[0] * o[0] + r[1] * o[1] + r[2] * o[2];
  return out;
}

Viewpoint choose_viewpoint(const GrowingStar& star, const std::vector<std::array<double, 3>>& approx) {
  Viewpoint v;
  const std::array<double, 3> o = boundary_centroid(star, approx);
  v.point = o;
  const lp::FloatChebyshev c = lp::float_chebyshev(shifted(star.rows(), o));
  v.float_kernel = c.optimal;
  if (c.optimal && std::all_of(c.centre.begin(), c.centre.end(), [](double x) { return std::isfinite(x); }))
    v.point = {c.centre[0] + o[0], c.centre[1] + o[1], c.centre[2] + o[2]};
  return v;
}

bool sees_inside(const GrowingStar& star, const std::vector<HPoint>& target, const FaceRef& f, const HPoint& p) {
  const topology::Triangle t = star.triangle(f);
  // Exact whatever --filter says: the stars of the local initial map are classified, not counted.
  return orient3d(target[t[0]], target[t[1]], target[t[2]], p, PredicateContext::certain()) == Sign::negative;
}

bool exact_kernel_has_interior(const GrowingStar& star, const std::vector<HPoint>& target, const lp::ChebyshevOptions& lp) {
  std::vector<lp::HalfSpace> hs;
  hs.reserve(star.boundary().size());
  for (const FaceRef& f : star.boundary()) {
    const topology::Triangle t = star.triangle(f);
    const InnerHalfSpace h = inner_halfspace(target[t[0]], target[t[1]], target[t[2]]);
    if (h.is_degenerate()) return false;
    hs.push_back({Rational(h.u[0]), Rational(h.u[1]), Rational(h.u[2]), Rational(h.w)});
  }
  return lp::chebyshev_center(hs, lp).status == lp::ChebyshevStatus::interior;
}

}  // namespace

KernelTest test_kernel(const GrowingStar& star, const std::vector<HPoint>& target,
                       const std::vector<std::array<double, 3>>& approx, const lp::ChebyshevOptions& lp) {
  KernelTest k;
  const Viewpoint view = choose_viewpoint(star, approx);
  const std::vector<FaceRef>& faces = star.boundary();
  const HPoint p = HPoint::from_doubles(view.point[0], view.point[1], view.point[2]);
  std::vector<std::size_t> violated;
  for (std::size_t i = 0; i < faces.size(); ++i)
    if (!sees_inside(star, target, faces[i], p)) violated.push_back(i);
  if (violated.empty()) {
    k.star_shaped = true;
    return k;
  }
  // The exact LP decides when the float LP saw a kernel, and always for a star without a face to
  // grow across (the whole mesh), whose verdict ends the growth.
  const auto inside_mesh = [&](std::size_t i) { return star.behind(faces[i]) != topology::invalid_index; };
  std::vector<std::size_t> all(faces.size());
  std::iota(all.begin(), all.end(), std::size_t(0));
  if (view.float_kernel || std::none_of(all.begin(), all.end(), inside_mesh)) {
    k.exact_lp = true;
    if (exact_kernel_has_interior(star, target, lp)) {
      k.star_shaped = true;
      return k;
    }
  }
  std::vector<double> distance(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) distance[i] = wrong_side(star.rows()[i], view.point);
  const auto worse = [&](std::size_t a, std::size_t b) {
    if (distance[a] != distance[b]) return distance[a] > distance[b];
    if (faces[a].tet != faces[b].tet) return faces[a].tet < faces[b].tet;
    return faces[a].face < faces[b].face;
  };
  k.violated = violated.size();
  std::copy_if(violated.begin(), violated.end(), std::back_inserter(k.grow_across), inside_mesh);
  if (k.grow_across.empty()) std::copy_if(all.begin(), all.end(), std::back_inserter(k.grow_across), inside_mesh);
  std::sort(k.grow_across.begin(), k.grow_across.end(), worse);
  return k;
}

}  // namespace cmx::algorithm::stars
