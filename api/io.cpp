// cmx/io.hpp: mesh files by extension over io/read_mesh.hpp, io/write_mesh.hpp and io/tmap.hpp.
#include "cmx/io.hpp"

#include <cmath>

#include "arith/rational.hpp"
#include "arith/rounding.hpp"
#include "io/io_error.hpp"
#include "io/read_mesh.hpp"
#include "io/scanner.hpp"
#include "io/tmap.hpp"
#include "io/write_mesh.hpp"

namespace cmx {
namespace {

constexpr const char* known_formats = "known: .ovm .vtu .vtk .mesh .msh .node/.ele .tmap";

void to_text(const std::vector<cmx::Point3>& exact, std::vector<ExactPoint3>& text,
             std::vector<Point3d>& doubles) {
  text.resize(exact.size());
  doubles.resize(exact.size());
  for (std::size_t i = 0; i < exact.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k) {
      text[i][k] = to_string(exact[i][k]);
      doubles[i][k] = to_double(exact[i][k]);
    }
}

// The exact positions of `text` when not empty, else of `doubles` (then NaN and infinities are
// refused); when both are given their sizes must agree. `what` names the points in messages.
std::vector<cmx::Point3> exact_positions(const std::string& path, const char* what,
                                        const std::vector<ExactPoint3>& text,
                                        const std::vector<Point3d>& doubles) {
  if (!text.empty() && !doubles.empty() && text.size() != doubles.size())
    throw Error(path + ": " + what + " has " + std::to_string(doubles.size()) + " doubles but " +
                std::to_string(text.size()) + " exact points");
  const std::size_t n = text.empty() ? doubles.size() : text.size();
  std::vector<cmx::Point3> out(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < 3; ++k) {
      const std::string where =
          path + ": " + what + " " + std::to_string(i) + ", coordinate " + char('x' + k);
      if (text.empty()) {
        const double x = doubles[i][k];
        if (!std::isfinite(x)) throw Error(where + " is " + (std::isnan(x) ? "NaN" : "infinite"));
        out[i][k] = rational_from_double(x);
        continue;
      }
      std::string why;
      const auto q = parse_rational(text[i][k], &why);
      if (!q)
        throw Error(where + " '" + text[i][k] + "' is not an exact number" +
                    (why.empty() ? "" : " (" + why + ")"));
      out[i][k] = *q;
    }
  return out;
}

void write_file(const std::string& path, const Mesh& mesh) {
  const std::string ext = io::extension_of(path);
  std::vector<cmx::Point3> exact = exact_positions(path, "point", mesh.points_exact, mesh.points);
  if (ext == "tmap") {
    io::TetMap map{std::move(exact), exact_positions(path, "target point", mesh.target_exact, mesh.target),
                   mesh.tets};
    if (map.target.size() != map.source.size())
      throw Error(path + ": a .tmap needs one target point per point (" + std::to_string(map.source.size()) +
                  " points, " + std::to_string(map.target.size()) + " target points)");
    io::write_tmap(path, map);
    return;
  }
  const std::vector<io::DoublePoint> doubles = mesh.points.empty() ? io::nearest_doubles(exact) : mesh.points;
  if (ext == "ovm")
    io::write_ovm(path, doubles, mesh.tets, mesh.points_exact.empty() ? nullptr : &exact);
  else if (io::is_display_mesh_path(path))
    io::write_display_mesh(path, doubles, mesh.tets);
  else
    throw Error(path + ": cannot write format '." + ext + "' (" + known_formats + ")");
}

}  // namespace

Mesh read(const std::string& path) {
  Mesh mesh;
  try {
    if (io::is_map_path(path)) {
      io::TetMap map = io::read_tmap(path);
      to_text(map.source, mesh.points_exact, mesh.points);
      to_text(map.target, mesh.target_exact, mesh.target);
      mesh.tets = std::move(map.tets);
      return mesh;
    }
    if (!io::is_readable_mesh_path(path))
      throw Error(path + ": unknown mesh format '." + io::extension_of(path) + "' (" + known_formats + ")");
    io::TetMeshData data = io::read_tet_mesh(path);
    to_text(data.positions, mesh.points_exact, mesh.points);
    mesh.tets = std::move(data.tets);
  } catch (const io::IoError& e) {
    throw Error(e.what());
  }
  return mesh;
}

void write(const std::string& path, const Mesh& mesh) {
  try {
    write_file(path, mesh);
  } catch (const io::IoError& e) {
    throw Error(e.what());
  }
}

}  // namespace cmx
