#include "cli/progress_line.hpp"

#include <algorithm>
#include <cstdio>
#include <string_view>

namespace cmx::cli {

std::string progress_line(const MapProgress& p) {
  char buf[256];
  const int phase_length = int(std::min<std::size_t>(p.phase.size(), 40));
  if (p.phase == "expansion")
    std::snprintf(buf, sizeof buf, "\r  expansion: expanded %zu, left %zu, added %zu, max bits %zu, %.1f s\x1b[K", p.expanded,
                  p.remaining, p.added_vertices, p.max_bits, p.seconds);
  else if (p.total)
    std::snprintf(buf, sizeof buf, "\r  %.*s: %zu/%zu, %.1f s\x1b[K", phase_length, p.phase.data(), p.done, p.total,
                  p.seconds);
  else
    std::snprintf(buf, sizeof buf, "\r  %.*s: %zu, %.1f s\x1b[K", phase_length, p.phase.data(), p.done, p.seconds);
  return buf;
}

}  // namespace cmx::cli
