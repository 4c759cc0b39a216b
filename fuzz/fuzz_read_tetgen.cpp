// libFuzzer target: the TetGen reader. The input is split at the first NUL byte into the .node
// and the .ele text (no NUL: the same bytes serve as both).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "io/io_error.hpp"
#include "io/read_mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const auto split = bytes.find('\0');
  const auto node = split == std::string_view::npos ? bytes : bytes.substr(0, split);
  const auto ele = split == std::string_view::npos ? bytes : bytes.substr(split + 1);
  try {
    (void)cmx::io::read_tetgen(node, "fuzz.node", ele, "fuzz.ele");
  } catch (const cmx::io::IoError&) {
  }
  return 0;
}
