// VTK XML UnstructuredGrid (.vtu) reader: one Piece; DataArrays in format "ascii" or "appended"
// with raw encoding (base64 inline "binary" arrays and compressed files are rejected as
// unsupported). Float32/Float64 points, any integer type for connectivity/offsets/types, either
// byte order, UInt32 or UInt64 block headers. A minimal tag scanner, not a general XML parser:
// comments are skipped, CDATA and entities are not needed by the arrays read here.
#include <charconv>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <map>

#include "io/binary_numbers.hpp"
#include "io/orientation.hpp"
#include "io/read_mesh.hpp"
#include "io/scanner.hpp"

namespace cmx::io {
namespace {

struct Tag {
  std::string name;  // "DataArray", "/Cells", ...
  std::map<std::string, std::string> attributes;
  std::size_t begin = 0, end = 0;  // offsets of '<' and one past '>'
  bool self_closing = false;
};

class VtuReader {
 public:
  VtuReader(std::string_view data, const std::string& name) : data_(data), name_(name) {}

  std::size_t line_at(std::size_t offset) const {
    std::size_t line = 1;
    for (std::size_t i = 0; i < offset && i < data_.size(); ++i) line += data_[i] == '\n';
    return line;
  }
  [[noreturn]] void fail(std::size_t offset, ErrorKind kind, const std::string& message) const {
    throw IoError(kind, name_, line_at(offset), message);
  }

  // The next tag at or after `pos` (skipping comments, declarations and text); false at the end.
  bool next_tag(std::size_t pos, Tag& tag) const {
    while (true) {
      const auto lt = data_.find('<', pos);
      if (lt == std::string_view::npos) return false;
      if (data_.substr(lt, 4) == "<!--") {
        const auto close = data_.find("-->", lt);
        if (close == std::string_view::npos) fail(lt, ErrorKind::truncated, "unterminated XML comment");
        pos = close + 3;
        continue;
      }
      if (data_.substr(lt, 2) == "<?" || data_.substr(lt, 2) == "<!") {
        const auto close = data_.find('>', lt);
        if (close == std::string_view::npos) fail(lt, ErrorKind::truncated, "unterminated XML declaration");
        pos = close + 1;
        continue;
      }
      tag = Tag{};
      tag.begin = lt;
      std::size_t i = lt + 1;
      while (i < data_.size() && !std::isspace(static_cast<unsigned char>(data_[i])) && data_[i] != '>' && data_[i] != '/') ++i;
      if (i < data_.size() && data_[i] == '/' && i == lt + 1) {  // closing tag
        ++i;
        while (i < data_.size() && !std::isspace(static_cast<unsigned char>(data_[i])) && data_[i] != '>') ++i;
      }
      tag.name = std::string(data_.substr(lt + 1, i - lt - 1));
      while (true) {
        while (i < data_.size() && std::isspace(static_cast<unsigned char>(data_[i]))) ++i;
        if (i >= data_.size()) fail(lt, ErrorKind::truncated, "unterminated XML tag <" + tag.name);
        if (data_[i] == '>') {
          tag.end = i + 1;
          return true;
        }
        if (data_[i] == '/' && i + 1 < data_.size() && data_[i + 1] == '>') {
          tag.self_closing = true;
          tag.end = i + 2;
          return true;
        }
        const auto eq = data_.find('=', i);
        if (eq == std::string_view::npos || eq + 1 >= data_.size() || (data_[eq + 1] != '"' && data_[eq + 1] != '\''))
          fail(i, ErrorKind::syntax, "malformed attribute in XML tag <" + tag.name + ">");
        std::string key(data_.substr(i, eq - i));
        while (!key.empty() && std::isspace(static_cast<unsigned char>(key.back()))) key.pop_back();
        const auto close = data_.find(data_[eq + 1], eq + 2);
        if (close == std::string_view::npos) fail(i, ErrorKind::truncated, "unterminated attribute value in <" + tag.name + ">");
        tag.attributes[key] = std::string(data_.substr(eq + 2, close - eq - 2));
        i = close + 1;
      }
    }
  }

