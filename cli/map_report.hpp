#pragma once
// The JSON report of `cmx map --report`: the options, and after a run its statistics and verdicts.
#include <string>

#include "algorithm/map.hpp"
#include "cli/json.hpp"
#include "cli/map_args.hpp"

namespace cmx::cli {

// The snap policy the run applies: a non-exact --arith's doubles are the plain rounding.
algorithm::SnapPolicy snap_used(const MapArgs& a);

// `r` is null when the run stopped before a result existed (bad input, invalid problem).
JsonObject report_json(const MapArgs& a, const algorithm::MapResult* r, const std::string& status, const std::string& message);

}  // namespace cmx::cli
