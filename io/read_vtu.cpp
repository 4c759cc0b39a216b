// VTK XML UnstructuredGrid (.vtu) reader: one Piece; DataArrays in format "ascii", inline
// "binary" (base64) or "appended" (<AppendedData encoding="raw"> or "base64"); uncompressed or
// compressed with compressor="vtkZLibDataCompressor" (io/vtk_binary_block.hpp); Float32/Float64
// points, any integer type for connectivity/offsets/types; either byte order; header_type UInt32
// or UInt64. Point and cell data arrays are ignored. Cell types: io/vtk_cell_types.hpp.
#include <charconv>
#include <cmath>
#include <cstdint>

#include "io/binary_numbers.hpp"
#include "io/orientation.hpp"
#include "io/read_mesh.hpp"
#include "io/scanner.hpp"
#include "io/second_order.hpp"
#include "io/vtk_binary_block.hpp"
#include "io/vtk_cell_types.hpp"
#include "io/xml_tags.hpp"

namespace cmx::io {
namespace {

struct NumberFormat {
  int size = 0;
  bool real = false, is_signed = true;
};

struct Array {
  std::vector<Rational> reals;
  std::vector<std::uint64_t> integers;
};

class VtuReader {
 public:
  VtuReader(std::string_view data, const std::string& name) : xml_(data, name), data_(data) {}

  TetMeshData read(const ReadOptions& options) {
    scan_structure();
    TetMeshData mesh;
    const auto coordinates = read_array(points_, 3 * npoints_, true).reals;
    mesh.positions.reserve(std::size_t(npoints_));
    for (std::uint64_t i = 0; i < npoints_; ++i)
      mesh.positions.push_back({coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]});
    HigherOrderNodes higher_order;
    read_cells(mesh, higher_order);
    higher_order.drop_unused(mesh);
    validate_and_orient(mesh, options, xml_.file(), std::vector<std::size_t>(mesh.tets.size(), xml_.line_at(connectivity_.begin)));
    return mesh;
  }

 private:
  void read_file_attributes(const XmlTag& tag) {
    if (tag.attribute("type") != "UnstructuredGrid")
      xml_.fail(tag.begin, ErrorKind::unsupported, "only VTKFile type=\"UnstructuredGrid\" is supported");
    const auto& compressor = tag.attribute("compressor");
    if (compressor == "vtkZLibDataCompressor") layout_.zlib = true;
    else if (!compressor.empty())
      xml_.fail(tag.begin, ErrorKind::unsupported, "compressor " + quoted(compressor) + " is not supported (only vtkZLibDataCompressor)");
    layout_.big_endian = tag.attribute("byte_order") == "BigEndian";
    const auto& header = tag.attribute("header_type");
    if (header == "UInt64") layout_.header_size = 8;
    else if (!header.empty() && header != "UInt32")
      xml_.fail(tag.begin, ErrorKind::unsupported, "header_type " + quoted(header) + " is not supported (UInt32 or UInt64)");
    // A compressed file may hold up to max_inflate_ratio times its size once inflated.
    inflated_bound_ = std::uint64_t(data_.size()) * (layout_.zlib ? max_inflate_ratio : 1);
  }

  void note_appended_data(const XmlTag& tag) {
    const auto& encoding = tag.attribute("encoding");
    if (encoding != "raw" && encoding != "base64")
      xml_.fail(tag.begin, ErrorKind::unsupported, "<AppendedData> encoding " + quoted(encoding) + " is not supported (raw or base64)");
    appended_base64_ = encoding == "base64";
    const auto underscore = data_.find('_', tag.end);
    if (underscore == std::string_view::npos) xml_.fail(tag.begin, ErrorKind::truncated, "no '_' marker in <AppendedData>");
    appended_ = underscore + 1;
    appended_end_ = data_.size();
    if (appended_base64_)  // raw data may contain any bytes, base64 text ends at the closing tag
      if (const auto close = data_.find("</AppendedData", appended_); close != std::string_view::npos) appended_end_ = close;
  }

  void note_array(const XmlTag& tag, const std::string& section) {
    if (section == "Points" && !points_.begin) points_ = tag;
    if (section != "Cells") return;
    const auto& n = tag.attribute("Name");
    if (n == "connectivity") connectivity_ = tag;
    else if (n == "offsets") offsets_ = tag;
    else if (n == "types") types_ = tag;
  }

