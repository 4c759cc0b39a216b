// TetGen .node/.ele writer: both files, 0-based, no attributes or markers.
#include "io/atomic_file.hpp"
#include "io/read_mesh.hpp"
#include "io/write_mesh.hpp"

namespace cmx::io {

void write_tetgen(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets) {
  const auto paths = tetgen_paths(path);
  detail::check_writable(path, points, tets);
  const FileBody node = [&](std::ostream& out) {
    out << "# TetGen nodes written by cmx, 0-based\n" << points.size() << " 3 0 0\n";
    for (std::size_t i = 0; i < points.size(); ++i) {
      out << i << ' ';
      detail::write_point(out, points[i]);
      out << '\n';
    }
  };
  const FileBody ele = [&](std::ostream& out) {
    out << "# TetGen tetrahedra written by cmx, 0-based\n" << tets.size() << " 4 0\n";
    for (std::size_t i = 0; i < tets.size(); ++i)
      out << i << ' ' << tets[i][0] << ' ' << tets[i][1] << ' ' << tets[i][2] << ' ' << tets[i][3] << '\n';
  };
  write_files_atomically({{paths.node, node}, {paths.ele, ele}});
}

}  // namespace cmx::io
