#include "io/io_error.hpp"

namespace cmx::io {
namespace {

std::string format(const std::string& file, std::size_t line, const std::string& message) {
  std::string s = file;
  if (line > 0) s += ':' + std::to_string(line);
  return s + ": " + message;
}

}  // namespace

const char* kind_name(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::open_failed: return "open_failed";
    case ErrorKind::unsupported: return "unsupported";
    case ErrorKind::syntax: return "syntax";
    case ErrorKind::truncated: return "truncated";
    case ErrorKind::count_mismatch: return "count_mismatch";
    case ErrorKind::index_out_of_range: return "index_out_of_range";
    case ErrorKind::non_tet_cell: return "non_tet_cell";
    case ErrorKind::not_finite: return "not_finite";
    case ErrorKind::duplicate: return "duplicate";
    case ErrorKind::degenerate_tet: return "degenerate_tet";
    case ErrorKind::inconsistent_orientation: return "inconsistent_orientation";
    case ErrorKind::too_large: return "too_large";
    case ErrorKind::mismatch: return "mismatch";
    case ErrorKind::write_failed: return "write_failed";
  }
  return "unknown";
}

IoError::IoError(ErrorKind kind, std::string file, std::size_t line, std::string message)
    : std::runtime_error(format(file, line, message)),
      kind_(kind),
      file_(std::move(file)),
      line_(line),
      message_(std::move(message)) {}

}  // namespace cmx::io
