#include "cli/files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "cli/command.hpp"
#include "io/io_error.hpp"

namespace cmx::cli {
namespace fs = std::filesystem;

std::string unwritable_reason(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  const std::string dir = parent.empty() ? "." : parent.string();
  std::error_code ec;
  if (!fs::exists(dir, ec)) return "cannot write '" + path + "': directory '" + dir + "' does not exist";
  if (!fs::is_directory(dir, ec)) return "cannot write '" + path + "': '" + dir + "' is not a directory";
  if (access(dir.c_str(), W_OK | X_OK) != 0) return "cannot write '" + path + "': directory '" + dir + "' is not writable";
  if (fs::is_directory(path, ec)) return "cannot write '" + path + "': it is a directory";
  return {};
}

std::vector<std::string> mesh_files(const std::string& path) {
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {path};
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "node") return {path, path.substr(0, dot + 1) + "ele"};
  if (ext == "ele") return {path.substr(0, dot + 1) + "node", path};
  return {path};
}

void check_readable(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) throw Failure(exit_bad_input, path + ": cannot open: " + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw Failure(exit_bad_input, path + ": is a directory");
  const int fd = open(path.c_str(), O_RDONLY);
  if (fd < 0) throw Failure(exit_bad_input, path + ": cannot open: " + std::strerror(errno));
  close(fd);
}

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec);
  const fs::path ca = fs::weakly_canonical(a, ec);
  if (ec) return a == b;
  const fs::path cb = fs::weakly_canonical(b, ec);
  if (ec) return a == b;
  return ca == cb;
}

void check_outputs_apart(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    for (const std::string& input : inputs)
      if (same_file(outputs[i], input))
        throw Failure(exit_usage, "refusing to write '" + outputs[i] + "': it is the input '" + input + "'");
    for (std::size_t j = 0; j < i; ++j)
      if (same_file(outputs[i], outputs[j]))
        throw Failure(exit_usage, "refusing to write '" + outputs[i] + "' twice ('" + outputs[j] + "' is the same file)");
  }
}

void check_writable(const std::vector<std::string>& outputs) {
  for (const std::string& path : outputs)
    if (std::string why = unwritable_reason(path); !why.empty()) throw Failure(exit_write_failed, why);
}

int exit_code_of(const io::IoError& e) {
  switch (e.kind()) {
    case io::ErrorKind::write_failed: return exit_write_failed;
    case io::ErrorKind::inconsistent_orientation: return exit_invalid_problem;
    default: return exit_bad_input;
  }
}

}  // namespace cmx::cli
