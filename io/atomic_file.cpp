#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "io/io_error.hpp"

namespace cmx::io {
namespace {

std::atomic<Durability> durability{Durability::atomic};

std::string errno_text() { return std::strerror(errno); }

void sync_path(const std::string& path) {
  const int fd = open(path.c_str(), O_RDONLY);
  if (fd >= 0) {
    fsync(fd);
    close(fd);
  }
}

std::string directory_of(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
}

mode_t default_file_mode() {
  // mkstemp creates 0600; a normal output file gets 0666 minus the umask, as ofstream would.
  const mode_t mask = umask(0);
  umask(mask);
  return mode_t(0666) & ~mask;
}

// Creates an empty temporary next to `path` and returns its name.
std::string create_temporary(const std::string& path) {
  std::string pattern = path + ".tmp.XXXXXX";
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = mkstemp(name.data());
  if (fd < 0) throw IoError(ErrorKind::write_failed, path, 0, "cannot create a temporary file next to it: " + errno_text());
  fchmod(fd, default_file_mode());
  close(fd);
  return name.data();
}

// Writes the body into the temporary `tmp` of `path` (and syncs it to disk when asked to).
void fill_temporary(const std::string& path, const std::string& tmp, const FileBody& body) {
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw IoError(ErrorKind::write_failed, path, 0, "cannot open temporary file " + tmp);
    body(out);
    out.flush();
    if (!out) throw IoError(ErrorKind::write_failed, path, 0, "write error (disk full?)");
  }
  if (output_durability() == Durability::synced) sync_path(tmp);
}

void rename_into_place(const std::string& tmp, const std::string& path) {
  if (std::rename(tmp.c_str(), path.c_str()) != 0)
    throw IoError(ErrorKind::write_failed, path, 0, "cannot rename the temporary file into place: " + errno_text());
}

}  // namespace

void set_output_durability(Durability d) { durability.store(d); }
Durability output_durability() { return durability.load(); }

void write_file_atomically(const std::string& path, const FileBody& body) { write_files_atomically({{path, body}}); }

void write_files_atomically(const std::vector<std::pair<std::string, FileBody>>& files) {
  std::vector<std::string> temporaries;
  try {
    for (const auto& [path, body] : files) {
      temporaries.push_back(create_temporary(path));
      fill_temporary(path, temporaries.back(), body);
    }
    for (std::size_t i = 0; i < files.size(); ++i) {
      rename_into_place(temporaries[i], files[i].first);
      temporaries[i].clear();  // renamed: nothing left to remove
    }
    if (output_durability() == Durability::synced)
      for (const auto& [path, body] : files) sync_path(directory_of(path));  // the renames themselves
  } catch (...) {
    for (const auto& tmp : temporaries)
      if (!tmp.empty()) std::remove(tmp.c_str());
    throw;
  }
}

}  // namespace cmx::io
