// MSH 4.1, ASCII and binary: the same sections in both, numbers as text or as raw size_t (the
// data size of $MeshFormat: 4 or 8 bytes), int (4 bytes) and double (8 bytes) in the byte order of
// the endianness marker. $Entities is skipped (parsed in binary files, where it cannot be searched
// for its end marker); nodes and elements come in entity blocks.
#include <cstdint>

#include "io/binary_numbers.hpp"
#include "io/gmsh_reader.hpp"

namespace cmx::io {

std::uint64_t GmshReader::size_value(std::string_view what) {
  if (!binary_) return s_.unsigned_integer(what);
  return load_unsigned(s_.bytes(std::size_t(size_t_bytes_), what).data(), size_t_bytes_, big_endian_);
}

std::int64_t GmshReader::int_value(std::string_view what) {
  if (!binary_) return s_.integer(what);
  return load_signed(s_.bytes(4, what).data(), 4, big_endian_);
}

Rational GmshReader::real_value(std::string_view what) { return binary_ ? binary_double() : s_.rational(what); }

std::uint64_t GmshReader::count_value(std::string_view what, std::uint64_t limit, std::size_t ascii_bytes, std::size_t binary_bytes) {
  if (!binary_) return s_.count(what, limit, ascii_bytes);
  const auto n = size_value(what);
  if (n > limit) s_.fail(ErrorKind::too_large, std::string(what) + " " + std::to_string(n) + " exceeds the limit " + std::to_string(limit));
  if (binary_bytes && n > s_.remaining() / binary_bytes)
    s_.fail(ErrorKind::truncated, std::string(what) + " " + std::to_string(n) + " cannot fit in the " + std::to_string(s_.remaining()) +
                                      " bytes left in the file (truncated file or wrong count)");
  return n;
}

void GmshReader::skip_entities4() {
  s_.rest_of_line();  // binary data starts on the line after the section name
  std::uint64_t counts[4];
  for (auto& c : counts) c = count_value("entity count", UINT64_MAX, 0, 4 + 24 + std::size_t(size_t_bytes_));
  for (int dim = 0; dim < 4; ++dim)
    for (std::uint64_t e = 0; e < counts[dim]; ++e) {
      int_value("entity tag");
      for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) real_value("entity bounding box");
      const auto physicals = count_value("physical tag count", UINT64_MAX, 0, 4);
      for (std::uint64_t k = 0; k < physicals; ++k) int_value("physical tag");
      if (dim == 0) continue;
      const auto bounding = count_value("bounding entity count", UINT64_MAX, 0, 4);
      for (std::uint64_t k = 0; k < bounding; ++k) int_value("bounding entity tag");
    }
}

void GmshReader::read_nodes4() {
  const std::size_t st = std::size_t(size_t_bytes_);
  if (binary_) s_.rest_of_line();
  const auto blocks = count_value("entity block count", max_vertices, 8, 12 + st);
  const auto n = count_value("node count", max_vertices, 8, st + 24);
  size_value("min node tag");
  size_value("max node tag");
  mesh_.positions.reserve(std::size_t(n));
  node_index_.reserve(std::size_t(n));
  std::vector<std::int64_t> tags;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const auto dim = int_value("entity dimension");
    int_value("entity tag");
    const auto parametric = int_value("parametric flag");
    if (dim < 0 || dim > 3 || parametric < 0 || parametric > 1) s_.fail(ErrorKind::syntax, "bad node block header");
    const auto count = count_value("nodes in block", n - std::min<std::uint64_t>(n, mesh_.positions.size()), 4, st + 24);
    tags.clear();
    tags.reserve(std::size_t(count));
    for (std::uint64_t i = 0; i < count; ++i) tags.push_back(std::int64_t(size_value("node tag")));
    for (std::uint64_t i = 0; i < count; ++i) {
      Point3 p;
      for (auto& c : p) c = real_value("node coordinate");
      for (std::int64_t k = 0; k < (parametric ? dim : 0); ++k) real_value("parametric coordinate");
      add_node(tags[i], std::move(p));
    }
  }
  if (mesh_.positions.size() != n)
    s_.fail(ErrorKind::count_mismatch,
            "the node blocks hold " + std::to_string(mesh_.positions.size()) + " nodes, the header says " + std::to_string(n));
}

void GmshReader::read_elements4() {
  const std::size_t st = std::size_t(size_t_bytes_);
  if (binary_) s_.rest_of_line();
  const std::size_t header_line = s_.line();
  const auto blocks = count_value("entity block count", UINT64_MAX / 16, 8, 12 + st);
  const auto n = count_value("element count", UINT64_MAX / 16, 4, 2 * st);
  size_value("min element tag");
  size_value("max element tag");
  std::uint64_t seen = 0;
  std::vector<std::int64_t> nodes;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    int_value("entity dimension");
    int_value("entity tag");
    const auto type = int_value("element type");
    const auto shape = checked_shape(type);
    const auto count = count_value("elements in block", n - std::min(n, seen), 4, (std::size_t(shape.nodes) + 1) * st);
    for (std::uint64_t i = 0; i < count; ++i, ++seen) {
      if (!binary_) s_.skip_space();
      const std::size_t line = binary_ ? header_line : s_.line();
      const auto id = std::int64_t(size_value("element tag"));
      nodes.clear();
      for (int k = 0; k < shape.nodes; ++k) nodes.push_back(std::int64_t(size_value("node tag")));
      add_element(type, nodes, line, id);
    }
  }
  if (seen != n)
    s_.fail(ErrorKind::count_mismatch, "the element blocks hold " + std::to_string(seen) + " elements, the header says " + std::to_string(n));
}

}  // namespace cmx::io
