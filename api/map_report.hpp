#pragma once
// The statistics and verdicts of a map run as JSON: the fields `cmx map --report` writes after its
// options, and cmx::MapResult::report_json. One writer, so the two cannot drift apart.
#include "algorithm/map.hpp"
#include "api/json.hpp"

namespace cmx::api {

// Appends peak_rss_kb (when the OS tells it), input, local, preprocess, expansion, double_output,
// output, bits, seconds, predicates, verdict and, after a precision loss, precision_loss.
void add_result_fields(JsonObject& j, const algorithm::MapResult& r);

}  // namespace cmx::api
