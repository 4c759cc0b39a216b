#include "algorithm/verify/verify_map.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <map>
#include <memory>

#include "algorithm/describe.hpp"
#include "algorithm/verify/verify_subdivision.hpp"
#include "kernel/orient.hpp"
#include "kernel/orient_exact.hpp"
#include "topology/ball_check.hpp"
#include "topology/complex_queries.hpp"

namespace cmx::algorithm {

namespace {


Point3 coords(const HPoint& p) { return {p.coordinate(0), p.coordinate(1), p.coordinate(2)}; }

// The verifier's own static filter (deliberately not the kernel's cascade, whose answers it
// checks), for tets whose twelve coordinates are all doubles: det[b-a, c-a, d-a] evaluated in
// Shewchuk's order for orient3d, whose rounding error is at most (7 + 56 eps) eps times the
// permanent (eps = 2^-53; J. R. Shewchuk, Adaptive Precision Floating-Point Arithmetic, 1997),
// provided nothing underflows or overflows. Otherwise, or when |det| is within the bound: exact.
//
// The ranges that guarantee this, on the nonzero differences of coordinates (a zero difference
// makes its products exactly zero): orient3d multiplies three differences and then eps, so
// [2^-300, 2^300] keeps every triple product in [2^-900, 2^900] and the bound above 2^-960,
// normal doubles all. orient2d multiplies two: [2^-400, 2^400] keeps the products in
// [2^-800, 2^800] and its bound normal. A wider orient3d range, [2^-500, 2^300], let triple
// products of differences near 2^-350 fall into the subnormals, where their rounding error
// exceeds the bound: the filter then answered wrong signs (test_verify_orient.cpp scans that
// window).
constexpr double orient3d_min_difference = 0x1p-300, orient3d_max_difference = 0x1p300;
constexpr double orient2d_min_difference = 0x1p-400, orient2d_max_difference = 0x1p400;

bool in_filter_range(const double* v, int n, double lo, double hi) {
  for (int k = 0; k < n; ++k)
    if (v[k] != 0 && !(std::fabs(v[k]) >= lo && std::fabs(v[k]) <= hi)) return false;
  return true;
}

std::optional<Sign> static_orient(const HPoint& pa, const HPoint& pb, const HPoint& pc, const HPoint& pd) {
  if (!pa.is_double() || !pb.is_double() || !pc.is_double() || !pd.is_double()) return std::nullopt;
  const auto a = pa.approx(), b = pb.approx(), c = pc.approx(), d = pd.approx();
  double v[9];
  for (int i = 0; i < 3; ++i) {
    v[i] = a[std::size_t(i)] - d[std::size_t(i)];
    v[3 + i] = b[std::size_t(i)] - d[std::size_t(i)];
    v[6 + i] = c[std::size_t(i)] - d[std::size_t(i)];
  }
  if (!in_filter_range(v, 9, orient3d_min_difference, orient3d_max_difference)) return std::nullopt;
  const double adx = v[0], ady = v[1], adz = v[2], bdx = v[3], bdy = v[4], bdz = v[5], cdx = v[6], cdy = v[7], cdz = v[8];
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy, cdxady = cdx * ady, adxcdy = adx * cdy, adxbdy = adx * bdy,
               bdxady = bdx * ady;
  // Shewchuk's orient3d(a, b, c, d) is the sign of det[a-d, b-d, c-d] = -det[b-a, c-a, d-a].
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * std::fabs(adz) +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * std::fabs(bdz) +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * std::fabs(cdz);
  constexpr double eps = 0x1p-53;
  const double bound = (7.0 + 56.0 * eps) * eps * permanent;
  if (det > bound) return Sign::negative;
  if (-det > bound) return Sign::positive;
  return std::nullopt;
}

// The verifier's own interval filter (again not the kernel's): det[b-a, c-a, d-a] on the points'
// cached coordinate enclosures, every operation rounded to nearest and then widened outward by
// one ulp (std::nextafter), which contains the exact result of the operation on the interval's
// ends without touching the rounding mode. Decides when the interval excludes 0.
struct Range {
  double lo, hi;
};

double down(double x) { return std::nextafter(x, -INFINITY); }
double up(double x) { return std::nextafter(x, INFINITY); }
Range minus(Range x, Range y) { return {down(x.lo - y.hi), up(x.hi - y.lo)}; }
Range times(Range x, Range y) {
  const double p[4] = {x.lo * y.lo, x.lo * y.hi, x.hi * y.lo, x.hi * y.hi};
  return {down(std::min(std::min(p[0], p[1]), std::min(p[2], p[3]))), up(std::max(std::max(p[0], p[1]), std::max(p[2], p[3])))};
}
Range plus(Range x, Range y) { return {down(x.lo + y.lo), up(x.hi + y.hi)}; }

std::optional<Sign> interval_orient(const HPoint& pa, const HPoint& pb, const HPoint& pc, const HPoint& pd) {
  Range u[3], v[3], w[3];
  for (int i = 0; i < 3; ++i) {
    const Range a{pa.enclosure(i).lo, pa.enclosure(i).hi};
    u[i] = minus({pb.enclosure(i).lo, pb.enclosure(i).hi}, a);
    v[i] = minus({pc.enclosure(i).lo, pc.enclosure(i).hi}, a);
    w[i] = minus({pd.enclosure(i).lo, pd.enclosure(i).hi}, a);
  }
  const Range mx = minus(times(v[1], w[2]), times(v[2], w[1]));
  const Range my = minus(times(v[2], w[0]), times(v[0], w[2]));
  const Range mz = minus(times(v[0], w[1]), times(v[1], w[0]));
  const Range det = plus(plus(times(u[0], mx), times(u[1], my)), times(u[2], mz));
  if (!std::isfinite(det.lo) || !std::isfinite(det.hi)) return std::nullopt;  // overflow, or NaN
  if (det.lo > 0) return Sign::positive;
  if (det.hi < 0) return Sign::negative;
  return std::nullopt;
}

}  // namespace

Sign verification_orient(const HPoint& a, const HPoint& b, const HPoint& c, const HPoint& d) {
  if (const std::optional<Sign> s = static_orient(a, b, c, d)) return *s;
  if (const std::optional<Sign> s = interval_orient(a, b, c, d)) return *s;
  return orient3d_exact(a, b, c, d);
}

namespace {

// A triangle in space with the coordinate plane it is projected to (the axis dropped is the one
// of the largest normal component, so the projection is injective on its plane).
struct PlaneTriangle {
  HPoint a, b, c;
  int drop = 2;
  int sign = 0;   // sign of its projected area
  Rational area;  // its projected area (times 2)
};

// Signed area (times 2) of (p, q, r) projected by dropping axis `drop`.
Rational projected_area(const Point3& p, const Point3& q, const Point3& r, int drop) {
  const int i = drop == 0 ? 1 : 0, j = drop == 2 ? 1 : 2;
  return (q[i] - p[i]) * (r[j] - p[j]) - (q[j] - p[j]) * (r[i] - p[i]);
}

// The projection drops the axis of the largest normal component (estimated in doubles; any axis
// whose exact projected area is nonzero is injective on the triangle's plane, and the exact area
// decides: when the estimate's axis gives zero, the others are tried).
PlaneTriangle make_triangle(const HPoint& a, const HPoint& b, const HPoint& c) {
  PlaneTriangle t{a, b, c, 2, 0, Rational(0)};
  const auto pa = a.approx(), pb = b.approx(), pc = c.approx();
  double n[3];
  for (int d = 0; d < 3; ++d) {
    const int i = d == 0 ? 1 : 0, j = d == 2 ? 1 : 2;
    n[d] = std::fabs((pb[std::size_t(i)] - pa[std::size_t(i)]) * (pc[std::size_t(j)] - pa[std::size_t(j)]) -
                     (pb[std::size_t(j)] - pa[std::size_t(j)]) * (pc[std::size_t(i)] - pa[std::size_t(i)]));
  }
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int x, int y) { return n[x] > n[y]; });
  const Point3 ra = coords(a), rb = coords(b), rc = coords(c);
  for (int d : order) {
    t.area = projected_area(ra, rb, rc, d);
    t.drop = d;
    t.sign = sgn(t.area);
    if (t.sign != 0) break;
  }
  return t;
}

