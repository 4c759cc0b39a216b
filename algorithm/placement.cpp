#include "algorithm/placement.hpp"

#include "lp/few_bit_point.hpp"

namespace cmx::algorithm {

std::optional<PrecisionPolicy> parse_precision_policy(std::string_view name) {
  if (name == "none") return PrecisionPolicy::none;
  if (name == "dyadic") return PrecisionPolicy::dyadic;
  if (name == "shift") return PrecisionPolicy::shift;
  if (name == "segment") return PrecisionPolicy::segment;
  return std::nullopt;
}

std::string_view to_string(PrecisionPolicy p) {
  switch (p) {
    case PrecisionPolicy::none: return "none";
    case PrecisionPolicy::dyadic: return "dyadic";
    case PrecisionPolicy::shift: return "shift";
    case PrecisionPolicy::segment: return "segment";
  }
  return "?";
}

namespace {

HPoint to_hpoint(const lp::Point3& p) { return HPoint(p[0], p[1], p[2]); }

lp::Point3 to_point3(const HPoint& p) { return {p.coordinate(0), p.coordinate(1), p.coordinate(2)}; }

// Dyadic points on the segment from `from` toward `to` (t = 1/2, 1/4, ...), first strictly inside
// with fewer bits than `cap`; nullopt when none within 64 halvings.
std::optional<lp::Point3> segment_point(const std::vector<lp::HalfSpace>& h, const HPoint& from, const HPoint& to,
                                        std::size_t cap) {
  const lp::Point3 a = to_point3(from), b = to_point3(to);
  Rational t(1, 2);
  for (int step = 0; step < 64; ++step, t /= 2) {
    lp::Point3 q;
    for (int k = 0; k < 3; ++k) q[std::size_t(k)] = a[std::size_t(k)] + t * (b[std::size_t(k)] - a[std::size_t(k)]);
    if (lp::point_bits(q) >= cap) return std::nullopt;
    if (lp::strictly_inside(h, q)) return q;
  }
  return std::nullopt;
}

}  // namespace

Placement place_in_cone(const ExpansionCone& cone, const PlacementOptions& options, const HPoint* segment_from,
                        const HPoint* segment_to) {
  Placement out;
  if (cone.degenerate) {
    out.status = lp::ChebyshevStatus::infeasible;
    return out;
  }
  const std::vector<lp::HalfSpace> h = lp_halfspaces(cone);
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
      r = lp::few_bits_by_dyadics(h, c.center);
      break;
  }
  out.position = to_hpoint(r.point);
  out.bits = lp::point_bits(r.point);
  return out;
}

}  // namespace cmx::algorithm
