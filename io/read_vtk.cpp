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

// The sections of one file, read in order into the mesh; each section a member function.
class VtkReader {
 public:
  VtkReader(std::string_view bytes, const std::string& name) : s_(bytes, name) {}

  TetMeshData read(const ReadOptions& options, const std::string& name) {
    header();
    while (s_.skip_space()) {
      const std::size_t header_line = s_.line();
      const auto keyword = s_.token("section keyword");
      if (keyword == "POINTS") points();
      else if (keyword == "METADATA") metadata();
      else if (keyword == "CELLS") cells(header_line);
      else if (keyword == "CELL_TYPES") cell_types();
      else if (keyword == "POINT_DATA" || keyword == "CELL_DATA" || keyword == "FIELD") break;  // attributes are not part of the mesh
      else s_.fail(ErrorKind::syntax, "unexpected keyword " + quoted(keyword) + " in an UNSTRUCTURED_GRID");
    }
    if (!have_points_) s_.fail(ErrorKind::truncated, "no POINTS section");
    if (!have_cells_) s_.fail(ErrorKind::truncated, "no CELLS section");
    if (!have_types_) s_.fail(ErrorKind::truncated, "no CELL_TYPES section");
    check_point_indices();
    higher_order_.drop_unused(mesh_);
    validate_and_orient(mesh_, options, name, tet_lines_);
    return std::move(mesh_);
  }

 private:
  // "# vtk DataFile Version X.Y", the title, ASCII or BINARY, DATASET UNSTRUCTURED_GRID.
  void header() {
    const auto magic = s_.rest_of_line();
    if (magic.substr(0, 5) != "# vtk")
      s_.fail_at(1, ErrorKind::syntax, "not a legacy VTK file: the first line must start with '# vtk DataFile Version'");
    if (const auto v = magic.find("Version"); v != std::string_view::npos) {
      const auto digits = magic.substr(v + 7);
      const auto d = digits.find_first_of("0123456789");
      if (d != std::string_view::npos) major_ = digits[d] - '0';
    }
    s_.rest_of_line();  // title
    const auto mode = s_.token("ASCII or BINARY");
    if (mode != "ASCII" && mode != "BINARY") s_.fail(ErrorKind::syntax, "expected ASCII or BINARY, found " + quoted(mode));
    binary_ = mode == "BINARY";
    if (const auto t = s_.token("DATASET"); t != "DATASET") s_.fail(ErrorKind::syntax, "expected 'DATASET', found " + quoted(t));
    if (const auto t = s_.token("dataset type"); t != "UNSTRUCTURED_GRID")
      s_.fail(ErrorKind::unsupported, "only DATASET UNSTRUCTURED_GRID is supported, found " + quoted(t));
  }

  void points() {
    if (have_points_) s_.fail(ErrorKind::syntax, "a second POINTS section");
    npoints_ = s_.count("point count", max_vertices, binary_ ? 12 : 6);
    const auto type = number_type(s_, s_.token("point data type"));
    if (binary_) s_.rest_of_line();
    mesh_.positions.reserve(std::size_t(npoints_));
    Numbers numbers(s_, binary_);
    for (std::uint64_t i = 0; i < npoints_; ++i) {
      Point3 p;
      for (auto& c : p) c = numbers.real(type, "point coordinate");
      mesh_.positions.push_back(std::move(p));
    }
    have_points_ = true;
  }

  // VTK 9 metadata (component names, information keys): text up to an empty line.
  void metadata() {
    s_.rest_of_line();
    while (!s_.at_end()) {
      const auto line = s_.rest_of_line();
      if (line.find_first_not_of(" \t\r") == std::string_view::npos) break;
    }
  }

  void connectivity_index(const NumberType& type) {
    const auto v = Numbers(s_, binary_).index(type, "point index");
    if (v > max_vertices) s_.fail(ErrorKind::index_out_of_range, "point index " + std::to_string(v) + " is out of range");
    connectivity_.push_back(std::uint32_t(v));
  }

  void cells(std::size_t header_line) {
    if (have_cells_) s_.fail(ErrorKind::syntax, "a second CELLS section");
    const auto n = s_.count("cell count", max_tets + 1, binary_ ? 4 : 2);
    const auto size = s_.count("cell list size", UINT64_MAX / 8, binary_ ? 4 : 2);
    if (major_ >= 5) cells_51(n, size, header_line);
    else cells_42(n, size, header_line);
    have_cells_ = true;
  }

  // 5.1: n is the number of offsets (cells + 1), size the connectivity length.
  void cells_51(std::uint64_t n, std::uint64_t size, std::size_t header_line) {
    for (int part = 0; part < 2; ++part) {
      const char* keyword = part == 0 ? "OFFSETS" : "CONNECTIVITY";
      s_.skip_space();
      const auto kw = s_.token(keyword);
      if (kw != keyword) s_.fail(ErrorKind::syntax, std::string("expected ") + keyword + " (VTK 5.x cell layout), found " + quoted(kw));
      const auto type = number_type(s_, s_.token("offset type"));
      if (binary_) s_.rest_of_line();
      if (part == 0) offsets_51(n, size, type);
      else connectivity_51(size, type, header_line);
    }
  }

  void offsets_51(std::uint64_t n, std::uint64_t size, const NumberType& type) {
    Numbers numbers(s_, binary_);
    offsets_.reserve(plausible_count(n, s_.remaining(), binary_ ? std::size_t(type.size) : 2));
    for (std::uint64_t i = 0; i < n; ++i) {
      offsets_.push_back(numbers.index(type, "cell offset"));
      if (i == 0 ? offsets_.back() != 0 : offsets_.back() < offsets_[i - 1])
        s_.fail(ErrorKind::syntax, "cell offsets must start at 0 and not decrease");
    }
    if (n == 0 || offsets_.back() != size)
      s_.fail(ErrorKind::count_mismatch, "the last cell offset must equal the CELLS connectivity size " + std::to_string(size));
  }

