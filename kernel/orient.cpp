// The cascade: dispatch by policy, then from the cheapest tier to the exact one.
#include "kernel/orient.hpp"

#include <cmath>
#include <stdexcept>

#include "kernel/determinant.hpp"
#include "kernel/orient_adaptive.hpp"
#include "kernel/orient_exact.hpp"
#include "kernel/orient_interval.hpp"
#include "kernel/orient_semistatic.hpp"

namespace cmx {

namespace {

using Kind = FilterPolicy::Kind;

void require_finite(const double* p, int dims) {
  for (int k = 0; k < dims; ++k)
    if (!std::isfinite(p[k])) throw std::domain_error("orientation predicate: NaN or infinite coordinate");
}

HPoint to_hpoint(const double* p, int dims) { return HPoint::from_doubles(p[0], p[1], dims == 3 ? p[2] : 0.0); }

template <class F>
Sign counted(std::uint64_t FilterStats::*counter, FilterStats* stats, F&& f) {
  const Sign s = f();
  if (stats) ++(stats->*counter);
  return s;
}

// The semi-static filter did not decide: adaptive stages, or exact outside their range.
// Kept out of line so the filter's fast path has a small stack frame and no register spills.
[[gnu::noinline]] Sign orient3d_double_slow(const double* a, const double* b, const double* c, const double* d, FilterStats* stats,
                          const HPoint* const* exact_points) {
  const double all[12] = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2]};
  if (adaptive::in_adaptive_range(all, 12)) return adaptive::orient3d(a, b, c, d, stats);
  if (stats) ++stats->exact;
  if (exact_points)
    return orient3d_exact(*exact_points[0], *exact_points[1], *exact_points[2], *exact_points[3]);
  require_finite(all, 12);
  return orient3d_exact(to_hpoint(a, 3), to_hpoint(b, 3), to_hpoint(c, 3), to_hpoint(d, 3));
}

[[gnu::noinline]] Sign orient2d_double_slow(const double* a, const double* b, const double* c, FilterStats* stats,
                          const HPoint* const* exact_points) {
  const double all[6] = {a[0], a[1], b[0], b[1], c[0], c[1]};
  if (adaptive::in_adaptive_range(all, 6)) return adaptive::orient2d(a, b, c, stats);
  if (stats) ++stats->exact;
  if (exact_points) return orient2d_exact(*exact_points[0], *exact_points[1], *exact_points[2]);
  require_finite(all, 6);
  return orient2d_exact(to_hpoint(a, 2), to_hpoint(b, 2), to_hpoint(c, 2));
}

void lows(const HPoint& p, double* out) {
  out[0] = p.enclosure(0).lo;
  out[1] = p.enclosure(1).lo;
  out[2] = p.enclosure(2).lo;
}

}  // namespace

namespace {
[[gnu::noinline]] Sign orient3d_other_policies(const double* a, const double* b, const double* c, const double* d,
                                               const FilterPolicy& policy, FilterStats* stats) {
  switch (policy.kind) {
    case Kind::cascade:
    case Kind::mpfr:  // on doubles the adaptive stages always decide before an MPFR tier
      if (const UncertainSign s = semistatic::orient3d(a, b, c, d)) {
        if (stats) ++stats->semi_static;
        return *s;
      }
      return orient3d_double_slow(a, b, c, d, stats, nullptr);
    case Kind::interval:
      if (const UncertainSign s = orient3d_interval(a, b, c, d)) {
        if (stats) ++stats->interval;
        return *s;
      }
      break;
    case Kind::naive:
      require_finite(a, 3), require_finite(b, 3), require_finite(c, 3), require_finite(d, 3);
      return counted(&FilterStats::naive, stats, [&] { return sign_of(orient3d_det(a, b, c, d)); });
    case Kind::exact: break;
  }
  require_finite(a, 3), require_finite(b, 3), require_finite(c, 3), require_finite(d, 3);
  if (stats) ++stats->exact;
  return orient3d_exact(to_hpoint(a, 3), to_hpoint(b, 3), to_hpoint(c, 3), to_hpoint(d, 3));
}
}  // namespace

Sign orient3d(const double* a, const double* b, const double* c, const double* d, const FilterPolicy& policy,
              FilterStats* stats) {
  if (policy.kind != Kind::cascade) [[unlikely]]
    return orient3d_other_policies(a, b, c, d, policy, stats);
  // The hot path: the semi-static filter and nothing else.
  if (const UncertainSign s = semistatic::orient3d(a, b, c, d)) [[likely]] {
    if (stats) ++stats->semi_static;
    return *s;
  }
  return orient3d_double_slow(a, b, c, d, stats, nullptr);
}

