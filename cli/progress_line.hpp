#pragma once
// The progress line `cmx map` keeps rewriting on a terminal's stderr, naming the phase.
#include <string>

#include "cmx/map.hpp"

namespace cmx::cli {

// "\r  expansion: expanded 120, left 30, added 4, max bits 80, 3.1 s" during the expansion,
// "\r  collapse: 1200/5000, 40.2 s" in the other phases ("1200" when the total is unknown), then
// the ANSI sequence that clears the rest of the line.
std::string progress_line(const MapProgress& p);

}  // namespace cmx::cli
