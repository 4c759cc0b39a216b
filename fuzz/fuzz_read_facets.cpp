// libFuzzer target: the facet-list reader (io/read_facets.hpp), and on what it accepts the
// orientation and ball check that `cmx info` runs on it: any bytes either give an IoError or a
// list whose ids are in range, which the topology layer must take without crashing.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "io/io_error.hpp"
#include "io/read_facets.hpp"
#include "topology/ball_check.hpp"
#include "topology/coherent_orientation.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  cmx::io::FacetList list;
  try {
    list = cmx::io::read_facet_list(bytes, "fuzz.facets");
  } catch (const cmx::io::IoError&) {
    return 0;
  }
  if (list.vertex_count > 100000) return 0;  // ids are dense: a huge count means a huge file
  for (const auto& t : list.tets)
    for (std::uint32_t v : t)
      if (v >= list.vertex_count) std::abort();
  cmx::topology::TetMesh mesh(list.vertex_count, std::span<const cmx::topology::TetIndices>(list.tets));
  if (mesh.skipped_tets() != 0) std::abort();
  if (cmx::topology::orient_coherently(mesh).ok) (void)cmx::topology::check_ball(mesh);
  return 0;
}