  // Finds the Piece, its arrays and the appended data (binary data follows it: no more tags).
  void scan_structure() {
    XmlTag tag;
    if (!xml_.next(0, tag) || tag.name != "VTKFile") xml_.fail(0, ErrorKind::syntax, "not a VTK XML file: no <VTKFile> element");
    read_file_attributes(tag);
    std::string section;
    std::size_t piece_at = 0;
    bool have_piece = false;
    for (std::size_t pos = tag.end; xml_.next(pos, tag);) {
      pos = tag.end;
      if (tag.name == "Piece") {
        if (have_piece) xml_.fail(tag.begin, ErrorKind::unsupported, "more than one <Piece> is not supported");
        have_piece = true;
        piece_at = tag.begin;
        npoints_ = parse_count(tag, "NumberOfPoints", max_vertices);
        ncells_ = parse_count(tag, "NumberOfCells", max_tets);
      } else if (tag.name == "Points" || tag.name == "Cells" || tag.name == "PointData" || tag.name == "CellData") {
        section = tag.self_closing ? "" : tag.name;
      } else if (!tag.name.empty() && tag.name.front() == '/' && tag.name.substr(1) == section) {
        section.clear();
      } else if (tag.name == "DataArray") {
        note_array(tag, section);
      } else if (tag.name == "AppendedData") {
        note_appended_data(tag);
        break;
      }
    }
    if (!have_piece) xml_.fail(data_.size(), ErrorKind::truncated, "no <Piece> element");
    if (!points_.begin || !connectivity_.begin || !offsets_.begin || !types_.begin)
      xml_.fail(piece_at, ErrorKind::truncated, "the Piece lacks Points or Cells connectivity/offsets/types arrays");
    if (points_.has("NumberOfComponents") && points_.attribute("NumberOfComponents") != "3")
      xml_.fail(points_.begin, ErrorKind::unsupported, "Points must have 3 components");
  }

  std::uint64_t parse_count(const XmlTag& tag, const std::string& key, std::uint64_t limit) const {
    const std::string& text = tag.attribute(key);
    std::uint64_t n = 0;
    const auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (ec != std::errc() || p != text.data() + text.size() || text.empty())
      xml_.fail(tag.begin, ErrorKind::syntax, "attribute " + key + " must be a non-negative integer, found " + quoted(text));
    if (n > limit || n > inflated_bound_)
      xml_.fail(tag.begin, ErrorKind::too_large, key + " " + std::to_string(n) + " is larger than the file can hold");
    return n;
  }

  void read_cells(TetMeshData& mesh, HigherOrderNodes& higher_order) const {
    const auto offsets = read_array(offsets_, ncells_, false).integers;
    const auto types = read_array(types_, ncells_, false).integers;
    const std::uint64_t total = ncells_ ? offsets.back() : 0;
    const auto connectivity = read_array(connectivity_, total, false).integers;
    std::uint64_t start = 0;
    for (std::uint64_t c = 0; c < ncells_; start = offsets[c++]) {
      if (offsets[c] < start || offsets[c] > total) xml_.fail(offsets_.begin, ErrorKind::syntax, "cell offsets must not decrease");
      const auto kind = vtk_cell_kind(std::int64_t(types[c]));
      if (kind == VtkCellKind::lower_dimensional) continue;
      if (kind == VtkCellKind::refused) xml_.fail(types_.begin, ErrorKind::non_tet_cell, vtk_refusal(c, std::int64_t(types[c])));
      const std::uint64_t nodes = kind == VtkCellKind::tetrahedron ? 4 : 10;
      if (offsets[c] - start != nodes)
        xml_.fail(connectivity_.begin, ErrorKind::count_mismatch,
                  "cell " + std::to_string(c) + " of VTK type " + std::to_string(types[c]) + " has " + std::to_string(offsets[c] - start) +
                      " points, not " + std::to_string(nodes));
      Tet t;
      for (std::uint64_t j = 0; j < nodes; ++j) {
        const auto v = connectivity[std::size_t(start + j)];
        if (v >= npoints_)
          xml_.fail(connectivity_.begin, ErrorKind::index_out_of_range,
                    "cell " + std::to_string(c) + " uses point " + std::to_string(v) + " of " + std::to_string(npoints_));
        if (j < 4) t[j] = std::uint32_t(v);
        else higher_order.add(std::uint32_t(v));
      }
      mesh.tets.push_back(t);
    }
  }

  NumberFormat number_format(const XmlTag& tag, bool real) const {
    const std::string& type = tag.attribute("type");
    NumberFormat f;
    if (type == "Float64" || type == "Float32") f = {type == "Float64" ? 8 : 4, true, true};
    else if (type == "Int8" || type == "UInt8") f = {1, false, type[0] == 'I'};
    else if (type == "Int16" || type == "UInt16") f = {2, false, type[0] == 'I'};
    else if (type == "Int32" || type == "UInt32") f = {4, false, type[0] == 'I'};
    else if (type == "Int64" || type == "UInt64") f = {8, false, type[0] == 'I'};
    else xml_.fail(tag.begin, ErrorKind::unsupported, "unsupported DataArray type " + quoted(type));
    if (!real && f.real) xml_.fail(tag.begin, ErrorKind::syntax, "an index array stored as " + type);
    return f;
  }

