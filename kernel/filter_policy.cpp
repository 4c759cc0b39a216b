#include "kernel/filter_policy.hpp"

#include <cstdio>

#include "kernel/policy_name.hpp"

namespace cmx {

namespace {
constexpr long min_filter_bits = 2, max_filter_bits = 1000000;
constexpr const char* valid_filter_names = "cascade, interval, exact, naive or mpfr:BITS (BITS in 2..1000000)";
}  // namespace

std::optional<FilterPolicy> parse_filter_policy(std::string_view name, std::string* why) {
  using K = FilterPolicy::Kind;
  if (name == "cascade") return FilterPolicy{K::cascade, 0};
  if (name == "interval") return FilterPolicy{K::interval, 0};
  if (name == "exact") return FilterPolicy{K::exact, 0};
  if (name == "naive") return FilterPolicy{K::naive, 0};
  if (name.substr(0, 5) == "mpfr:") {
    if (const auto bits = parse_bounded_integer(name.substr(5), min_filter_bits, max_filter_bits))
      return FilterPolicy{K::mpfr, std::int32_t(*bits)};
    if (why) *why = "bad precision in filter '" + std::string(name) + "': expected " + valid_filter_names;
    return std::nullopt;
  }
  if (why) *why = "unknown filter '" + std::string(name) + "': expected " + valid_filter_names;
  return std::nullopt;
}

std::string to_string(const FilterPolicy& policy) {
  switch (policy.kind) {
    case FilterPolicy::Kind::cascade: return "cascade";
    case FilterPolicy::Kind::interval: return "interval";
    case FilterPolicy::Kind::exact: return "exact";
    case FilterPolicy::Kind::naive: return "naive";
    case FilterPolicy::Kind::mpfr: return "mpfr:" + std::to_string(policy.mpfr_bits);
  }
  return "?";
}

FilterStats& FilterStats::operator+=(const FilterStats& o) {
  semi_static += o.semi_static;
  for (int i = 0; i < 4; ++i) adaptive[i] += o.adaptive[i];
  interval += o.interval;
  mpfr += o.mpfr;
  exact += o.exact;
  naive += o.naive;
  return *this;
}

std::string FilterStats::report() const {
  const std::uint64_t all = total();
  std::string out;
  auto line = [&](const char* name, std::uint64_t n) {
    if (n == 0) return;
    char buf[96];
    std::snprintf(buf, sizeof buf, "%-12s %12llu (%6.2f %%)\n", name, static_cast<unsigned long long>(n),
                  100.0 * double(n) / double(all));
    out += buf;
  };
  line("semi-static", semi_static);
  line("adaptive A", adaptive[0]);
  line("adaptive B", adaptive[1]);
  line("adaptive C", adaptive[2]);
  line("adaptive D", adaptive[3]);
  line("interval", interval);
  line("mpfr", mpfr);
  line("exact", exact);
  line("naive", naive);
  if (all == 0) out = "no predicate calls\n";
  return out;
}

}  // namespace cmx
