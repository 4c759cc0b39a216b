#pragma once
// The JSON report of `cmx map --report`: the options, and after a run its statistics and verdicts.
#include <string>
#include <vector>

#include "algorithm/map.hpp"
#include "cmx/map.hpp"
#include "cli/json.hpp"
#include "cli/map_args.hpp"

namespace cmx::cli {

// The snap policy the run applies: a non-exact --arith's doubles are the plain rounding.
algorithm::SnapPolicy snap_used(const MapArgs& a);

// The report: cmx's version, DOMAIN, status, message, options, then `fields` (a run's statistics
// and verdicts, cmx::MapResult::report_fields; empty when the run stopped before a result existed).
JsonObject report_json(const MapArgs& a, const std::vector<ReportField>& fields, const std::string& status,
                       const std::string& message);

}  // namespace cmx::cli
