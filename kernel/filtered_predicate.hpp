#pragma once
// One filtered-predicate template for every sign predicate of the kernel, in the style of CGAL's
// Filtered_predicate: try the cheapest arithmetic, return when its sign is certain, else the next
// tier, the exact tier last.
//
// A predicate P (kernel/orient_predicates.hpp) says once what it computes:
//   P::points, P::dims                      its number of points and the coordinates it reads;
//   P::determinant(const T (&)[points][dims]) -> T   the determinant, for every number type T;
//   P::semi_static(p), P::adaptive(p, &stage)        the double-input stages (inline);
//   P::exact(h)                             the exact sign on homogeneous integer points.
// A tier is a type with
//   static constexpr Tier tier;             the counter it decides for (FilterStats);
//   static constexpr bool always_decides;   true only for tiers that may end a cascade;
//   decide<P>(args, policy, by) -> UncertainSign  on DoubleArgs and/or PointArgs; `by` is preset
//                                           to `tier` and a tier with stages sets the deciding one.
// run<P>(Tiers<...>{}, args, context) tries the tiers in order and counts the deciding one in the
// one place that counts (run_tiers). The tiers that evaluate P::determinant in a number type T go
// through sign_in<T, P> (NumberTraits<T>, arith/number_traits.hpp), written once for all T.
// Which tier list each FilterPolicy kind runs is decided in filtered() below and nowhere else.
//
// Cost: filtered() under the default policy inlines the policy test and the semi-static filter;
// every later tier runs behind a [[gnu::noinline]] call (rest_on_*, by_policy_on_*) that takes
// the points one by one in registers, so the hot path keeps no frame and no spills.
#include <array>
#include <cmath>
#include <stdexcept>
#include <tuple>

#include "arith/interval.hpp"
#include "arith/mpfr_interval.hpp"
#include "arith/number_traits.hpp"
#include "arith/sign.hpp"
#include "kernel/filter_policy.hpp"
#include "kernel/homogeneous_point.hpp"
#include "kernel/orient_adaptive.hpp"