// Sign of projected_area(p, q, r, drop): with all-double inputs first by the static bound of
// Shewchuk's orient2d, (3 + 16 eps) eps times the permanent (in its range, above).
int projected_sign(const HPoint& hp, const HPoint& hq, const HPoint& hr, int drop) {
  const int i = drop == 0 ? 1 : 0, j = drop == 2 ? 1 : 2;
  if (hp.is_double() && hq.is_double() && hr.is_double()) {
    const auto p = hp.approx(), q = hq.approx(), r = hr.approx();
    const double v[4] = {q[std::size_t(i)] - p[std::size_t(i)], r[std::size_t(j)] - p[std::size_t(j)],
                         q[std::size_t(j)] - p[std::size_t(j)], r[std::size_t(i)] - p[std::size_t(i)]};
    if (in_filter_range(v, 4, orient2d_min_difference, orient2d_max_difference)) {
      const double left = v[0] * v[1], right = v[2] * v[3], det = left - right;
      constexpr double eps = 0x1p-53;
      const double bound = (3.0 + 16.0 * eps) * eps * (std::fabs(left) + std::fabs(right));
      if (det > bound) return 1;
      if (-det > bound) return -1;
    }
  }
  return sgn(projected_area(coords(hp), coords(hq), coords(hr), drop));
}