  void connectivity_51(std::uint64_t size, const NumberType& type, std::size_t header_line) {
    connectivity_.reserve(plausible_count(size, s_.remaining(), binary_ ? std::size_t(type.size) : 2));
    std::size_t cell = 0;
    for (std::uint64_t i = 0; i < size; ++i) {
      while (cell + 1 < offsets_.size() && offsets_[cell] == i) {
        cell_lines_.push_back(binary_ ? header_line : (s_.skip_space(), s_.line()));
        ++cell;
      }
      connectivity_index(type);
    }
    while (cell_lines_.size() + 1 < offsets_.size()) cell_lines_.push_back(s_.line());
  }

  // 4.2: "k i0 .. ik-1" per cell; size counts the k's too.
  void cells_42(std::uint64_t n, std::uint64_t size, std::size_t header_line) {
    const NumberType int32{4, false, true};
    Numbers numbers(s_, binary_);
    offsets_.reserve(plausible_count(n, s_.remaining(), binary_ ? 8 : 4) + 1);
    connectivity_.reserve(plausible_count(size, s_.remaining(), binary_ ? 4 : 2));
    if (binary_) s_.rest_of_line();
    offsets_.push_back(0);
    for (std::uint64_t c = 0; c < n; ++c) {
      if (!binary_) s_.skip_space();
      cell_lines_.push_back(binary_ ? header_line : s_.line());
      const auto k = numbers.index(int32, "cell size");
      if (connectivity_.size() + k > size)
        s_.fail(ErrorKind::count_mismatch, "cell " + std::to_string(c) + " runs past the CELLS size " + std::to_string(size));
      for (std::uint64_t j = 0; j < k; ++j) connectivity_index(int32);
      offsets_.push_back(connectivity_.size());
    }
    if (connectivity_.size() + n != size)
      s_.fail_at(header_line, ErrorKind::count_mismatch,
                 "CELLS size " + std::to_string(size) + " does not match the " + std::to_string(connectivity_.size() + n) + " numbers listed");
  }

  void cell_types() {
    if (!have_cells_) s_.fail(ErrorKind::syntax, "CELL_TYPES before CELLS");
    if (have_types_) s_.fail(ErrorKind::syntax, "a second CELL_TYPES section");
    const auto n = s_.count("cell type count", max_tets, binary_ ? 4 : 2);
    if (n + 1 != offsets_.size())
      s_.fail(ErrorKind::count_mismatch, "CELL_TYPES has " + std::to_string(n) + " entries but CELLS has " + std::to_string(offsets_.size() - 1) + " cells");
    if (binary_) s_.rest_of_line();
    const NumberType int32{4, false, true};
    Numbers numbers(s_, binary_);
    mesh_.tets.reserve(plausible_count(n, connectivity_.size(), 4));
    for (std::uint64_t c = 0; c < n; ++c) add_cell(c, std::int64_t(numbers.index(int32, "cell type")));
    have_types_ = true;
  }

  // Cell c of VTK type `type`: a tet (its higher-order nodes set aside), skipped or refused.
  void add_cell(std::uint64_t c, std::int64_t type) {
    const auto kind = vtk_cell_kind(type);
    if (kind == VtkCellKind::lower_dimensional) return;
    if (kind == VtkCellKind::refused) s_.fail_at(cell_lines_[c], ErrorKind::non_tet_cell, vtk_refusal(c, type));
    const std::uint64_t nodes = kind == VtkCellKind::tetrahedron ? 4 : 10;
    const auto k = offsets_[c + 1] - offsets_[c];
    if (k != nodes)
      s_.fail_at(cell_lines_[c], ErrorKind::count_mismatch,
                 "cell " + std::to_string(c) + " of VTK type " + std::to_string(type) + " has " + std::to_string(k) + " points, not " +
                     std::to_string(nodes));
    const auto* v = &connectivity_[std::size_t(offsets_[c])];
    mesh_.tets.push_back({v[0], v[1], v[2], v[3]});
    for (std::uint64_t j = 4; j < nodes; ++j) higher_order_.add(v[j]);
    tet_lines_.push_back(cell_lines_[c]);
  }

  void check_point_indices() {
    for (std::size_t c = 0; c + 1 < offsets_.size(); ++c)
      for (auto j = offsets_[c]; j < offsets_[c + 1]; ++j)
        if (connectivity_[std::size_t(j)] >= npoints_)
          s_.fail_at(cell_lines_[c], ErrorKind::index_out_of_range,
                     "cell " + std::to_string(c) + " uses point " + std::to_string(connectivity_[std::size_t(j)]) + " but there are " +
                         std::to_string(npoints_) + " points");
  }

  Scanner s_;
  int major_ = 2;
  bool binary_ = false;
  bool have_points_ = false, have_cells_ = false, have_types_ = false;
  std::uint64_t npoints_ = 0;
  TetMeshData mesh_;
  std::vector<std::uint64_t> offsets_;  // cell c uses connectivity_[offsets_[c] .. offsets_[c+1])
  std::vector<std::uint32_t> connectivity_;
  std::vector<std::size_t> cell_lines_;
  std::vector<std::size_t> tet_lines_;
  HigherOrderNodes higher_order_;
};

}  // namespace

TetMeshData read_vtk(std::string_view bytes, const std::string& name, const ReadOptions& options) {
  return VtkReader(bytes, name).read(options, name);
}

}  // namespace cmx::io