namespace cmx {

// The arguments of a predicate: raw double coordinates (DoubleArgs), exact points (PointArgs), or
// exact points whose coordinates are doubles, read as such (DoublePointArgs: `p` points into
// the enclosures' copies, `exact` are the points, so the exact tier skips the conversion).
template <int N>
struct DoubleArgs {
  std::array<const double*, N> p;
};
template <int N>
struct PointArgs {
  std::array<const HPoint*, N> p;
};
template <int N>
struct DoublePointArgs {
  std::array<const double*, N> p;
  std::array<const HPoint*, N> exact;
};

template <class... T>
struct Tiers {};

namespace filtered_detail {

template <int Dims, int N>
void require_finite(const DoubleArgs<N>& args) {
  for (const double* q : args.p)
    for (int k = 0; k < Dims; ++k)
      if (!std::isfinite(q[k])) throw std::domain_error("orientation predicate: NaN or infinite coordinate");
}

template <int Dims, int N>
bool finite(const DoubleArgs<N>& args) {
  for (const double* q : args.p)
    for (int k = 0; k < Dims; ++k)
      if (!std::isfinite(q[k])) return false;
  return true;
}

template <int Dims, int N>
bool finite(const PointArgs<N>& args) {
  for (const HPoint* q : args.p)
    for (int k = 0; k < Dims; ++k)
      if (!std::isfinite(q->enclosure(k).lo) || !std::isfinite(q->enclosure(k).hi)) return false;
  return true;
}

}  // namespace filtered_detail

// The sign of P's determinant evaluated in T, with coordinate(i, k) the k-th coordinate of the
// i-th point as a T: certain for certified T (NumberTraits<T>::is_certified) unless nullopt.
// Always inlined into its tier, so that the tier costs one call (the determinant) between the
// rounding-mode switches, as a hand-written tier would (bench/RESULTS.md).
template <class T, class P, class Coordinate>
[[gnu::always_inline]] inline UncertainSign sign_in(Coordinate&& coordinate) {
  using Traits = NumberTraits<T>;
  T c[P::points][P::dims];  // converted outside the Scope: conversions assume the default rounding
  for (int i = 0; i < P::points; ++i)
    for (int k = 0; k < P::dims; ++k) c[i][k] = coordinate(i, k);
  T det;
  {
    [[maybe_unused]] const typename Traits::Scope scope{};
    for (auto& point : c)
      for (T& x : point) x = Traits::fence(x);
    det = Traits::fence(P::determinant(c));
  }
  return Traits::sign(det);
}

// Tier: the semi-static filter on doubles.
struct SemiStaticTier {
  static constexpr Tier tier = Tier::semi_static;
  static constexpr bool always_decides = false;
  template <class P, class DoubleView>
  static UncertainSign decide(const DoubleView& args, const FilterPolicy&, Tier&) {
    return P::semi_static(args.p);
  }
};

// Tier: Shewchuk's adaptive stages A-D on doubles inside their range (exact there).
struct AdaptiveTier {
  static constexpr Tier tier = Tier::adaptive_a;
  static constexpr bool always_decides = false;
  template <class P, class DoubleView>
  static UncertainSign decide(const DoubleView& args, const FilterPolicy&, Tier& by) {
    constexpr int N = P::points;
    double all[N * P::dims];
    for (int i = 0; i < N; ++i)
      for (int k = 0; k < P::dims; ++k) all[i * P::dims + k] = args.p[i][k];
    if (!adaptive::in_adaptive_range(all, N * P::dims)) return std::nullopt;
    int stage = 0;
    const Sign s = P::adaptive(args.p, &stage);
    by = Tier(int(Tier::adaptive_a) + stage);
    return s;
  }
};

// Tier: the double interval, on doubles as points or on the cached enclosures of HPoints (no GMP);
// undecided when a bound is not finite.
struct IntervalTier {
  static constexpr Tier tier = Tier::interval;
  static constexpr bool always_decides = false;
  template <class P, int N>
  static UncertainSign decide(const DoubleArgs<N>& args, const FilterPolicy&, Tier&) {
    if (!filtered_detail::finite<P::dims>(args)) return std::nullopt;
    return sign_in<Interval, P>([&](int i, int k) { return Interval(args.p[i][k]); });
  }
  template <class P, int N>
  static UncertainSign decide(const PointArgs<N>& args, const FilterPolicy&, Tier&) {
    if (!filtered_detail::finite<P::dims>(args)) return std::nullopt;
    return sign_in<Interval, P>([&](int i, int k) {
      const DoubleEnclosure& e = args.p[i]->enclosure(k);
      return Interval(e.lo, e.hi);
    });
  }
};

// Tier: an MPFR interval of policy.mpfr_bits bits on the exact coordinates (precision studies).
struct MpfrTier {
  static constexpr Tier tier = Tier::mpfr;
  static constexpr bool always_decides = false;
  template <class P, int N>
  static UncertainSign decide(const PointArgs<N>& args, const FilterPolicy& policy, Tier&) {
    return sign_in<MpfrInterval, P>(
        [&](int i, int k) { return MpfrInterval(args.p[i]->coordinate(k), policy.mpfr_bits); });
  }
};

// Tier: the plain double determinant on the (nearest) doubles. Always "decides", often wrongly
// near degeneracy: the policy `naive`, for demonstrations only.
struct NaiveTier {
  static constexpr Tier tier = Tier::naive;
  static constexpr bool always_decides = true;
  template <class P, int N>
  static UncertainSign decide(const DoubleArgs<N>& args, const FilterPolicy&, Tier&) {
    filtered_detail::require_finite<P::dims>(args);
    return sign_in<double, P>([&](int i, int k) { return args.p[i][k]; });
  }
  template <class P, int N>
  static UncertainSign decide(const PointArgs<N>& args, const FilterPolicy&, Tier&) {
    std::array<double, 3> near[N];
    for (int i = 0; i < N; ++i) near[i] = args.p[i]->approx();
    return sign_in<double, P>([&](int i, int k) { return near[i][k]; });
  }
};

// Tier: the exact homogeneous integer determinant (GMP). Always decides; NaN or infinite double
// coordinates throw std::domain_error here (no earlier tier decides on them).
struct ExactTier {
  static constexpr Tier tier = Tier::exact;
  static constexpr bool always_decides = true;
  template <class P, int N>
  static UncertainSign decide(const DoublePointArgs<N>& args, const FilterPolicy&, Tier&) {
    return P::exact(args.exact.data());
  }
  template <class P, int N>
  static UncertainSign decide(const DoubleArgs<N>& args, const FilterPolicy&, Tier&) {
    filtered_detail::require_finite<P::dims>(args);
    HPoint h[N];
    const HPoint* hp[N];
    for (int i = 0; i < N; ++i) {
      h[i] = HPoint::from_doubles(args.p[i][0], args.p[i][1], P::dims == 3 ? args.p[i][2] : 0.0);
      hp[i] = &h[i];
    }
    return P::exact(hp);
  }
  template <class P, int N>
  static UncertainSign decide(const PointArgs<N>& args, const FilterPolicy&, Tier&) {
    return P::exact(args.p.data());
  }
};

template <class P, class First, class... Rest, class Args>
inline Sign run_tiers(const Args& args, PredicateContext context);

// The tail of a cascade, out of line (see the header comment). Each takes the points one by one
// (in registers) and rebuilds its arguments: a reference to the caller's would keep them in
// memory on the hot path too.
template <class P, class... Rest, class... D>
[[gnu::noinline]] Sign rest_on_doubles(PredicateContext context, D... p) {
  return run_tiers<P, Rest...>(DoubleArgs<sizeof...(D)>{{p...}}, context);
}
template <class P, class... Rest, class... H>
[[gnu::noinline]] Sign rest_on_points(PredicateContext context, H... h) {
  return run_tiers<P, Rest...>(PointArgs<sizeof...(H)>{{h...}}, context);
}
// Reads the points' coordinates as doubles (their enclosures are points).
template <class P, class... Rest, class... H>
[[gnu::always_inline]] inline Sign run_on_double_points(PredicateContext context, H... h) {
  constexpr int N = sizeof...(H);
  DoublePointArgs<N> args{{}, {h...}};
  double c[N][3];
  for (int i = 0; i < N; ++i) {
    for (int k = 0; k < 3; ++k) c[i][k] = args.exact[i]->enclosure(k).lo;
    args.p[i] = c[i];
  }
  return run_tiers<P, Rest...>(args, context);
}
template <class P, class... Rest, class... H>
[[gnu::noinline]] Sign rest_on_double_points(PredicateContext context, H... h) {
  return run_on_double_points<P, Rest...>(context, h...);
}

template <class P, class... Rest, int N>
Sign run_rest(const DoubleArgs<N>& args, PredicateContext context) {
  return std::apply([&](auto... p) { return rest_on_doubles<P, Rest...>(context, p...); }, args.p);
}
template <class P, class... Rest, int N>
Sign run_rest(const PointArgs<N>& args, PredicateContext context) {
  return std::apply([&](auto... h) { return rest_on_points<P, Rest...>(context, h...); }, args.p);
}
template <class P, class... Rest, int N>
Sign run_rest(const DoublePointArgs<N>& args, PredicateContext context) {
  return std::apply([&](auto... h) { return rest_on_double_points<P, Rest...>(context, h...); }, args.exact);
}

template <class P, class First, class... Rest, class Args>
[[gnu::always_inline]] inline Sign run_tiers(const Args& args, PredicateContext context) {
  Tier by = First::tier;
  if (const UncertainSign s = First::template decide<P>(args, context.policy, by)) [[likely]] {
    if (context.stats) ++context.stats->counter(by);  // the one place that counts
    return *s;
  }
  if constexpr (sizeof...(Rest) == 0) {
    static_assert(First::always_decides, "a cascade must end with a tier that always decides");
    throw std::logic_error("filtered predicate: the last tier did not decide");
  } else {
    return run_rest<P, Rest...>(args, context);
  }
}

template <class P, class... T, class Args>
[[gnu::always_inline]] inline Sign run(Tiers<T...>, const Args& args, PredicateContext context) {
  return run_tiers<P, T...>(args, context);
}

// One tier alone (for tests and fuzzing): its sign or nullopt, nothing counted.
template <class P, class T, class Args>
UncertainSign try_tier(const Args& args, const FilterPolicy& policy) {
  Tier by = T::tier;
  return T::template decide<P>(args, policy, by);
}

// The tier lists of the policies (kernel/filter_policy.hpp).
using DoubleCascade = Tiers<SemiStaticTier, AdaptiveTier, ExactTier>;
using IntervalCascade = Tiers<IntervalTier, ExactTier>;
using MpfrCascade = Tiers<IntervalTier, MpfrTier, ExactTier>;
using ExactOnly = Tiers<ExactTier>;
using NaiveOnly = Tiers<NaiveTier>;

template <class P, class... T, class... H>
[[gnu::always_inline]] inline Sign on_double_points(Tiers<T...>, PredicateContext context, H... h) {
  return run_on_double_points<P, T...>(context, h...);
}

namespace filtered_detail {

// The policies whose tier list is the same for every input kind.
template <class P, class Args>
[[gnu::always_inline]] inline Sign run_common_lists(const Args& args, PredicateContext context) {
  switch (context.policy.kind) {
    case FilterPolicy::Kind::interval:
      return run<P>(IntervalCascade{}, args, context);
    case FilterPolicy::Kind::naive:
      return run<P>(NaiveOnly{}, args, context);
    default:  // exact (cascade and mpfr are handled by the callers)
      return run<P>(ExactOnly{}, args, context);
  }
}

inline bool cascades(const FilterPolicy& policy) {
  return policy.kind == FilterPolicy::Kind::cascade || policy.kind == FilterPolicy::Kind::mpfr;
}

template <class P, class... D>
[[gnu::noinline]] Sign by_policy_on_doubles(PredicateContext context, D... p) {
  const DoubleArgs<sizeof...(D)> args{{p...}};
  // On doubles the adaptive stages decide before an MPFR tier could: mpfr runs the cascade.
  if (cascades(context.policy)) return run<P>(DoubleCascade{}, args, context);
  return run_common_lists<P>(args, context);
}

// True when the coordinates P reads are doubles for every point.
template <class P, int N>
bool reads_doubles(const PointArgs<N>& args) {
  for (const HPoint* q : args.p) {
    if constexpr (P::dims == 3) {
      if (!q->is_double()) return false;
    } else {
      for (int k = 0; k < P::dims; ++k)
        if (!q->enclosure(k).is_point()) return false;
    }
  }
  return true;
}

template <class P, class... H>
[[gnu::noinline]] Sign by_policy_on_points(PredicateContext context, H... h) {
  const PointArgs<sizeof...(H)> args{{h...}};
  if (cascades(context.policy)) {
    if (reads_doubles<P>(args)) return on_double_points<P>(DoubleCascade{}, context, h...);
    if (context.policy.kind == FilterPolicy::Kind::mpfr) return run<P>(MpfrCascade{}, args, context);
    return run<P>(IntervalCascade{}, args, context);
  }
  return run_common_lists<P>(args, context);
}

}  // namespace filtered_detail

// The filtered predicate P under context.policy, counting into context.stats. Inline: the default
// policy's first tier is the hot path of the whole method.
template <class P, int N>
inline Sign filtered(const DoubleArgs<N>& args, PredicateContext context) {
  if (context.policy.kind == FilterPolicy::Kind::cascade) [[likely]]
    return run<P>(DoubleCascade{}, args, context);
  return std::apply([&](auto... p) { return filtered_detail::by_policy_on_doubles<P>(context, p...); },
                    args.p);
}

template <class P, int N>
inline Sign filtered(const PointArgs<N>& args, PredicateContext context) {
  return std::apply(
      [&](auto... h) {
        if (context.policy.kind == FilterPolicy::Kind::cascade && filtered_detail::reads_doubles<P>(args))
            [[likely]]
          return on_double_points<P>(DoubleCascade{}, context, h...);
        return filtered_detail::by_policy_on_points<P>(context, h...);
      },
      args.p);
}

}  // namespace cmx