// x lies in the closed triangle (coplanar, and inside in the projection).
bool contains(const PlaneTriangle& t, const HPoint& x) {
  if (t.sign == 0) return false;
  if (x == t.a || x == t.b || x == t.c) return true;  // most output boundary vertices are corners
  if (verification_orient(t.a, t.b, t.c, x) != Sign::zero) return false;
  const int s1 = projected_sign(t.a, t.b, x, t.drop);
  const int s2 = projected_sign(t.b, t.c, x, t.drop);
  const int s3 = projected_sign(t.c, t.a, x, t.drop);
  return s1 * t.sign >= 0 && s2 * t.sign >= 0 && s3 * t.sign >= 0;
}

struct Counts {
  std::size_t negative = 0, zero = 0;
  std::size_t first_bad = SIZE_MAX;
  Sign first_sign = Sign::positive;
};


Counts orientation_counts(const std::vector<topology::Tet>& tets, const std::vector<HPoint>& pos) {
  Counts c;
  for (std::size_t i = 0; i < tets.size(); ++i) {
    const auto& t = tets[i];
    const Sign s = verification_orient(pos[t[0]], pos[t[1]], pos[t[2]], pos[t[3]]);
    if (s == Sign::positive) continue;
    (s == Sign::zero ? c.zero : c.negative) += 1;
    if (c.first_bad == SIZE_MAX) {
      c.first_bad = i;
      c.first_sign = s;
    }
  }
  return c;
}

// The boundary check of the header, in one space (target or source positions). An output face
// with the corners of an input triangle, in its order, is that triangle: it covers it whole, and
// nothing else may lie in it. Other faces must lie in an input triangle with its orientation,
// and the pieces of a triangle must add up to its area (both exact). Triangles are built (their
// exact areas computed) only for that second kind, which a map that refines no boundary face
// never needs.
class BoundaryTiling {
 public:
  // `corners` point into vectors that outlive the tiling.
  BoundaryTiling(std::vector<std::array<const HPoint*, 3>> corners, const std::vector<HPoint>& pos)
      : corners_(std::move(corners)), pos_(pos), triangle_(corners_.size()), area_(corners_.size()),
        whole_(corners_.size(), 0), pieces_(corners_.size(), 0) {}

