#pragma once
// The CLI writes its JSON with the API's builder (api/json.hpp), so `cmx map --report` and
// cmx::MapResult::report_json share one writer.
#include "api/json.hpp"

namespace cmx::cli {
using api::json_number;
using api::json_quote;
using api::JsonObject;
}  // namespace cmx::cli
