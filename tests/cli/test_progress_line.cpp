// The progress line of `cmx map`, as a function: it names the phase, counts what the phase
// counts, and clears the rest of the terminal line.
#include <doctest/doctest.h>

#include "cli/progress_line.hpp"

using cmx::MapProgress;
using cmx::cli::progress_line;

TEST_CASE("the progress line names the expansion phase and its counts") {
  MapProgress p;
  p.phase = "expansion";
  p.expanded = 120;
  p.remaining = 30;
  p.added_vertices = 4;
  p.max_bits = 80;
  p.seconds = 3.14;
  CHECK(progress_line(p) == "\r  expansion: expanded 120, left 30, added 4, max bits 80, 3.1 s\x1b[K");
}

TEST_CASE("the progress line of the later phases shows steps done of all, or done alone") {
  MapProgress p;
  p.phase = "collapse";
  p.done = 1200;
  p.total = 5000;
  p.seconds = 40.23;
  CHECK(progress_line(p) == "\r  collapse: 1200/5000, 40.2 s\x1b[K");
  p.phase = "verification";
  p.total = 0;  // unknown
  CHECK(progress_line(p) == "\r  verification: 1200, 40.2 s\x1b[K");
}
