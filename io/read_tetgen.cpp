// TetGen .node/.ele reader. .node: "n dim nattr nmarker" then "index x y z [attrs] [marker]";
// .ele: "m nodes_per_tet nattr" then "index a b c d [more nodes] [attrs]". '#' comments. The first
// index in .node decides whether indices are 0- or 1-based (TetGen's -z switch); node indices must
// then be consecutive. Second-order tets (10 nodes) contribute their four corners and their
// mid-edge nodes are dropped (io/second_order.hpp). The orientation convention is detected
// (io/orientation.hpp).
#include <cstdint>

#include "io/orientation.hpp"
#include "io/read_mesh.hpp"
#include "io/scanner.hpp"
#include "io/second_order.hpp"

namespace cmx::io {

TetMeshData read_tetgen(std::string_view node_bytes, const std::string& node_name, std::string_view ele_bytes,
                        const std::string& ele_name, const ReadOptions& options) {
  TetMeshData mesh;
  std::uint64_t base = 0;
  {
    Scanner s(node_bytes, node_name);
    s.set_comment_char('#');
    const auto n = s.count("node count", max_vertices, 8);
    const auto dim = s.unsigned_integer("dimension");
    if (dim != 3) s.fail(ErrorKind::unsupported, "dimension " + std::to_string(dim) + ": only 3D .node files are supported");
    const auto nattr = s.count("attribute count", 1000, 0);
    const auto nmarker = s.unsigned_integer("boundary marker flag");
    if (nmarker > 1) s.fail(ErrorKind::syntax, "the boundary marker flag must be 0 or 1");
    mesh.positions.reserve(std::size_t(n));
    for (std::uint64_t i = 0; i < n; ++i) {
      s.skip_space();
      const std::size_t line = s.line();
      const auto index = s.unsigned_integer("node index");
      if (i == 0) {
        if (index > 1) s.fail(ErrorKind::syntax, "the first node index must be 0 or 1, found " + std::to_string(index));
        base = index;
      } else if (index != base + i) {
        s.fail(ErrorKind::syntax, "node index " + std::to_string(index) + " where " + std::to_string(base + i) + " was expected (indices must be consecutive)");
      }
      Point3 p;
      for (auto& c : p) c = s.rational("node coordinate");
      for (std::uint64_t k = 0; k < nattr; ++k) s.rational("node attribute");
      if (nmarker) s.integer("boundary marker");
      if (s.more_on_line()) s.fail_at(line, ErrorKind::count_mismatch, "node " + std::to_string(index) + " has more fields than the header announces");
      mesh.positions.push_back(std::move(p));
    }
  }
  std::vector<std::size_t> tet_lines;
  HigherOrderNodes higher_order;
  {
    Scanner s(ele_bytes, ele_name);
    s.set_comment_char('#');
    const auto m = s.count("tetrahedron count", max_tets, 10);
    const auto per = s.unsigned_integer("nodes per tetrahedron");
    if (per != 4 && per != 10) s.fail(ErrorKind::non_tet_cell, std::to_string(per) + " nodes per element: only 4- and 10-node tetrahedra are supported");
    const auto nattr = s.count("attribute count", 1000, 0);
    mesh.tets.reserve(std::size_t(m));
    for (std::uint64_t i = 0; i < m; ++i) {
      s.skip_space();
      const std::size_t line = s.line();
      s.unsigned_integer("tetrahedron index");
      Tet t{};
      for (std::uint64_t k = 0; k < per; ++k) {
        const auto v = s.unsigned_integer("node index");
        if (v < base || v - base >= mesh.positions.size())
          s.fail(ErrorKind::index_out_of_range, "node index " + std::to_string(v) + " out of range (" + std::to_string(mesh.positions.size()) +
                                                    " nodes, numbered from " + std::to_string(base) + ")");
        if (k < 4) t[k] = std::uint32_t(v - base);
        else higher_order.add(std::uint32_t(v - base));
      }
      for (std::uint64_t k = 0; k < nattr; ++k) s.rational("region attribute");
      if (s.more_on_line()) s.fail_at(line, ErrorKind::count_mismatch, "tetrahedron line has more fields than the header announces");
      mesh.tets.push_back(t);
      tet_lines.push_back(line);
    }
  }
  higher_order.drop_unused(mesh);
  validate_and_orient(mesh, options, ele_name, tet_lines);
  return mesh;
}

}  // namespace cmx::io
