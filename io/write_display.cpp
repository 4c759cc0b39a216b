// The writers of display formats: VTU, legacy VTK 4.2, Medit, Gmsh 2.2 (all ASCII, doubles with
// 17 significant digits), and the dispatch by extension.
#include <charconv>
#include <cmath>

#include "arith/rounding.hpp"
#include "io/atomic_file.hpp"
#include "io/io_error.hpp"
#include "io/scanner.hpp"
#include "io/write_mesh.hpp"

namespace cmx::io {

std::string format_double(double x) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, 17);
  return std::string(buf, r.ptr);
}

std::vector<DoublePoint> nearest_doubles(const std::vector<Point3>& positions) {
  std::vector<DoublePoint> out;
  out.reserve(positions.size());
  for (const auto& p : positions) out.push_back({to_double(p[0]), to_double(p[1]), to_double(p[2])});
  return out;
}

void detail::check_writable(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets) {
  for (std::size_t i = 0; i < points.size(); ++i)
    for (double c : points[i])
      if (!std::isfinite(c))
        throw IoError(ErrorKind::not_finite, path, 0, "point " + std::to_string(i) + " has a non-finite coordinate");
  for (std::size_t i = 0; i < tets.size(); ++i)
    for (auto v : tets[i])
      if (v >= points.size())
        throw IoError(ErrorKind::index_out_of_range, path, 0,
                      "tet " + std::to_string(i) + " uses vertex " + std::to_string(v) + " of " + std::to_string(points.size()));
}

namespace {

void write_point(std::ostream& out, const DoublePoint& p) {
  out << format_double(p[0]) << ' ' << format_double(p[1]) << ' ' << format_double(p[2]);
}

}  // namespace

void write_vtu(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets) {
  detail::check_writable(path, points, tets);
  write_file_atomically(path, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
           "  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << points.size() << "\" NumberOfCells=\"" << tets.size() << "\">\n"
        << "      <Points>\n        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const auto& p : points) {
      out << "          ";
      write_point(out, p);
      out << '\n';
    }
    out << "        </DataArray>\n      </Points>\n      <Cells>\n"
           "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const auto& t : tets) out << "          " << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << t[3] << '\n';
    out << "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < tets.size(); ++i) out << "          " << 4 * (i + 1) << '\n';
    out << "        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < tets.size(); ++i) out << "          10\n";
    out << "        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  });
}

void write_vtk(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets) {
  detail::check_writable(path, points, tets);
  write_file_atomically(path, [&](std::ostream& out) {
    out << "# vtk DataFile Version 4.2\ncmx tetrahedral mesh\nASCII\nDATASET UNSTRUCTURED_GRID\n";
    out << "POINTS " << points.size() << " double\n";
    for (const auto& p : points) {
      write_point(out, p);
      out << '\n';
    }
    out << "CELLS " << tets.size() << ' ' << 5 * tets.size() << '\n';
    for (const auto& t : tets) out << "4 " << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << t[3] << '\n';
    out << "CELL_TYPES " << tets.size() << '\n';
    for (std::size_t i = 0; i < tets.size(); ++i) out << "10\n";
  });
}

void write_medit(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets) {
  detail::check_writable(path, points, tets);
  write_file_atomically(path, [&](std::ostream& out) {
    out << "MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n" << points.size() << '\n';
    for (const auto& p : points) {
      write_point(out, p);
      out << " 0\n";
    }
    out << "\nTetrahedra\n" << tets.size() << '\n';
    for (const auto& t : tets) out << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << ' ' << t[3] + 1 << " 1\n";
    out << "\nEnd\n";
  });
}

void write_gmsh(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets) {
  detail::check_writable(path, points, tets);
  write_file_atomically(path, [&](std::ostream& out) {
    out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" << points.size() << '\n';
    for (std::size_t i = 0; i < points.size(); ++i) {
      out << i + 1 << ' ';
      write_point(out, points[i]);
      out << '\n';
    }
    out << "$EndNodes\n$Elements\n" << tets.size() << '\n';
    // Two tags (physical 1, elementary 1): what Gmsh itself writes and every reader expects.
    for (std::size_t i = 0; i < tets.size(); ++i) {
      const auto& t = tets[i];
      out << i + 1 << " 4 2 1 1 " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << ' ' << t[3] + 1 << '\n';
    }
    out << "$EndElements\n";
  });
}

bool is_writable_mesh_path(const std::string& path) {
  const auto ext = extension_of(path);
  return ext == "ovm" || ext == "vtu" || ext == "vtk" || ext == "mesh" || ext == "msh";
}

void write_tet_mesh(const std::string& path, const TetMeshData& mesh) {
  const auto ext = extension_of(path);
  if (!is_writable_mesh_path(path))
    throw IoError(ErrorKind::unsupported, path, 0, "cannot write format '." + ext + "' (known: .ovm .vtu .vtk .mesh .msh)");
  const auto points = nearest_doubles(mesh.positions);
  if (ext == "ovm") write_ovm(path, points, mesh.tets, &mesh.positions, mesh.vertex_string_properties);
  else if (ext == "vtu") write_vtu(path, points, mesh.tets);
  else if (ext == "vtk") write_vtk(path, points, mesh.tets);
  else if (ext == "mesh") write_medit(path, points, mesh.tets);
  else write_gmsh(path, points, mesh.tets);
}

}  // namespace cmx::io
