#include "api/json.hpp"

#include <nlohmann/json.hpp>

namespace cmx::api {

std::string json_quote(const std::string& text) {
  return nlohmann::json(text).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace cmx::api
