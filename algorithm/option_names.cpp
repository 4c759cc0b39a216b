// The option names of the method's policies, in one place: the names --snap and --precision take.
#include "algorithm/option_names.hpp"

#include "algorithm/doubles/double_output.hpp"
#include "algorithm/expansion/placement.hpp"
#include "algorithm/map.hpp"

namespace cmx::algorithm {
namespace {

constexpr OptionNames<SnapPolicy, 4> snap_policy_names{{{{SnapPolicy::none, "none"},
                                                         {SnapPolicy::nearest, "nearest"},
                                                         {SnapPolicy::chebyshev_pass, "chebyshev-pass"},
                                                         {SnapPolicy::repair, "repair"}}}};
constexpr OptionNames<PrecisionPolicy, 4> precision_policy_names{{{{PrecisionPolicy::none, "none"},
                                                                   {PrecisionPolicy::dyadic, "dyadic"},
                                                                   {PrecisionPolicy::shift, "shift"},
                                                                   {PrecisionPolicy::segment, "segment"}}}};

constexpr OptionNames<ShelledMode, 3> shelled_mode_names{{{{ShelledMode::when_stuck, "when-stuck"},
                                                         {ShelledMode::after_pushes, "after-pushes"},
                                                         {ShelledMode::first, "first"}}}};

constexpr OptionNames<ReplayMode, 4> replay_mode_names{{{{ReplayMode::off, "off"},
                                                         {ReplayMode::after_nobuenoss, "after-nobuenoss"},
                                                         {ReplayMode::until_greedy, "until-greedy"},
                                                         {ReplayMode::full, "full"}}}};

}  // namespace

std::optional<ReplayMode> parse_replay_mode(std::string_view name) {
  return replay_mode_names.parse(name);
}
std::string_view to_string(ReplayMode m) {
  return replay_mode_names.name(m);
}

std::optional<ShelledMode> parse_shelled_mode(std::string_view name) {
  return shelled_mode_names.parse(name);
}
std::string_view to_string(ShelledMode m) {
  return shelled_mode_names.name(m);
}

std::optional<SnapPolicy> parse_snap_policy(std::string_view name) {
  return snap_policy_names.parse(name);
}
std::string_view to_string(SnapPolicy p) {
  return snap_policy_names.name(p);
}

std::optional<PrecisionPolicy> parse_precision_policy(std::string_view name) {
  return precision_policy_names.parse(name);
}
std::string_view to_string(PrecisionPolicy p) {
  return precision_policy_names.name(p);
}

}  // namespace cmx::algorithm