namespace {
// Every HPoint case but "cascade on four double points" (kept out of line, see above).
[[gnu::noinline]] Sign orient3d_hpoint_general(const HPoint& a, const HPoint& b, const HPoint& c, const HPoint& d,
                                               const FilterPolicy& policy, FilterStats* stats) {
  const bool doubles = a.is_double() && b.is_double() && c.is_double() && d.is_double();
  switch (policy.kind) {
    case Kind::cascade:
    case Kind::mpfr:
      if (doubles) {
        double pa[3], pb[3], pc[3], pd[3];
        lows(a, pa), lows(b, pb), lows(c, pc), lows(d, pd);
        if (const UncertainSign s = semistatic::orient3d(pa, pb, pc, pd)) {
          if (stats) ++stats->semi_static;
          return *s;
        }
        const HPoint* points[4] = {&a, &b, &c, &d};
        return orient3d_double_slow(pa, pb, pc, pd, stats, points);
      }
      if (const UncertainSign s = orient3d_interval(a, b, c, d)) {
        if (stats) ++stats->interval;
        return *s;
      }
      if (policy.kind == Kind::mpfr)
        if (const UncertainSign s = orient3d_mpfr(a, b, c, d, policy.mpfr_bits)) {
          if (stats) ++stats->mpfr;
          return *s;
        }
      break;
    case Kind::interval:
      if (const UncertainSign s = orient3d_interval(a, b, c, d)) {
        if (stats) ++stats->interval;
        return *s;
      }
      break;
    case Kind::naive: {
      const auto pa = a.approx(), pb = b.approx(), pc = c.approx(), pd = d.approx();
      return counted(&FilterStats::naive, stats,
                     [&] { return sign_of(orient3d_det(pa.data(), pb.data(), pc.data(), pd.data())); });
    }
    case Kind::exact: break;
  }
  if (stats) ++stats->exact;
  return orient3d_exact(a, b, c, d);
}
}  // namespace

Sign orient3d(const HPoint& a, const HPoint& b, const HPoint& c, const HPoint& d, const FilterPolicy& policy,
              FilterStats* stats) {
  // The hot path: four double points under the default policy, read from the cached enclosures
  // (no GMP), decided by the semi-static filter.
  if (policy.kind == Kind::cascade && a.is_double() && b.is_double() && c.is_double() && d.is_double()) [[likely]] {
    const double pa[3] = {a.enclosure(0).lo, a.enclosure(1).lo, a.enclosure(2).lo};
    const double pb[3] = {b.enclosure(0).lo, b.enclosure(1).lo, b.enclosure(2).lo};
    const double pc[3] = {c.enclosure(0).lo, c.enclosure(1).lo, c.enclosure(2).lo};
    const double pd[3] = {d.enclosure(0).lo, d.enclosure(1).lo, d.enclosure(2).lo};
    if (const UncertainSign s = semistatic::orient3d(pa, pb, pc, pd)) [[likely]] {
      if (stats) ++stats->semi_static;
      return *s;
    }
  }
  return orient3d_hpoint_general(a, b, c, d, policy, stats);
}

Sign orient2d(const double* a, const double* b, const double* c, const FilterPolicy& policy, FilterStats* stats) {
  switch (policy.kind) {
    case Kind::cascade:
    case Kind::mpfr:
      if (const UncertainSign s = semistatic::orient2d(a, b, c)) {
        if (stats) ++stats->semi_static;
        return *s;
      }
      return orient2d_double_slow(a, b, c, stats, nullptr);
    case Kind::interval:
      if (const UncertainSign s = orient2d_interval(a, b, c)) {
        if (stats) ++stats->interval;
        return *s;
      }
      break;
    case Kind::naive:
      require_finite(a, 2), require_finite(b, 2), require_finite(c, 2);
      return counted(&FilterStats::naive, stats, [&] { return sign_of(orient2d_det(a, b, c)); });
    case Kind::exact: break;
  }
  require_finite(a, 2), require_finite(b, 2), require_finite(c, 2);
  if (stats) ++stats->exact;
  return orient2d_exact(to_hpoint(a, 2), to_hpoint(b, 2), to_hpoint(c, 2));
}

Sign orient2d(const HPoint& a, const HPoint& b, const HPoint& c, const FilterPolicy& policy, FilterStats* stats) {
  // Only x and y matter, so "double" means double in x and y.
  auto xy_double = [](const HPoint& p) { return p.enclosure(0).is_point() && p.enclosure(1).is_point(); };
  const bool doubles = xy_double(a) && xy_double(b) && xy_double(c);
  switch (policy.kind) {
    case Kind::cascade:
    case Kind::mpfr:
      if (doubles) {
        double pa[3], pb[3], pc[3];
        lows(a, pa), lows(b, pb), lows(c, pc);
        if (const UncertainSign s = semistatic::orient2d(pa, pb, pc)) {
          if (stats) ++stats->semi_static;
          return *s;
        }
        const HPoint* points[3] = {&a, &b, &c};
        return orient2d_double_slow(pa, pb, pc, stats, points);
      }
      if (const UncertainSign s = orient2d_interval(a, b, c)) {
        if (stats) ++stats->interval;
        return *s;
      }
      if (policy.kind == Kind::mpfr)
        if (const UncertainSign s = orient2d_mpfr(a, b, c, policy.mpfr_bits)) {
          if (stats) ++stats->mpfr;
          return *s;
        }
      break;
    case Kind::interval:
      if (const UncertainSign s = orient2d_interval(a, b, c)) {
        if (stats) ++stats->interval;
        return *s;
      }
      break;
    case Kind::naive: {
      const auto pa = a.approx(), pb = b.approx(), pc = c.approx();
      return counted(&FilterStats::naive, stats, [&] { return sign_of(orient2d_det(pa.data(), pb.data(), pc.data())); });
    }
    case Kind::exact: break;
  }
  if (stats) ++stats->exact;
  return orient2d_exact(a, b, c);
}

}  // namespace cmx
