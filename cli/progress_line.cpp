#include "cli/progress_line.hpp"

#include <cstdio>
#include <string_view>

namespace cmx::cli {

std::string progress_line(const algorithm::MapProgress& p) {
  char buf[256];
  const std::string_view phase = p.phase ? p.phase : "";
  if (phase == "expansion")
    std::snprintf(buf, sizeof buf, "\r  expansion: expanded %zu, left %zu, added %zu, max bits %zu, %.1f s\x1b[K", p.expanded,
                  p.remaining, p.splits, p.max_bits, p.seconds);
  else if (p.total)
    std::snprintf(buf, sizeof buf, "\r  %.40s: %zu/%zu, %.1f s\x1b[K", p.phase, p.done, p.total, p.seconds);
  else
    std::snprintf(buf, sizeof buf, "\r  %.40s: %zu, %.1f s\x1b[K", p.phase ? p.phase : "", p.done, p.seconds);
  return buf;
}

}  // namespace cmx::cli