  TetMeshData read(const ReadOptions& options) {
    Tag tag;
    std::size_t pos = 0;
    if (!next_tag(0, tag) || tag.name != "VTKFile") fail(0, ErrorKind::syntax, "not a VTK XML file: no <VTKFile> element");
    if (tag.attributes["type"] != "UnstructuredGrid")
      fail(tag.begin, ErrorKind::unsupported, "only VTKFile type=\"UnstructuredGrid\" is supported");
    if (tag.attributes.count("compressor") && !tag.attributes["compressor"].empty())
      fail(tag.begin, ErrorKind::unsupported, "compressed VTU files are not supported (write without compression)");
    big_endian_ = tag.attributes["byte_order"] == "BigEndian";
    header_size_ = tag.attributes["header_type"] == "UInt64" ? 8 : 4;
    pos = tag.end;
    // Collect the arrays of interest and the appended-data start.
    std::string section;
    std::uint64_t npoints = 0, ncells = 0;
    std::size_t piece_at = 0;
    bool have_piece = false;
    while (next_tag(pos, tag)) {
      pos = tag.end;
      if (tag.name == "Piece") {
        if (have_piece) fail(tag.begin, ErrorKind::unsupported, "more than one <Piece> is not supported");
        have_piece = true;
        piece_at = tag.begin;
        npoints = parse_count(tag, "NumberOfPoints", max_vertices);
        ncells = parse_count(tag, "NumberOfCells", max_tets);
      } else if (tag.name == "Points" || tag.name == "Cells" || tag.name == "PointData" || tag.name == "CellData") {
        section = tag.self_closing ? "" : tag.name;
      } else if (tag.name.front() == '/' && tag.name.substr(1) == section) {
        section.clear();
      } else if (tag.name == "DataArray") {
        if (section == "Points" && !points_.begin) points_ = tag;
        else if (section == "Cells") {
          const auto& n = tag.attributes["Name"];
          if (n == "connectivity") connectivity_ = tag;
          else if (n == "offsets") offsets_ = tag;
          else if (n == "types") types_ = tag;
        }
      } else if (tag.name == "AppendedData") {
        if (tag.attributes["encoding"] != "raw") fail(tag.begin, ErrorKind::unsupported, "only raw appended data is supported (encoding=\"raw\")");
        const auto underscore = data_.find('_', tag.end);
        if (underscore == std::string_view::npos) fail(tag.begin, ErrorKind::truncated, "no '_' marker in <AppendedData>");
        appended_ = underscore + 1;
        break;  // binary data follows: no more tags to scan
      }
    }
    if (!have_piece) fail(data_.size(), ErrorKind::truncated, "no <Piece> element");
    if (!points_.begin || !connectivity_.begin || !offsets_.begin || !types_.begin)
      fail(piece_at, ErrorKind::truncated, "the Piece lacks Points or Cells connectivity/offsets/types arrays");
    if (points_.attributes.count("NumberOfComponents") && points_.attributes["NumberOfComponents"] != "3")
      fail(points_.begin, ErrorKind::unsupported, "Points must have 3 components");

    TetMeshData mesh;
    {
      const auto coordinates = read_array(points_, 3 * npoints, true);
      mesh.positions.reserve(std::size_t(npoints));
      for (std::uint64_t i = 0; i < npoints; ++i)
        mesh.positions.push_back({coordinates.reals[3 * i], coordinates.reals[3 * i + 1], coordinates.reals[3 * i + 2]});
    }
    const auto offsets = read_array(offsets_, ncells, false).integers;
    const auto types = read_array(types_, ncells, false).integers;
    const std::uint64_t total = ncells ? offsets.back() : 0;
    const auto connectivity = read_array(connectivity_, total, false).integers;
    const std::size_t cells_line = line_at(connectivity_.begin);
    std::vector<std::size_t> tet_lines;
    std::uint64_t start = 0;
    for (std::uint64_t c = 0; c < ncells; ++c) {
      const auto stop = offsets[c];
      if (stop < start || stop > total) fail(offsets_.begin, ErrorKind::syntax, "cell offsets must not decrease");
      const auto k = stop - start;
      if (types[c] == 10) {
        if (k != 4) fail(connectivity_.begin, ErrorKind::count_mismatch, "cell " + std::to_string(c) + " is a tetrahedron with " + std::to_string(k) + " points");
        Tet t;
        for (std::size_t j = 0; j < 4; ++j) {
          const auto v = connectivity[std::size_t(start + j)];
          if (v >= npoints) fail(connectivity_.begin, ErrorKind::index_out_of_range, "cell " + std::to_string(c) + " uses point " + std::to_string(v) + " of " + std::to_string(npoints));
          t[j] = std::uint32_t(v);
        }
        mesh.tets.push_back(t);
        tet_lines.push_back(cells_line);
      } else if (types[c] > 9 && types[c] != 21 && types[c] != 22 && types[c] != 23 && types[c] != 69 && types[c] != 70) {
        fail(types_.begin, ErrorKind::non_tet_cell, "cell " + std::to_string(c) + " has VTK type " + std::to_string(types[c]) + "; only tetrahedra (10) are supported among 3D cells");
      }
      start = stop;
    }
    validate_and_orient(mesh, options, name_, tet_lines);
    return mesh;
  }

 private:
  struct Array {
    std::vector<Rational> reals;
    std::vector<std::uint64_t> integers;
  };

  std::uint64_t parse_count(Tag& tag, const std::string& key, std::uint64_t limit) {
    const std::string& text = tag.attributes[key];
    std::uint64_t n = 0;
    const auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (ec != std::errc() || p != text.data() + text.size() || text.empty())
      fail(tag.begin, ErrorKind::syntax, "attribute " + key + " must be a non-negative integer, found " + quoted(text));
    if (n > limit || n > data_.size()) fail(tag.begin, ErrorKind::too_large, key + " " + std::to_string(n) + " is larger than the file can hold");
    return n;
  }

