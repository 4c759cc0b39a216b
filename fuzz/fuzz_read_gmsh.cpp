// libFuzzer target: the gmsh reader must reject any malformed input with an IoError, never crash,
// hang or allocate without bound.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "io/io_error.hpp"
#include "io/read_mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    (void)cmx::io::read_gmsh(bytes, "fuzz.gmsh");
  } catch (const cmx::io::IoError&) {
  }
  return 0;
}
