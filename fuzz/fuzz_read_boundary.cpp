// libFuzzer target: the boundary-position (`index x y z`) reader and the tmap reader.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "io/boundary.hpp"
#include "io/io_error.hpp"
#include "io/tmap.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    (void)cmx::io::parse_boundary_positions(bytes, "fuzz.txt", 1000);
  } catch (const cmx::io::IoError&) {
  }
  try {
    (void)cmx::io::parse_tmap(bytes, "fuzz.tmap");
  } catch (const cmx::io::IoError&) {
  }
  return 0;
}
