#include <unistd.h>

#include <filesystem>

#include "cli/command.hpp"

namespace cmx::cli {

std::string unwritable_reason(const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path parent = fs::path(path).parent_path();
  const std::string dir = parent.empty() ? "." : parent.string();
  std::error_code ec;
  if (!fs::exists(dir, ec)) return "cannot write '" + path + "': directory '" + dir + "' does not exist";
  if (!fs::is_directory(dir, ec)) return "cannot write '" + path + "': '" + dir + "' is not a directory";
  if (access(dir.c_str(), W_OK | X_OK) != 0) return "cannot write '" + path + "': directory '" + dir + "' is not writable";
  if (fs::is_directory(path, ec)) return "cannot write '" + path + "': it is a directory";
  return {};
}

}  // namespace cmx::cli
