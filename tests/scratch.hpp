#pragma once
// One scratch directory per test process, under TMPDIR (or /tmp), removed with everything in it
// when the process exits: the temporary files of a test, and the files a program under test
// writes next to them (out.vtk.json beside out.vtk), leave nothing behind. CMX_TEST_KEEP_TEMP=1
// keeps it for a look after a failure. A process killed by a signal keeps it too (static
// destructors do not run).
#include <stdlib.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace cmx::test {

// mkdtemp on "<dir>/<stem>XXXXXX"; throws when it fails.
inline std::filesystem::path make_unique_directory(const std::filesystem::path& dir,
                                                   const std::string& stem) {
  std::string pattern = (dir / (stem + "XXXXXX")).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  if (mkdtemp(name.data()) == nullptr) throw std::runtime_error("mkdtemp failed on " + pattern);
  return name.data();
}

inline const std::filesystem::path& scratch_directory() {
  struct Scratch {
    std::filesystem::path path;
    Scratch() {
      const char* tmp = std::getenv("TMPDIR");
      path = make_unique_directory(tmp && *tmp ? tmp : "/tmp", "cmx_test_");
    }
    Scratch(const Scratch&) = delete;
    Scratch& operator=(const Scratch&) = delete;
    ~Scratch() {
      const char* keep = std::getenv("CMX_TEST_KEEP_TEMP");
      if (keep && *keep && std::string_view(keep) != "0") return;
      std::error_code ignored;  // a test made something unremovable: nothing to report at exit
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Scratch scratch;
  return scratch.path;
}

}  // namespace cmx::test