  Array read_array(const XmlTag& tag, std::uint64_t count, bool real) const {
    const auto format = number_format(tag, real);
    if (count > inflated_bound_) xml_.fail(tag.begin, ErrorKind::too_large, "array larger than the file");
    const std::string& encoding = tag.attribute("format");
    if (encoding == "ascii") return read_ascii(tag, count, real);
    if (encoding != "binary" && encoding != "appended")
      xml_.fail(tag.begin, ErrorKind::unsupported, "DataArray format " + quoted(encoding) + " is not supported (ascii, binary or appended)");
    const std::string payload = binary_payload(tag, count * std::uint64_t(format.size));
    return decode_numbers(tag, payload, count, format, real);
  }

  Array read_ascii(const XmlTag& tag, std::uint64_t count, bool real) const {
    if (tag.self_closing) xml_.fail(tag.begin, ErrorKind::truncated, "empty ascii DataArray");
    const auto close = data_.find("</DataArray", tag.end);
    if (close == std::string_view::npos) xml_.fail(tag.begin, ErrorKind::truncated, "no </DataArray>");
    Array out;
    const std::size_t plausible = plausible_count(count, close - tag.end, 2);
    real ? out.reals.reserve(plausible) : out.integers.reserve(plausible);
    Scanner s(data_.substr(0, close), xml_.file());
    s.seek(tag.end);
    for (std::uint64_t i = 0; i < count; ++i) {
      if (real) {
        out.reals.push_back(s.rational("coordinate"));
        continue;
      }
      const auto v = s.integer("integer");
      if (v < 0) s.fail(ErrorKind::index_out_of_range, "negative value " + std::to_string(v) + " in a cell array");
      out.integers.push_back(std::uint64_t(v));
    }
    if (s.skip_space()) s.fail(ErrorKind::count_mismatch, "DataArray has more than the " + std::to_string(count) + " values expected");
    return out;
  }

  // The decoded bytes of an inline binary or appended array.
  std::string binary_payload(const XmlTag& tag, std::uint64_t bytes) const {
    const ArrayPlace place{xml_.file(), xml_.line_at(tag.begin), tag.has("Name") ? tag.attribute("Name") : tag.attribute("type")};
    if (tag.attribute("format") == "binary") {
      if (tag.self_closing) xml_.fail(tag.begin, ErrorKind::truncated, "empty binary DataArray");
      const auto close = data_.find("</DataArray", tag.end);
      if (close == std::string_view::npos) xml_.fail(tag.begin, ErrorKind::truncated, "no </DataArray>");
      auto in = EncodedBytes::base64(data_.substr(tag.end, close - tag.end));
      return decode_vtk_block(in, layout_, bytes, place);
    }
    if (!appended_) xml_.fail(tag.begin, ErrorKind::truncated, "appended DataArray without <AppendedData>");
    std::uint64_t offset = 0;
    const std::string& text = tag.attribute("offset");
    const auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), offset);
    if (ec != std::errc() || p != text.data() + text.size() || text.empty())
      xml_.fail(tag.begin, ErrorKind::syntax, "appended DataArray needs a numeric offset attribute");
    if (offset > appended_end_ - appended_) xml_.fail(tag.begin, ErrorKind::truncated, "DataArray offset beyond the end of the file");
    const auto region = data_.substr(appended_ + std::size_t(offset), appended_end_ - appended_ - std::size_t(offset));
    auto in = appended_base64_ ? EncodedBytes::base64(region) : EncodedBytes::raw(region);
    return decode_vtk_block(in, layout_, bytes, place);
  }

  Array decode_numbers(const XmlTag& tag, const std::string& payload, std::uint64_t count, const NumberFormat& f, bool real) const {
    Array out;
    real ? out.reals.reserve(std::size_t(count)) : out.integers.reserve(std::size_t(count));
    const bool big = layout_.big_endian;
    for (std::size_t i = 0; i < count; ++i) {
      const char* p = payload.data() + i * std::size_t(f.size);
      if (f.real) {
        const double d = f.size == 8 ? load_double(p, big) : double(load_float(p, big));
        if (!std::isfinite(d)) xml_.fail(tag.begin, ErrorKind::not_finite, "a point coordinate is not finite");
        out.reals.push_back(rational_from_double(d));
        continue;
      }
      const std::int64_t v = f.is_signed ? load_signed(p, f.size, big) : std::int64_t(load_unsigned(p, f.size, big));
      if (v < 0) xml_.fail(tag.begin, ErrorKind::index_out_of_range, "negative value in a cell array");
      if (real) out.reals.emplace_back(std::to_string(v));
      else out.integers.push_back(std::uint64_t(v));
    }
    return out;
  }

  XmlTags xml_;
  std::string_view data_;
  BlockLayout layout_;
  std::uint64_t inflated_bound_ = 0;
  std::uint64_t npoints_ = 0, ncells_ = 0;
  std::size_t appended_ = 0, appended_end_ = 0;
  bool appended_base64_ = false;
  XmlTag points_, connectivity_, offsets_, types_;
};

}  // namespace

TetMeshData read_vtu(std::string_view bytes, const std::string& name, const ReadOptions& options) {
  return VtuReader(bytes, name).read(options);
}

}  // namespace cmx::io