  void add_whole(std::size_t k) { ++whole_[k]; }
  // Adds output face f as a piece of triangle k: false when it does not lie in it with its orientation.
  bool add(std::size_t k, const topology::Triangle& f) {
    const PlaneTriangle& t = triangle(k);
    Point3 r[3];
    for (int i = 0; i < 3; ++i) {
      if (!contains(t, pos_[f[i]])) return false;
      r[i] = coords(pos_[f[i]]);
    }
    const Rational a = projected_area(r[0], r[1], r[2], t.drop);
    if (sgn(a) != t.sign) return false;
    area_[k] += a;
    ++pieces_[k];
    return true;
  }
  bool fits(std::size_t k, const topology::Triangle& f) {
    const PlaneTriangle& t = triangle(k);
    for (int i = 0; i < 3; ++i)
      if (!contains(t, pos_[f[i]])) return false;
    return true;
  }
  // First input triangle not covered exactly once (whole, or by pieces adding up to its area).
  std::size_t first_uncovered() {
    for (std::size_t k = 0; k < corners_.size(); ++k) {
      const bool exactly = whole_[k] == 1 ? pieces_[k] == 0 : whole_[k] == 0 && area_[k] == triangle(k).area;
      if (!exactly) return k;
    }
    return SIZE_MAX;
  }

 private:
  const PlaneTriangle& triangle(std::size_t k) {
    if (!triangle_[k])
      triangle_[k] = std::make_unique<PlaneTriangle>(make_triangle(*corners_[k][0], *corners_[k][1], *corners_[k][2]));
    return *triangle_[k];
  }

  std::vector<std::array<const HPoint*, 3>> corners_;
  const std::vector<HPoint>& pos_;
  std::vector<std::unique_ptr<PlaneTriangle>> triangle_;  // a pointer each: most are never built
  std::vector<Rational> area_;
  std::vector<std::size_t> whole_, pieces_;
};

std::string face_text(const topology::Triangle& f) { return ids_text(f); }

// A triangle rotated so that its smallest vertex comes first, keeping its orientation.
topology::Triangle canonical(topology::Triangle t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

// Places output face f in an input triangle of both tilings; "" or what failed.
std::string place_piece(const topology::Triangle& f, const std::vector<topology::BoundaryFace>& input_faces,
                        const std::map<topology::VertexId, std::vector<std::size_t>>& incident, BoundaryTiling& in_target,
                        BoundaryTiling& in_source) {
  std::vector<std::size_t> candidates;
  for (auto v : f)
    if (auto it = incident.find(v); it != incident.end()) candidates.insert(candidates.end(), it->second.begin(), it->second.end());
  if (candidates.empty())
    for (std::size_t k = 0; k < input_faces.size(); ++k) candidates.push_back(k);
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  for (std::size_t k : candidates) {
    if (!in_target.fits(k, f) || !in_source.fits(k, f)) continue;
    if (!in_target.add(k, f) || !in_source.add(k, f))
      return "output boundary face " + face_text(f) + " is reversed inside input boundary triangle " +
             face_text(input_faces[k].face);
    return {};
  }
  return "output boundary face " + face_text(f) + " lies in no input boundary triangle";
}

// The boundary-refinement part of verify_map; returns "" or what failed.
std::string check_boundary(const VerificationInput& in, const std::vector<topology::Tet>& tets,
                           const std::vector<HPoint>& source, const std::vector<HPoint>& target,
                           const std::vector<HPoint>& prescribed_by_vertex) {
  const std::size_t n_in = in.source->size();
  const auto input_faces = topology::boundary_faces(topology::TetMesh(n_in, *in.tets));
  std::vector<std::array<const HPoint*, 3>> in_target_corners, in_source_corners;
  std::map<topology::VertexId, std::vector<std::size_t>> incident;
  std::map<topology::Triangle, std::size_t> by_corners;
  for (std::size_t k = 0; k < input_faces.size(); ++k) {
    const auto& f = input_faces[k].face;
    in_target_corners.push_back({&prescribed_by_vertex[f[0]], &prescribed_by_vertex[f[1]], &prescribed_by_vertex[f[2]]});
    // Without a source geometry (a ball given by its tets alone) the second tiling repeats the
    // target's: the subdivision check stands in for the source side.
    if (in.parents)
      in_source_corners.push_back(in_target_corners.back());
    else
      in_source_corners.push_back({&(*in.source)[f[0]], &(*in.source)[f[1]], &(*in.source)[f[2]]});
    for (auto v : f) incident[v].push_back(k);
    by_corners.emplace(canonical(f), k);
  }
  BoundaryTiling in_target(std::move(in_target_corners), target),
      in_source(std::move(in_source_corners), in.parents ? target : source);
  for (const auto& bf : topology::boundary_faces(topology::TetMesh(target.size(), tets))) {
    if (const auto same = by_corners.find(canonical(bf.face)); same != by_corners.end()) {
      in_target.add_whole(same->second);
      in_source.add_whole(same->second);
      continue;
    }
    if (std::string why = place_piece(bf.face, input_faces, incident, in_target, in_source); !why.empty()) return why;
  }
  if (std::size_t k = in_target.first_uncovered(); k != SIZE_MAX)
    return "prescribed boundary triangle " + face_text(input_faces[k].face) + " is not covered exactly";
  if (std::size_t k = in_source.first_uncovered(); k != SIZE_MAX)
    return "input boundary triangle " + face_text(input_faces[k].face) + " is not covered exactly in the source";
  return {};
}

}  // namespace

