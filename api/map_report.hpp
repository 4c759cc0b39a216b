#pragma once
// The statistics and verdicts of a map run as JSON: the fields `cmx map --report` writes after its
// options, and cmx::MapResult::report_json. One writer, so the two cannot drift apart.
#include <vector>

#include "algorithm/map.hpp"
#include "api/json.hpp"
#include "cmx/map.hpp"

namespace cmx::api {

// Returns peak_rss_kb (when the OS tells it), input, local, preprocess, expansion, double_output,
// output, bits, seconds, predicates, verdict and, after a precision loss, precision_loss.
std::vector<ReportField> result_fields(const algorithm::MapResult& r);
void add_result_fields(JsonObject& j, const std::vector<ReportField>& fields);

}  // namespace cmx::api