  Array read_array(Tag& tag, std::uint64_t count, bool real) {
    const std::string type = tag.attributes["type"];
    int size = 0;
    bool is_real = false, is_signed = true;
    if (type == "Float64") size = 8, is_real = true;
    else if (type == "Float32") size = 4, is_real = true;
    else if (type == "Int8" || type == "UInt8") size = 1, is_signed = type[0] == 'I';
    else if (type == "Int16" || type == "UInt16") size = 2, is_signed = type[0] == 'I';
    else if (type == "Int32" || type == "UInt32") size = 4, is_signed = type[0] == 'I';
    else if (type == "Int64" || type == "UInt64") size = 8, is_signed = type[0] == 'I';
    else fail(tag.begin, ErrorKind::unsupported, "unsupported DataArray type " + quoted(type));
    if (!real && is_real) fail(tag.begin, ErrorKind::syntax, "an index array stored as " + type);
    const std::string format = tag.attributes["format"];
    Array out;
    if (count > data_.size()) fail(tag.begin, ErrorKind::too_large, "array larger than the file");
    const std::size_t plausible = plausible_count(count, data_.size(), format == "ascii" ? 2 : std::size_t(size));
    (real ? out.reals.reserve(plausible) : out.integers.reserve(plausible));
    if (format == "ascii") {
      if (tag.self_closing) fail(tag.begin, ErrorKind::truncated, "empty ascii DataArray");
      const auto close = data_.find("</DataArray", tag.end);
      if (close == std::string_view::npos) fail(tag.begin, ErrorKind::truncated, "no </DataArray>");
      Scanner s(data_.substr(0, close), name_);
      s.seek(tag.end);
      for (std::uint64_t i = 0; i < count; ++i) {
        if (real) out.reals.push_back(s.rational("coordinate"));
        else {
          const auto v = s.integer("integer");
          if (v < 0) s.fail(ErrorKind::index_out_of_range, "negative value " + std::to_string(v) + " in a cell array");
          out.integers.push_back(std::uint64_t(v));
        }
      }
      if (s.skip_space()) s.fail(ErrorKind::count_mismatch, "DataArray has more than the " + std::to_string(count) + " values expected");
    } else if (format == "appended") {
      if (!appended_) fail(tag.begin, ErrorKind::truncated, "appended DataArray without <AppendedData>");
      Scanner offset_text(tag.attributes["offset"], name_);
      std::uint64_t offset = 0;
      try {
        offset = offset_text.unsigned_integer("offset");
      } catch (const IoError&) {
        fail(tag.begin, ErrorKind::syntax, "appended DataArray needs a numeric offset attribute");
      }
      if (offset > data_.size() - appended_) fail(tag.begin, ErrorKind::truncated, "DataArray offset beyond the end of the file");
      std::size_t at = appended_ + std::size_t(offset);
      if (data_.size() - at < std::size_t(header_size_)) fail(tag.begin, ErrorKind::truncated, "appended data ends in a block header");
      const auto bytes = load_unsigned(data_.data() + at, header_size_, big_endian_);
      at += std::size_t(header_size_);
      if (bytes != count * std::uint64_t(size))
        fail(tag.begin, ErrorKind::count_mismatch, "appended block has " + std::to_string(bytes) + " bytes, " + std::to_string(count * std::uint64_t(size)) + " expected");
      if (bytes > data_.size() - at) fail(tag.begin, ErrorKind::truncated, "appended block runs past the end of the file");
      for (std::uint64_t i = 0; i < count; ++i, at += std::size_t(size)) {
        const char* p = data_.data() + at;
        if (is_real) {
          const double d = size == 8 ? load_double(p, big_endian_) : double(load_float(p, big_endian_));
          if (!std::isfinite(d)) fail(tag.begin, ErrorKind::not_finite, "a point coordinate is not finite");
          out.reals.push_back(rational_from_double(d));
        } else {
          const std::int64_t v = is_signed ? load_signed(p, size, big_endian_) : std::int64_t(load_unsigned(p, size, big_endian_));
          if (v < 0) fail(tag.begin, ErrorKind::index_out_of_range, "negative value in a cell array");
          if (real) out.reals.emplace_back(std::to_string(v));
          else out.integers.push_back(std::uint64_t(v));
        }
      }
    } else {
      fail(tag.begin, ErrorKind::unsupported, "DataArray format " + quoted(format) + " is not supported (ascii or raw appended)");
    }
    return out;
  }

  std::string_view data_;
  std::string name_;
  bool big_endian_ = false;
  int header_size_ = 4;
  std::size_t appended_ = 0;
  Tag points_, connectivity_, offsets_, types_;
};

}  // namespace

TetMeshData read_vtu(std::string_view bytes, const std::string& name, const ReadOptions& options) {
  return VtuReader(bytes, name).read(options);
}

}  // namespace cmx::io
