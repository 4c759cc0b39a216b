// Legacy VTK reader (UNSTRUCTURED_GRID only). Handles the 4.2 layout (`CELLS n size` followed by
// "k i0 .. ik-1" per cell) and the 5.1 layout (`CELLS n+1 size`, `OFFSETS type`, `CONNECTIVITY
// type`), ASCII and BINARY (big-endian, as the format prescribes). Point and cell data sections
// are ignored. Cell types: io/vtk_cell_types.hpp. VTK's tetra convention is det[b-a, c-a, d-a] > 0,
// but files in the wild (Galaxy Maps) list tets negatively, so the sign is detected
// (io/orientation.hpp).
#include <cmath>
#include <cstdint>

#include "io/binary_numbers.hpp"
#include "io/orientation.hpp"
#include "io/read_mesh.hpp"
#include "io/scanner.hpp"
#include "io/second_order.hpp"
#include "io/vtk_cell_types.hpp"

namespace cmx::io {
namespace {

struct NumberType {
  int size = 0;  // bytes in binary files
  bool real = false;
  bool is_signed = true;
};

NumberType number_type(Scanner& s, std::string_view t) {
  if (t == "double") return {8, true, true};
  if (t == "float") return {4, true, true};
  if (t == "int" || t == "vtktypeint32") return {4, false, true};
  if (t == "unsigned_int" || t == "vtktypeuint32") return {4, false, false};
  if (t == "long" || t == "vtktypeint64" || t == "vtkidtype") return {8, false, true};
  if (t == "unsigned_long" || t == "vtktypeuint64") return {8, false, false};
  if (t == "short") return {2, false, true};
  if (t == "unsigned_short") return {2, false, false};
  s.fail(ErrorKind::unsupported, "unsupported VTK data type " + quoted(t));
}

class Numbers {
 public:
  Numbers(Scanner& s, bool binary) : s_(s), binary_(binary) {}

  Rational real(const NumberType& type, std::string_view what) {
    if (!binary_) return s_.rational(what);
    const char* p = s_.bytes(std::size_t(type.size), what).data();
    double d;
    if (type.real) d = type.size == 8 ? load_double(p, true) : double(load_float(p, true));
    else return Rational(std::to_string(type.is_signed ? load_signed(p, type.size, true) : std::int64_t(load_unsigned(p, type.size, true))));
    if (!std::isfinite(d)) s_.fail(ErrorKind::not_finite, std::string(what) + " is not finite");
    return rational_from_double(d);
  }

  std::uint64_t index(const NumberType& type, std::string_view what) {
    if (!binary_) return s_.unsigned_integer(what);
    if (type.real) s_.fail(ErrorKind::syntax, std::string(what) + " stored as a floating-point type");
    const char* p = s_.bytes(std::size_t(type.size), what).data();
    if (type.is_signed) {
      const auto v = load_signed(p, type.size, true);
      if (v < 0) s_.fail(ErrorKind::index_out_of_range, std::string(what) + " " + std::to_string(v) + " is negative");
      return std::uint64_t(v);
    }
    return load_unsigned(p, type.size, true);
  }

