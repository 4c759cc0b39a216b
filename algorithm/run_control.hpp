#pragma once
// When a run must stop, and what it tells its caller on the way: one object shared by every
// phase of map_to_domain (expansion, collapses and merges, double output, shelling search).
//
// Each phase polls `step(phase, done, total)` (or `should_stop(phase)`, which reports no
// progress) between two of its steps, at points where its state is complete (a phase cut there
// can keep or undo its work whole). A run stops when
// the time limit has passed or when the caller's stop hook (MapOptions::stop) says so; once
// it has said stop it says so at every later poll, so every later phase ends at once too. The
// polls also feed the progress callback (about 5 Hz) for the phases that have no detailed
// progress of their own.
#include <chrono>
#include <cstddef>
#include <functional>
#include <optional>
#include <string_view>

#include "algorithm/map.hpp"

namespace cmx::algorithm {

class RunControl {
 public:
  using Clock = std::chrono::steady_clock;

  // No limit, no hook, no progress: never stops.
  RunControl() = default;
  RunControl(const MapOptions& options, Clock::time_point start);
  RunControl(const RunControl&) = delete;  // one run, one record of whether it was told to stop
  RunControl& operator=(const RunControl&) = delete;

  // True when the run must stop now. `phase` names the poller ("expansion", "collapse", ...).
  bool should_stop(const char* phase);
  // Reports progress (when due, and always when the phase changes): done of total steps of
  // `phase` (total 0: unknown). For the phases whose progress is nothing but such a count.
  void report(const char* phase, std::size_t done, std::size_t total = 0);
  // report, then should_stop.
  bool step(const char* phase, std::size_t done, std::size_t total = 0) {
    report(phase, done, total);
    return should_stop(phase);
  }

  // True when should_stop can ever answer true: phases keep an undo copy only then.
  [[nodiscard]] bool can_stop() const { return deadline_.has_value() || static_cast<bool>(stop_); }
  [[nodiscard]] bool stopped() const { return stopped_; }

  // The deadline for `seconds` after `start`: none for 0 (no limit) and for limits beyond half
  // of what the clock can still represent, about 146 years (1e300 or infinity mean "no limit",
  // not an overflow).
  static std::optional<Clock::time_point> deadline_after(double seconds, Clock::time_point start);

 private:
  std::optional<Clock::time_point> deadline_;
  std::function<bool(std::string_view)> stop_;
  std::function<void(const MapProgress&)> progress_;
  Clock::time_point start_{}, last_report_{};
  std::string_view last_phase_;
  bool stopped_ = false;
};

// Seconds of wall time since `start` on the run's clock: the figures of MapStatistics::seconds.
inline double seconds_since(RunControl::Clock::time_point start) {
  return std::chrono::duration<double>(RunControl::Clock::now() - start).count();
}

}  // namespace cmx::algorithm
