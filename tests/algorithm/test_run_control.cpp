// Stopping a run (algorithm/run_control.hpp): wherever the time limit or the stop hook falls, in
// whatever phase, map_to_domain ends with a verified map or a clean time limit, never with a
// broken map. The cuts are made by the stop hook at the N-th poll, so they are reproducible.
#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "generators/domain_generators.hpp"
#include "algorithm/map.hpp"
#include "algorithm/run_control.hpp"
#include "map_test_util.hpp"

using namespace cmx;
using namespace cmx::algorithm;
using namespace cmx::generators;
using cmx::test::problem_from;

namespace {

// The phase of every poll of an uncut run, in order.
std::vector<std::string> polls_of(const MapProblem& p, MapOptions options) {
  std::vector<std::string> phases;
  options.stop = [&](std::string_view phase) {
    phases.emplace_back(phase);
    return false;
  };
  const MapResult r = map_to_domain(p, options);
  REQUIRE_MESSAGE(r.outcome == MapOutcome::success, r.message);
  return phases;
}

// The polls to cut at: the first and the last of every run of polls of one phase, and about
// `per_phase` polls spread evenly over each run.
std::vector<std::size_t> cut_points(const std::vector<std::string>& phases, std::size_t per_phase) {
  std::vector<std::size_t> cuts;
  for (std::size_t first = 0; first < phases.size();) {
    std::size_t last = first;
    while (last + 1 < phases.size() && phases[last + 1] == phases[first]) ++last;
    const std::size_t stride = std::max<std::size_t>(1, (last - first + 1) / per_phase);
    for (std::size_t i = first; i <= last; i += stride) cuts.push_back(i);
    cuts.push_back(last);
    first = last + 1;
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  return cuts;
}

// The run stopped at poll `cut` (0-based): a clean time limit during the expansion, a verified
// map after it (the phase cut short undone, or kept whole).
MapResult cut_at(const MapProblem& p, MapOptions options, std::size_t cut) {
  std::size_t polls = 0;
  options.stop = [&](std::string_view) { return polls++ >= cut; };
  return map_to_domain(p, options);
}

void check_every_cut(const MapProblem& p, const MapOptions& options, std::size_t per_phase,
                     std::map<std::string, std::size_t>& cut_phases) {
  const std::vector<std::string> phases = polls_of(p, options);
  REQUIRE(!phases.empty());
  for (std::size_t cut : cut_points(phases, per_phase)) {
    CAPTURE(cut);
    CAPTURE(phases[cut]);
    const MapResult r = cut_at(p, options, cut);
    ++cut_phases[phases[cut]];
    if (phases[cut] == "expansion") {
      CHECK(r.outcome == MapOutcome::time_limit);
      CHECK(r.message.find("time limit") != std::string::npos);
      continue;
    }
    REQUIRE_MESSAGE(r.outcome == MapOutcome::success, r.message);
    CHECK_MESSAGE(r.verification.ok(), r.verification.first_failure);
    if (phases[cut] == "collapse") CHECK(r.stats.merge_stopped_at_time_limit);
    if (phases[cut] == "doubles") CHECK((r.doubles.stopped_at_deadline || r.doubles.check.valid()));
  }
  // The same cut twice: the same map (where a run stops depends on the poll, not on the clock).
  const std::size_t middle = phases.size() / 2;
  const MapResult a = cut_at(p, options, middle), b = cut_at(p, options, middle);
  CHECK(a.outcome == b.outcome);
  CHECK(a.tets == b.tets);
  CHECK(a.target == b.target);
}

}  // namespace

TEST_CASE("a run stopped at any poll of the expansion, the merges or the double repair is clean") {
  std::map<std::string, std::size_t> cut_phases;
  // One-layer slabs: most of their added vertices go in merges, relocating and flip collapses.
  check_every_cut(problem_from(thin_slab(12, 9, 1, 1), "star:3"), {}, 15, cut_phases);
  check_every_cut(problem_from(thin_slab(10, 8, 1, 2), "sphere"), {}, 10, cut_phases);
  // The paper's pass always runs, and polls before every vertex it moves.
  MapOptions pass;
  pass.snap = SnapPolicy::chebyshev_pass;
  check_every_cut(problem_from(perturbed_grid(4, 4, 4, 1), "star:2"), pass, 10, cut_phases);
  MESSAGE("cuts per phase: expansion " << cut_phases["expansion"] << ", collapse " << cut_phases["collapse"]
                                       << ", doubles " << cut_phases["doubles"]);
  CHECK(cut_phases["expansion"] > 0);
  CHECK(cut_phases["collapse"] > 0);
  CHECK(cut_phases["doubles"] > 0);
}

TEST_CASE("time limits beyond the clock range mean no limit, and zero means none") {
  const auto now = std::chrono::steady_clock::now();
  CHECK_FALSE(RunControl::deadline_after(0, now));
  // 1e10 s (317 years) is beyond what a steady clock counting nanoseconds can add to now.
  CHECK_FALSE(RunControl::deadline_after(1e10, now));
  CHECK_FALSE(RunControl::deadline_after(1e300, now));
  CHECK_FALSE(RunControl::deadline_after(std::numeric_limits<double>::infinity(), now));
  const auto hour = RunControl::deadline_after(3600, now);
  REQUIRE(hour);
  CHECK(*hour - now == std::chrono::hours(1));
  MapOptions o;
  o.time_limit_seconds = 1e300;
  const MapResult r = map_to_domain(problem_from(perturbed_grid(2, 2, 2, 1), "tet"), o);
  CHECK(r.outcome == MapOutcome::success);
}

TEST_CASE("once told to stop a run control stays stopped, and its polls report progress by phase") {
  MapOptions o;
  std::vector<std::string> seen;
  o.progress = [&](const MapProgress& p) { seen.emplace_back(p.phase); };
  bool stop = false;
  o.stop = [&](std::string_view) { return stop; };
  RunControl control(o, std::chrono::steady_clock::now());
  CHECK_FALSE(control.step("collapse", 1, 10));
  stop = true;
  CHECK(control.should_stop("collapse"));
  stop = false;
  CHECK(control.should_stop("doubles"));
  CHECK(control.stopped());
  // A new phase is reported at once, whatever the rate limit.
  control.report("verification", 0);
  REQUIRE(seen.size() == 2);
  CHECK(seen[0] == "collapse");
  CHECK(seen[1] == "verification");
}
