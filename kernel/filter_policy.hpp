#pragma once
// Filter policies of the predicate cascade (kernel/filtered_predicate.hpp), chosen by name, the
// counters of which tier decided, and PredicateContext, the two together as the one value that
// every kernel predicate call takes.
//
//   cascade   (default) double inputs: semi-static filter, then adaptive expansions (always
//             decides); other inputs: double interval on the cached enclosures, then exact.
//   interval  double interval (also on double inputs), then exact.
//   exact     the exact homogeneous integer determinant only.
//   mpfr:BITS cascade with an MPFR interval of BITS bits (2..1000000) between the double
//             interval and the exact tier; for precision studies.
//   naive     plain double determinant on the nearest doubles: WRONG signs near degeneracy;
//             for demonstrations only, never a default.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace cmx {

struct FilterPolicy {
  enum class Kind : std::int32_t { cascade, interval, exact, mpfr, naive };
  Kind kind = Kind::cascade;
  // Only for Kind::mpfr (2..1000000). 32 bits, so that a PredicateContext is 16 bytes and passed
  // in two registers.
  std::int32_t mpfr_bits = 0;

  friend bool operator==(const FilterPolicy&, const FilterPolicy&) = default;
};

// Parses "cascade", "interval", "exact", "naive" or "mpfr:BITS". On failure returns nullopt and,
// if `why` is given, a one-line reason that lists the valid names.
std::optional<FilterPolicy> parse_filter_policy(std::string_view name, std::string* why = nullptr);
// The canonical name ("mpfr:128", ...); parse_filter_policy reads it back.
std::string to_string(const FilterPolicy& policy);

// The tiers of the cascade, as counted: the adaptive stages A-D are consecutive.
enum class Tier : std::uint8_t {
  semi_static,
  adaptive_a,
  adaptive_b,
  adaptive_c,
  adaptive_d,
  interval,
  mpfr,
  exact,
  naive
};

// How many predicate calls each tier decided. Counted through PredicateContext::stats; nothing is
// counted globally. Not thread-safe: use one object per thread.
struct FilterStats {
  std::uint64_t semi_static = 0;   // semi-static filter on double inputs
  std::uint64_t adaptive[4] = {};  // Shewchuk stages A, B, C, D on double inputs
  std::uint64_t interval = 0;      // double interval on cached enclosures
  std::uint64_t mpfr = 0;          // MPFR interval
  std::uint64_t exact = 0;         // exact homogeneous determinant (GMP)
  std::uint64_t naive = 0;         // naive double (policy naive)

  std::uint64_t total() const {
    return semi_static + adaptive[0] + adaptive[1] + adaptive[2] + adaptive[3] + interval + mpfr + exact +
           naive;
  }
  // The counter of tier t (inline: with a constant t it folds to one increment).
  std::uint64_t& counter(Tier t) {
    switch (t) {
      case Tier::semi_static:
        return semi_static;
      case Tier::interval:
        return interval;
      case Tier::mpfr:
        return mpfr;
      case Tier::exact:
        return exact;
      case Tier::naive:
        return naive;
      default:
        return adaptive[int(t) - int(Tier::adaptive_a)];
    }
  }
  FilterStats& operator+=(const FilterStats& o);
  // One line per nonzero counter, "tier: count (percent)".
  std::string report() const;
};

// What every kernel predicate call is given: the policy that chooses the tiers, and where to count
// the deciding tier (nullptr: nowhere). Callers pass it explicitly; there is no default argument,
// so each call site says whether it runs under the user's policy or checks a result. Passed by
// value: 16 bytes, two registers, so building one per call costs nothing.
struct PredicateContext {
  FilterPolicy policy;
  FilterStats* stats;

  // The default cascade (always exact), counting nothing: for code that CHECKS a result (the
  // verifier, the check of rounded output, reading a map back) and for callers outside a run.
  // A check must not use the run's policy: a naive policy would judge its own output.
  static constexpr PredicateContext certain() { return {FilterPolicy{}, nullptr}; }
};
static_assert(sizeof(PredicateContext) == 16, "passed in two registers");

}  // namespace cmx
