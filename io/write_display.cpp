// The writers of display formats VTU, legacy VTK 4.2 and Medit (all ASCII, doubles with 17
// significant digits), the checks every display writer shares, and the dispatch by extension.
// Gmsh: write_gmsh.cpp; TetGen: write_tetgen.cpp.
#include <cctype>
#include <charconv>
#include <cmath>
#include <set>

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

void detail::write_point(std::ostream& out, const DoublePoint& p) {
  out << format_double(p[0]) << ' ' << format_double(p[1]) << ' ' << format_double(p[2]);
}

namespace {

void check_field_name(const std::string& path, const std::string& name, std::set<std::string>& seen) {
  bool plain = !name.empty();
  for (char c : name) plain = plain && (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-');
  if (!plain) throw IoError(ErrorKind::syntax, path, 0, "field name " + quoted(name) + " must be non-empty and made of [A-Za-z0-9_.-]");
  if (!seen.insert(name).second) throw IoError(ErrorKind::syntax, path, 0, "field name " + quoted(name) + " is given twice");
}

void check_length(const std::string& path, const std::string& name, std::size_t have, std::size_t want, const char* per) {
  if (have != want)
    throw IoError(ErrorKind::mismatch, path, 0,
                  "field " + quoted(name) + " has " + std::to_string(have) + " values for " + std::to_string(want) + " " + per);
}

}  // namespace

void detail::check_fields(const std::string& path, std::size_t points, std::size_t tets, const DisplayFields& fields) {
  std::set<std::string> seen;
  for (const auto& f : fields.point_vectors) {
    check_field_name(path, f.name, seen);
    check_length(path, f.name, f.values.size(), points, "points");
    for (const auto& v : f.values)
      if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
        throw IoError(ErrorKind::not_finite, path, 0, "field " + quoted(f.name) + " has a non-finite value");
  }
  for (const auto& f : fields.cell_scalars) {
    check_field_name(path, f.name, seen);
    check_length(path, f.name, f.values.size(), tets, "tets");
    for (double v : f.values) {
      if (!std::isfinite(v)) throw IoError(ErrorKind::not_finite, path, 0, "field " + quoted(f.name) + " has a non-finite value");
      if (f.type == ScalarType::uint8 && !(v >= 0 && v <= 255 && v == std::floor(v)))
        throw IoError(ErrorKind::mismatch, path, 0, "field " + quoted(f.name) + " is uint8 but holds " + format_double(v));
    }
  }
}

namespace {

// A field value as text: integers for uint8 fields, 17 significant digits otherwise.
std::string scalar_text(const CellScalarField& f, double v) {
  return f.type == ScalarType::uint8 ? std::to_string(int(v)) : format_double(v);
}

void write_vtu_fields(std::ostream& out, const DisplayFields& fields) {
  if (!fields.point_vectors.empty()) {
    out << "      <PointData Vectors=\"" << fields.point_vectors.front().name << "\">\n";
    for (const auto& f : fields.point_vectors) {
      out << "        <DataArray type=\"Float64\" Name=\"" << f.name << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (const auto& v : f.values) {
        out << "          ";
        detail::write_point(out, v);
        out << '\n';
      }
      out << "        </DataArray>\n";
    }
    out << "      </PointData>\n";
  }
  if (fields.cell_scalars.empty()) return;
  out << "      <CellData Scalars=\"" << fields.cell_scalars.front().name << "\">\n";
  for (const auto& f : fields.cell_scalars) {
    out << "        <DataArray type=\"" << (f.type == ScalarType::uint8 ? "UInt8" : "Float64") << "\" Name=\"" << f.name
        << "\" format=\"ascii\">\n";
    for (double v : f.values) out << "          " << scalar_text(f, v) << '\n';
    out << "        </DataArray>\n";
  }
  out << "      </CellData>\n";
}

void write_vtk_fields(std::ostream& out, std::size_t points, std::size_t tets, const DisplayFields& fields) {
  if (!fields.point_vectors.empty()) out << "POINT_DATA " << points << '\n';
  for (const auto& f : fields.point_vectors) {
    out << "VECTORS " << f.name << " double\n";
    for (const auto& v : f.values) {
      detail::write_point(out, v);
      out << '\n';
    }
  }
  if (!fields.cell_scalars.empty()) out << "CELL_DATA " << tets << '\n';
  for (const auto& f : fields.cell_scalars) {
    out << "SCALARS " << f.name << (f.type == ScalarType::uint8 ? " unsigned_char" : " double") << " 1\nLOOKUP_TABLE default\n";
    for (double v : f.values) out << scalar_text(f, v) << '\n';
  }
}

}  // namespace

void write_vtu(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets,
               const DisplayFields& fields) {
  detail::check_writable(path, points, tets);
  detail::check_fields(path, points.size(), tets.size(), fields);
  write_file_atomically(path, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
           "  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << points.size() << "\" NumberOfCells=\"" << tets.size() << "\">\n";
    write_vtu_fields(out, fields);
    out << "      <Points>\n        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const auto& p : points) {
      out << "          ";
      detail::write_point(out, p);
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

void write_vtk(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets,
               const DisplayFields& fields) {
  detail::check_writable(path, points, tets);
  detail::check_fields(path, points.size(), tets.size(), fields);
  write_file_atomically(path, [&](std::ostream& out) {
    out << "# vtk DataFile Version 4.2\ncmx tetrahedral mesh\nASCII\nDATASET UNSTRUCTURED_GRID\n";
    out << "POINTS " << points.size() << " double\n";
    for (const auto& p : points) {
      detail::write_point(out, p);
      out << '\n';
    }
    out << "CELLS " << tets.size() << ' ' << 5 * tets.size() << '\n';
    for (const auto& t : tets) out << "4 " << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << t[3] << '\n';
    out << "CELL_TYPES " << tets.size() << '\n';
    for (std::size_t i = 0; i < tets.size(); ++i) out << "10\n";
    write_vtk_fields(out, points.size(), tets.size(), fields);
  });
}

void write_medit(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets) {
  detail::check_writable(path, points, tets);
  write_file_atomically(path, [&](std::ostream& out) {
    out << "MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n" << points.size() << '\n';
    for (const auto& p : points) {
      detail::write_point(out, p);
      out << " 0\n";
    }
    out << "\nTetrahedra\n" << tets.size() << '\n';
    for (const auto& t : tets) out << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << ' ' << t[3] + 1 << " 1\n";
    out << "\nEnd\n";
  });
}

bool is_display_mesh_path(const std::string& path) {
  const auto ext = extension_of(path);
  return ext == "vtu" || ext == "vtk" || ext == "msh" || ext == "mesh" || ext == "node" || ext == "ele";
}

bool carries_display_fields(const std::string& path) {
  const auto ext = extension_of(path);
  return ext == "vtu" || ext == "vtk" || ext == "msh";
}

void write_display_mesh(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets,
                        const DisplayFields& fields) {
  const auto ext = extension_of(path);
  if (ext == "vtu") write_vtu(path, points, tets, fields);
  else if (ext == "vtk") write_vtk(path, points, tets, fields);
  else if (ext == "msh") write_gmsh41(path, points, tets, fields);
  else if (ext == "mesh") write_medit(path, points, tets);
  else if (ext == "node" || ext == "ele") write_tetgen(path, points, tets);
  else
    throw IoError(ErrorKind::unsupported, path, 0, "cannot write display format '." + ext + "' (known: .vtu .vtk .msh .mesh .node/.ele)");
}

bool is_writable_mesh_path(const std::string& path) { return extension_of(path) == "ovm" || is_display_mesh_path(path); }

void write_tet_mesh(const std::string& path, const TetMeshData& mesh) {
  if (!is_writable_mesh_path(path))
    throw IoError(ErrorKind::unsupported, path, 0,
                  "cannot write format '." + extension_of(path) + "' (known: .ovm .vtu .vtk .mesh .msh .node/.ele)");
  const auto points = nearest_doubles(mesh.positions);
  if (extension_of(path) == "ovm") write_ovm(path, points, mesh.tets, &mesh.positions, mesh.vertex_string_properties);
  else write_display_mesh(path, points, mesh.tets);
}

}  // namespace cmx::io