 private:
  Scanner& s_;
  bool binary_;
};

}  // namespace

TetMeshData read_vtk(std::string_view bytes, const std::string& name, const ReadOptions& options) {
  Scanner s(bytes, name);
  const auto magic = s.rest_of_line();
  if (magic.substr(0, 5) != "# vtk")
    s.fail_at(1, ErrorKind::syntax, "not a legacy VTK file: the first line must start with '# vtk DataFile Version'");
  int major = 2;
  if (const auto v = magic.find("Version"); v != std::string_view::npos) {
    const auto digits = magic.substr(v + 7);
    const auto d = digits.find_first_of("0123456789");
    if (d != std::string_view::npos) major = digits[d] - '0';
  }
  s.rest_of_line();  // title
  const auto mode = s.token("ASCII or BINARY");
  if (mode != "ASCII" && mode != "BINARY") s.fail(ErrorKind::syntax, "expected ASCII or BINARY, found " + quoted(mode));
  const bool binary = mode == "BINARY";
  if (const auto t = s.token("DATASET"); t != "DATASET") s.fail(ErrorKind::syntax, "expected 'DATASET', found " + quoted(t));
  if (const auto t = s.token("dataset type"); t != "UNSTRUCTURED_GRID")
    s.fail(ErrorKind::unsupported, "only DATASET UNSTRUCTURED_GRID is supported, found " + quoted(t));

  Numbers numbers(s, binary);
  TetMeshData mesh;
  bool have_points = false, have_cells = false, have_types = false;
  std::uint64_t npoints = 0;
  std::vector<std::uint64_t> offsets;      // cell c uses connectivity[offsets[c] .. offsets[c+1])
  std::vector<std::uint32_t> connectivity;
  std::vector<std::size_t> cell_lines;
  std::vector<std::size_t> tet_lines;
  HigherOrderNodes higher_order;

  const auto read_connectivity_index = [&](const NumberType& type) {
    const auto v = numbers.index(type, "point index");
    if (v > max_vertices) s.fail(ErrorKind::index_out_of_range, "point index " + std::to_string(v) + " is out of range");
    connectivity.push_back(std::uint32_t(v));
  };

  while (s.skip_space()) {
    const std::size_t header_line = s.line();
    const auto keyword = s.token("section keyword");
    if (keyword == "POINTS") {
      if (have_points) s.fail(ErrorKind::syntax, "a second POINTS section");
      npoints = s.count("point count", max_vertices, binary ? 12 : 6);
      const auto type = number_type(s, s.token("point data type"));
      if (binary) s.rest_of_line();
      mesh.positions.reserve(std::size_t(npoints));
      for (std::uint64_t i = 0; i < npoints; ++i) {
        Point3 p;
        for (auto& c : p) c = numbers.real(type, "point coordinate");
        mesh.positions.push_back(std::move(p));
      }
      have_points = true;
    } else if (keyword == "METADATA") {
      // VTK 9 metadata (component names, information keys): text up to an empty line.
      s.rest_of_line();
      while (!s.at_end()) {
        const auto line = s.rest_of_line();
        if (line.find_first_not_of(" \t\r") == std::string_view::npos) break;
      }
    } else if (keyword == "CELLS") {
      if (have_cells) s.fail(ErrorKind::syntax, "a second CELLS section");
      const auto n = s.count("cell count", max_tets + 1, binary ? 4 : 2);
      const auto size = s.count("cell list size", UINT64_MAX / 8, binary ? 4 : 2);
      if (major >= 5) {
        // 5.1: n is the number of offsets (cells + 1), size the connectivity length.
        for (int part = 0; part < 2; ++part) {
          s.skip_space();
          const auto kw = s.token(part == 0 ? "OFFSETS" : "CONNECTIVITY");
          if (kw != (part == 0 ? "OFFSETS" : "CONNECTIVITY"))
            s.fail(ErrorKind::syntax, std::string("expected ") + (part == 0 ? "OFFSETS" : "CONNECTIVITY") + " (VTK 5.x cell layout), found " + quoted(kw));
          const auto type = number_type(s, s.token("offset type"));
          if (binary) s.rest_of_line();
          if (part == 0) {
            offsets.reserve(plausible_count(n, s.remaining(), binary ? std::size_t(type.size) : 2));
            for (std::uint64_t i = 0; i < n; ++i) {
              offsets.push_back(numbers.index(type, "cell offset"));
              if (i == 0 ? offsets.back() != 0 : offsets.back() < offsets[i - 1])
                s.fail(ErrorKind::syntax, "cell offsets must start at 0 and not decrease");
            }
            if (n == 0 || offsets.back() != size)
              s.fail(ErrorKind::count_mismatch, "the last cell offset must equal the CELLS connectivity size " + std::to_string(size));
          } else {
            connectivity.reserve(plausible_count(size, s.remaining(), binary ? std::size_t(type.size) : 2));
            std::size_t cell = 0;
            for (std::uint64_t i = 0; i < size; ++i) {
              while (cell + 1 < offsets.size() && offsets[cell] == i) {
                cell_lines.push_back(binary ? header_line : (s.skip_space(), s.line()));
                ++cell;
              }
              read_connectivity_index(type);
            }
            while (cell_lines.size() + 1 < offsets.size()) cell_lines.push_back(s.line());
          }
        }
      } else {
        const NumberType int32{4, false, true};
        offsets.reserve(plausible_count(n, s.remaining(), binary ? 8 : 4) + 1);
        connectivity.reserve(plausible_count(size, s.remaining(), binary ? 4 : 2));
        if (binary) s.rest_of_line();
        offsets.push_back(0);
        for (std::uint64_t c = 0; c < n; ++c) {
          if (!binary) s.skip_space();
          cell_lines.push_back(binary ? header_line : s.line());
          const auto k = numbers.index(int32, "cell size");
          if (connectivity.size() + k > size)
            s.fail(ErrorKind::count_mismatch, "cell " + std::to_string(c) + " runs past the CELLS size " + std::to_string(size));
          for (std::uint64_t j = 0; j < k; ++j) read_connectivity_index(int32);
          offsets.push_back(connectivity.size());
        }
        if (connectivity.size() + n != size)
          s.fail_at(header_line, ErrorKind::count_mismatch,
                    "CELLS size " + std::to_string(size) + " does not match the " + std::to_string(connectivity.size() + n) + " numbers listed");
      }
      have_cells = true;
    } else if (keyword == "CELL_TYPES") {
      if (!have_cells) s.fail(ErrorKind::syntax, "CELL_TYPES before CELLS");
      if (have_types) s.fail(ErrorKind::syntax, "a second CELL_TYPES section");
      const auto n = s.count("cell type count", max_tets, binary ? 4 : 2);
      if (n + 1 != offsets.size())
        s.fail(ErrorKind::count_mismatch, "CELL_TYPES has " + std::to_string(n) + " entries but CELLS has " + std::to_string(offsets.size() - 1) + " cells");
      if (binary) s.rest_of_line();
      const NumberType int32{4, false, true};
      mesh.tets.reserve(plausible_count(n, connectivity.size(), 4));
      for (std::uint64_t c = 0; c < n; ++c) {
        const auto type = std::int64_t(numbers.index(int32, "cell type"));
        const auto kind = vtk_cell_kind(type);
        if (kind == VtkCellKind::lower_dimensional) continue;
        if (kind == VtkCellKind::refused) s.fail_at(cell_lines[c], ErrorKind::non_tet_cell, vtk_refusal(c, type));
        const std::uint64_t nodes = kind == VtkCellKind::tetrahedron ? 4 : 10;
        const auto k = offsets[c + 1] - offsets[c];
        if (k != nodes)
          s.fail_at(cell_lines[c], ErrorKind::count_mismatch,
                    "cell " + std::to_string(c) + " of VTK type " + std::to_string(type) + " has " + std::to_string(k) + " points, not " +
                        std::to_string(nodes));
        const auto* v = &connectivity[std::size_t(offsets[c])];
        mesh.tets.push_back({v[0], v[1], v[2], v[3]});
        for (std::uint64_t j = 4; j < nodes; ++j) higher_order.add(v[j]);
        tet_lines.push_back(cell_lines[c]);
      }
      have_types = true;
    } else if (keyword == "POINT_DATA" || keyword == "CELL_DATA" || keyword == "FIELD") {
      break;  // attributes are not part of the mesh
    } else {
      s.fail(ErrorKind::syntax, "unexpected keyword " + quoted(keyword) + " in an UNSTRUCTURED_GRID");
    }
  }
  if (!have_points) s.fail(ErrorKind::truncated, "no POINTS section");
  if (!have_cells) s.fail(ErrorKind::truncated, "no CELLS section");
  if (!have_types) s.fail(ErrorKind::truncated, "no CELL_TYPES section");
  for (std::size_t c = 0; c + 1 < offsets.size(); ++c)
    for (auto j = offsets[c]; j < offsets[c + 1]; ++j)
      if (connectivity[std::size_t(j)] >= npoints)
        s.fail_at(cell_lines[c], ErrorKind::index_out_of_range,
                  "cell " + std::to_string(c) + " uses point " + std::to_string(connectivity[std::size_t(j)]) + " but there are " + std::to_string(npoints) + " points");
  higher_order.drop_unused(mesh);
  validate_and_orient(mesh, options, name, tet_lines);
  return mesh;
}

}  // namespace cmx::io