MapVerification verify_map(const VerificationInput& in, const std::vector<topology::Tet>& tets,
                           const std::vector<HPoint>& source, const std::vector<HPoint>& target) {
  MapVerification v;
  auto fail = [&](const std::string& what) {
    if (v.first_failure.empty()) v.first_failure = what;
  };
  const Counts t = orientation_counts(tets, target);
  v.inverted = t.negative;
  v.degenerate = t.zero;
  v.target_positive = t.first_bad == SIZE_MAX;
  if (!v.target_positive)
    fail("tet " + ids_text(tets[t.first_bad]) + " is " + (t.first_sign == Sign::zero ? "degenerate" : "inverted") +
         " in the target (" + std::to_string(t.negative) + " inverted, " + std::to_string(t.zero) + " degenerate)");
  if (in.parents) {
    const std::string why =
        in.origin ? verify_subdivision(*in.tets, in.source->size(), tets, *in.parents, *in.origin) : "no vertex origins";
    v.source_positive = why.empty();
    if (!why.empty()) fail("not a subdivision of the input complex: " + why);
  } else {
    const Counts s = orientation_counts(tets, source);
    v.source_positive = s.first_bad == SIZE_MAX;
    if (!v.source_positive) fail("tet " + ids_text(tets[s.first_bad]) + " is not positive in the source");
  }

  const std::size_t n_in = in.source->size();
  std::vector<HPoint> prescribed_by_vertex(n_in);
  v.input_kept = source.size() >= n_in && target.size() == source.size();
  for (std::size_t i = 0; v.input_kept && !in.parents && i < n_in; ++i)
    if (!(source[i] == (*in.source)[i])) {
      v.input_kept = false;
      fail("input vertex " + std::to_string(i) + " moved in the source");
    }
  for (std::size_t i = 0; v.input_kept && i < in.boundary_vertices->size(); ++i) {
    const auto b = (*in.boundary_vertices)[i];
    prescribed_by_vertex[b] = (*in.boundary_positions)[i];
    if (!(target[b] == (*in.boundary_positions)[i])) {
      v.input_kept = false;
      fail("boundary vertex " + std::to_string(b) + " is not at its prescribed position");
    }
  }
  const topology::BallVerdict ball = topology::check_ball(topology::TetMesh(target.size(), tets));
  v.ball = ball.ok;
  if (!v.ball) fail("the output is not a ball: " + ball.message);
  if (v.input_kept && v.ball) {
    const std::string why = check_boundary(in, tets, source, target, prescribed_by_vertex);
    v.boundary_refines = why.empty();
    if (!why.empty()) fail(why);
  }
  return v;
}

DoubleCheck check_doubles(const std::vector<topology::Tet>& tets, const std::vector<std::array<double, 3>>& d) {
  // The cascade on raw doubles is exact (adaptive expansions), and much cheaper than GMP.
  DoubleCheck c;
  for (const auto& t : tets) {
    const Sign s =
        orient3d(d[t[0]].data(), d[t[1]].data(), d[t[2]].data(), d[t[3]].data(), PredicateContext::certain());
    if (s == Sign::negative) ++c.inverted;
    if (s == Sign::zero) ++c.degenerate;
  }
  return c;
}

}  // namespace cmx::algorithm
