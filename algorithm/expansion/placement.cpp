#include "algorithm/expansion/placement.hpp"

#include <cmath>
#include <utility>

#include "algorithm/tuning.hpp"
#include "arith/rounding.hpp"
#include "kernel/orient.hpp"
#include "lp/backend_registry.hpp"
#include "lp/few_bit_point.hpp"

namespace cmx::algorithm {

namespace {

HPoint to_hpoint(const cmx::Point3& p) {
  return HPoint(p[0], p[1], p[2]);
}

cmx::Point3 to_point3(const HPoint& p) {
  return {p.coordinate(0), p.coordinate(1), p.coordinate(2)};
}

// Dyadic points on the segment from `from` toward `to` (t = 1/2, 1/4, ...), first strictly inside
// with fewer bits than `cap`; nullopt when none within 64 halvings.
std::optional<cmx::Point3> segment_point(const std::vector<lp::HalfSpace>& h, const HPoint& from,
                                         const HPoint& to, std::size_t cap) {
  const cmx::Point3 a = to_point3(from), b = to_point3(to);
  Rational t(1, 2);
  for (int step = 0; step < 64; ++step, t /= 2) {
    cmx::Point3 q;
    for (int k = 0; k < 3; ++k)
      q[std::size_t(k)] = a[std::size_t(k)] + t * (b[std::size_t(k)] - a[std::size_t(k)]);
    if (lp::point_bits(q) >= cap) return std::nullopt;
    if (lp::strictly_inside(h, q)) return q;
  }
  return std::nullopt;
}

// The shortest dyadic rounding of the centre c (k = 53, 106, ... significant bits, then bisection)
// within L-infinity distance r/4 of c: Euclidean distance < r/2, so, the ball B(c, r) lying in the
// kernel (l2-upper weights), the point keeps a margin of r/2 from every constraint plane. Later
// cones see their neighbours well inside their own kernels: measured, this avoids most
// star-shapifications that points merely "somewhere inside" cause. Falls back to the plain
// inside test (with an l1 norm the ball is a cube, still inside).
std::optional<cmx::Point3> centred_dyadic(const std::vector<lp::HalfSpace>& h, const cmx::Point3& c,
                                          const Rational& r) {
  const Rational tol = r / 4;
  auto close = [&](const cmx::Point3& q) {
    for (int i = 0; i < 3; ++i)
      if (abs(q[std::size_t(i)] - c[std::size_t(i)]) > tol) return false;
    return lp::strictly_inside(h, q);
  };
  auto rounded = [&](unsigned k) {
    cmx::Point3 q;
    for (int i = 0; i < 3; ++i) q[std::size_t(i)] = round_to_dyadic(c[std::size_t(i)], k).value();
    return q;
  };
  // At least a double's 53 bits: coarser roundings snap nearby vertices onto common planes and
  // lines, and the exact coplanarities they create flatten later cones (starting at k = 1 costs
  // several times the star-shapifications and an order of magnitude more bits).
  const unsigned first = 53;
  unsigned fail = first - 1, ok = 0;
  for (unsigned k = first; k <= 65536; k *= 2) {
    if (close(rounded(k))) {
      ok = k;
      break;
    }
    fail = k;
  }
  if (ok == 0) return std::nullopt;
  while (ok - fail > 1) {
    const unsigned mid = fail + (ok - fail) / 2;
    (close(rounded(mid)) ? ok : fail) = mid;
  }
  return rounded(ok);
}

// Rounds out.position to a non-exact arith (see PlacementOptions::arith).
void round_to_arith(const std::vector<lp::HalfSpace>& h, const cmx::Point3& centre,
                    const CoordinateArith& arith, Placement& out) {
  out.unrounded_bits = out.bits;
  cmx::Point3 q = to_point3(arith.round(out.position));
  if (!lp::strictly_inside(h, q)) {
    const cmx::Point3 c = to_point3(arith.round(to_hpoint(centre)));
    if (lp::strictly_inside(h, c))
      q = c;
    else
      out.rounded_outside = true;
  }
  out.position = to_hpoint(q);
  out.bits = lp::point_bits(q);
}

}  // namespace

bool takes_float_shortcuts(const PlacementOptions& options) {
  return lp::backend_capabilities(options.lp.backend).certifies_float_basis;
}

FloatConeVerdict guess_cone(const FloatCone& cone, const PlacementOptions& options) {
  FloatConeVerdict out;
  if (!takes_float_shortcuts(options)) return out;
  out.lp = lp::float_chebyshev(cone.rows);
  if (!out.lp.optimal) return out;
  if (out.lp.radius > tuning::cone_open_radius * out.lp.scale)
    out.guess = ConeGuess::open;
  else if (out.lp.radius <= tuning::cone_closed_radius * out.lp.scale)
    out.guess = ConeGuess::closed;
  return out;
}

bool certified_closed(const Embedding& e, VertexId v, const FloatCone& cone,
                      const lp::FloatChebyshev& guess) {
  std::vector<InnerHalfSpace> support;
  for (std::size_t i : guess.tight_rows) support.push_back(cone_halfspace(e, v, cone.tets[i]));
  return proves_no_common_point(support);
}

std::optional<std::array<double, 3>> float_centre(const FloatCone& cone, const lp::FloatChebyshev& g,
                                                  const PlacementOptions& options) {
  if (!takes_float_shortcuts(options) || !options.arith.exact()) return std::nullopt;
  if (options.precision != PrecisionPolicy::dyadic && options.precision != PrecisionPolicy::segment)
    return std::nullopt;
  if (!g.optimal || !(g.radius > tuning::cone_open_radius * g.scale)) return std::nullopt;
  for (double x : g.centre)
    if (!std::isfinite(x)) return std::nullopt;
  for (const auto& row : cone.rows) {
    const double n = std::sqrt(row[0] * row[0] + row[1] * row[1] + row[2] * row[2]);
    const double slack = row[3] - row[0] * g.centre[0] - row[1] * g.centre[1] - row[2] * g.centre[2];
    if (!(n > 0) || !(slack >= 0.5 * g.radius * n)) return std::nullopt;
  }
  return g.centre;
}

std::optional<Placement> place_at_point(const Embedding& e, VertexId v, const std::array<double, 3>& centre) {
  const HPoint q{Rational(centre[0]), Rational(centre[1]), Rational(centre[2])};
  // The cone is exactly the tets of v with at most one other cluster vertex (expansion_cone.hpp).
  std::size_t rows = 0;
  for (TetId t : e.mesh.tets_of(v)) {
    const topology::Tet& tet = e.mesh.tet(t);
    if (e.unexpanded_count(tet) - (e.unexpanded[v] ? 1 : 0) >= 2) continue;
    ++rows;
    std::array<const HPoint*, 4> p;
    for (std::size_t i = 0; i < 4; ++i) p[i] = tet[i] == v ? &q : &e.target[tet[i]];
    if (orient3d(*p[0], *p[1], *p[2], *p[3], {e.filter, e.stats}) != Sign::positive) return std::nullopt;
  }
  Placement out;
  out.status = lp::ChebyshevStatus::interior;
  out.position = q;
  out.bits = out.centre_bits = lp::point_bits(to_point3(q));
  out.rows = rows;
  out.at_float_centre = true;
  return out;
}

std::optional<Placement> place_at_float_centre(const Embedding& e, VertexId v, const FloatCone& cone,
                                               const PlacementOptions& options) {
  if (!takes_float_shortcuts(options)) return std::nullopt;
  const std::optional<std::array<double, 3>> c = float_centre(cone, lp::float_chebyshev(cone.rows), options);
  if (!c) return std::nullopt;
  return place_at_point(e, v, *c);
}

Placement place_in_cone(const ExpansionCone& cone, const PlacementOptions& options,
                        const HPoint* segment_from, const HPoint* segment_to) {
  Placement out;
  if (cone.degenerate) {
    out.status = lp::ChebyshevStatus::infeasible;
    return out;
  }
  const std::vector<lp::HalfSpace> h = lp_halfspaces(cone);
  out.rows = h.size();
  const lp::ChebyshevResult c = lp::chebyshev_center(h, options.lp);
  out.status = c.status;
  out.info = c.lp.info;
  if (c.status != lp::ChebyshevStatus::interior) return out;
  out.centre_bits = lp::point_bits(c.center);
  lp::FewBitResult r;
  switch (options.precision) {
    case PrecisionPolicy::none:
      r.point = c.center;
      break;
    case PrecisionPolicy::shift:
      r = lp::few_bits_by_shift(h, c.center);
      break;
    case PrecisionPolicy::segment:
      if (segment_from && segment_to) {
        if (auto q = segment_point(h, *segment_from, *segment_to, out.centre_bits)) {
          r.point = *q;
          break;
        }
      }
      [[fallthrough]];
    case PrecisionPolicy::dyadic:
      if (auto q = centred_dyadic(h, c.center, c.radius))
        r.point = *q;
      else
        r = lp::few_bits_by_dyadics(h, c.center);
      break;
  }
  out.position = to_hpoint(r.point);
  out.bits = lp::point_bits(r.point);
  if (!options.arith.exact()) round_to_arith(h, c.center, options.arith, out);
  return out;
}

bool move_to_placement(Embedding& e, VertexId v, const Placement& p) {
  if (!p.ok() || p.rounded_outside || p.position == e.target[v]) return false;
  e.target[v] = p.position;
  return true;
}

bool recentre(Embedding& e, VertexId v, const PlacementOptions& options) {
  return move_to_placement(e, v, place_in_cone(gather_expansion_cone(e, v), options));
}

}  // namespace cmx::algorithm
