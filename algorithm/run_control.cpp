#include "algorithm/run_control.hpp"

#include <cmath>

namespace cmx::algorithm {

namespace {
// The progress callback's rate: often enough for a terminal line, rarely enough to cost nothing.
constexpr auto progress_period = std::chrono::milliseconds(200);
}  // namespace

RunControl::RunControl(const MapOptions& options, Clock::time_point start)
    : deadline_(deadline_after(options.time_limit_seconds, start)),
      stop_(options.stop),
      progress_(options.progress),
      start_(start),
      last_report_(start) {}

std::optional<RunControl::Clock::time_point> RunControl::deadline_after(double seconds, Clock::time_point start) {
  if (!(seconds > 0)) return std::nullopt;  // 0 (none); NaN and negatives are the caller's to refuse
  // Whatever still fits between `start` and the clock's end; a limit beyond it is no limit.
  const double room = std::chrono::duration<double>(Clock::time_point::max() - start).count();
  if (!std::isfinite(seconds) || seconds >= room / 2) return std::nullopt;
  return start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

bool RunControl::should_stop(const char* phase) {
  if (stopped_) return true;
  if ((deadline_ && Clock::now() > *deadline_) || (stop_ && stop_(phase))) stopped_ = true;
  return stopped_;
}

void RunControl::report(const char* phase, std::size_t done, std::size_t total) {
  if (!progress_) return;
  const Clock::time_point now = Clock::now();
  if (now - last_report_ < progress_period && phase == last_phase_) return;
  last_report_ = now;
  last_phase_ = phase;
  MapProgress p;
  p.phase = phase;
  p.done = done;
  p.total = total;
  p.seconds = std::chrono::duration<double>(now - start_).count();
  progress_(p);
}

}  // namespace cmx::algorithm
