#pragma once
// Filter policies of the predicate cascade (kernel/orient.hpp), chosen by name,
// and the counters of which tier decided.
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
  enum class Kind { cascade, interval, exact, mpfr, naive };
  Kind kind = Kind::cascade;
  long mpfr_bits = 0;  // only for Kind::mpfr

  friend bool operator==(const FilterPolicy&, const FilterPolicy&) = default;
};

// Parses "cascade", "interval", "exact", "naive" or "mpfr:BITS". On failure returns nullopt and,
// if `why` is given, a one-line reason that lists the valid names.
std::optional<FilterPolicy> parse_filter_policy(std::string_view name, std::string* why = nullptr);
// The canonical name ("mpfr:128", ...); parse_filter_policy reads it back.
std::string to_string(const FilterPolicy& policy);

// How many predicate calls each tier decided. Pass a pointer to the orient functions to count;
// nothing is counted globally. Not thread-safe: use one object per thread.
struct FilterStats {
  std::uint64_t semi_static = 0;   // semi-static filter on double inputs
  std::uint64_t adaptive[4] = {};  // Shewchuk stages A, B, C, D on double inputs
  std::uint64_t interval = 0;      // double interval on cached enclosures
  std::uint64_t mpfr = 0;          // MPFR interval
  std::uint64_t exact = 0;         // exact homogeneous determinant (GMP)
  std::uint64_t naive = 0;         // naive double (policy naive)

  std::uint64_t total() const {
    return semi_static + adaptive[0] + adaptive[1] + adaptive[2] + adaptive[3] + interval + mpfr + exact + naive;
  }
  FilterStats& operator+=(const FilterStats& o);
  // One line per nonzero counter, "tier: count (percent)".
  std::string report() const;
};

}  // namespace cmx
