#include "algorithm/map_error.hpp"

namespace cmx::algorithm {

const char* kind_name(MapErrorKind kind) {
  switch (kind) {
    case MapErrorKind::invalid_input: return "invalid_input";
    case MapErrorKind::not_ball: return "not_ball";
    case MapErrorKind::boundary_mismatch: return "boundary_mismatch";
    case MapErrorKind::source_not_positive: return "source_not_positive";
    case MapErrorKind::degenerate_boundary: return "degenerate_boundary";
    case MapErrorKind::boundary_orientation: return "boundary_orientation";
    case MapErrorKind::not_star_shaped: return "not_star_shaped";
    case MapErrorKind::time_limit: return "time_limit";
    case MapErrorKind::stuck: return "stuck";
    case MapErrorKind::internal: return "internal";
  }
  return "?";
}

static std::string compose(const std::string& message, const std::string& where) {
  return where.empty() ? message : where + ": " + message;
}

MapError::MapError(MapErrorKind kind, std::string message, std::string where)
    : std::runtime_error(compose(message, where)), kind_(kind), where_(std::move(where)) {}

}  // namespace cmx::algorithm
