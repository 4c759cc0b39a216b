// Gmsh .msh reader: MSH 2.x ASCII and binary (2.2 as written by Gmsh, fTetWild and TetWild) and
// MSH 4.1 ASCII and binary (read_gmsh4.cpp). Node tags may be sparse and unordered; vertices are
// numbered in the order the nodes appear. Elements of dimension < 3 are skipped; 10-node
// tetrahedra (type 11) contribute their corners (io/second_order.hpp); other 3D elements than
// tetrahedra (type 4) are rejected. Gmsh's tetra convention is det[b-a, c-a, d-a] > 0 (detected
// anyway). Unknown sections ($PhysicalNames, $NodeData, ...) are skipped.
#include <cmath>
#include <cstdint>

#include "io/binary_numbers.hpp"
#include "io/gmsh_reader.hpp"
#include "io/orientation.hpp"
#include "io/read_mesh.hpp"

namespace cmx::io {
namespace {

// Gmsh's higher-order 3D element types (besides 11, which is read), for the refusal message.
bool is_higher_order_3d(std::int64_t type) {
  switch (type) {
    case 12: case 13: case 14: case 17: case 18: case 19: case 29: case 30: case 31: case 92: case 93:
      return true;
    default:
      return false;
  }
}

}  // namespace

GmshElementShape gmsh_element_shape(std::int64_t type) {
  switch (type) {
    case 15: return {1, 0};
    case 1: return {2, 1};
    case 8: return {3, 1};
    case 26: return {4, 1};
    case 27: return {5, 1};
    case 28: return {6, 1};
    case 2: return {3, 2};
    case 3: return {4, 2};
    case 9: return {6, 2};
    case 10: return {9, 2};
    case 16: return {8, 2};
    case 20: return {9, 2};
    case 21: return {10, 2};
    case 22: return {12, 2};
    case 23: return {15, 2};
    case 24: return {15, 2};
    case 25: return {21, 2};
    case 4: return {4, 3};
    case 5: return {8, 3};
    case 6: return {6, 3};
    case 7: return {5, 3};
    case 11: return {10, 3};
    case 12: return {27, 3};
    case 13: return {18, 3};
    case 14: return {14, 3};
    case 17: return {20, 3};
    case 18: return {15, 3};
    case 19: return {13, 3};
    case 29: return {20, 3};
    case 30: return {35, 3};
    case 31: return {56, 3};
    case 92: return {64, 3};
    case 93: return {125, 3};
    default: return {};
  }
}

TetMeshData GmshReader::read(const ReadOptions& options) {
  bool have_format = false, have_nodes = false, have_elements = false;
  while (s_.skip_space()) {
    const auto section = s_.token("section");
    if (section.empty() || section[0] != '$')
      s_.fail(ErrorKind::syntax, "expected a section such as $MeshFormat, found " + quoted(section));
    const std::string name(section.substr(1));
    if (name == "MeshFormat") {
      read_format();
      have_format = true;
    } else if (name == "Entities" && binary_ && version_ >= 4) {
      skip_entities4();
    } else if (name == "Nodes") {
      if (!have_format) s_.fail(ErrorKind::syntax, "$Nodes before $MeshFormat");
      if (have_nodes) s_.fail(ErrorKind::syntax, "a second $Nodes section");
      version_ >= 4 ? read_nodes4() : read_nodes2();
      have_nodes = true;
    } else if (name == "Elements") {
      if (!have_nodes) s_.fail(ErrorKind::syntax, "$Elements before $Nodes");
      if (have_elements) s_.fail(ErrorKind::syntax, "a second $Elements section");
      version_ >= 4 ? read_elements4() : read_elements2();
      have_elements = true;
    } else {
      skip_section(name);
      continue;
    }
    expect_end(name);
  }
  if (!have_format) s_.fail_at(1, ErrorKind::syntax, "not a Gmsh file: no $MeshFormat");
  if (!have_nodes) s_.fail(ErrorKind::truncated, "no $Nodes section");
  if (!have_elements) s_.fail(ErrorKind::truncated, "no $Elements section");
  higher_order_.drop_unused(mesh_);
  validate_and_orient(mesh_, options, s_.file(), tet_lines_);
  return std::move(mesh_);
}

void GmshReader::read_format() {
  const auto version = s_.token("format version");
  if (version.substr(0, 2) == "2.") version_ = 2;
  else if (version == "4.1") version_ = 4;
  else s_.fail(ErrorKind::unsupported, "MSH version " + quoted(version) + " is not supported (2.x and 4.1 are)");
  binary_ = s_.unsigned_integer("file type") == 1;
  // The data size is sizeof(double) in MSH 2 and sizeof(size_t) in MSH 4.1.
  const auto data_size = s_.unsigned_integer("data size");
  if (version_ == 2 && data_size != 8) s_.fail(ErrorKind::unsupported, "only 8-byte doubles are supported");
  if (version_ == 4 && data_size != 8 && data_size != 4)
    s_.fail(ErrorKind::unsupported, "data size " + std::to_string(data_size) + ": MSH 4.1 size_t must be 4 or 8 bytes");
  size_t_bytes_ = int(data_size);
  if (binary_) {
    s_.rest_of_line();
    const char* one = s_.bytes(4, "endianness marker").data();
    if (load_unsigned(one, 4, false) == 1) big_endian_ = false;
    else if (load_unsigned(one, 4, true) == 1) big_endian_ = true;
    else s_.fail(ErrorKind::syntax, "bad endianness marker in a binary MSH file");
  }
}

void GmshReader::expect_end(const std::string& name) {
  const auto t = s_.token("$End" + name);
  if (t != "$End" + name) s_.fail(ErrorKind::count_mismatch, "expected $End" + name + ", found " + quoted(t));
}

void GmshReader::skip_section(const std::string& name) {
  const std::string end = "$End" + name;
  const auto rest = s_.data().substr(s_.position());
  const auto at = rest.find(end);
  if (at == std::string_view::npos) s_.fail(ErrorKind::truncated, "section $" + name + " has no " + end);
  s_.seek(s_.position() + at + end.size());
}

void GmshReader::add_node(std::int64_t tag, Point3 p) {
  const auto index = std::uint32_t(mesh_.positions.size());
  if (!node_index_.emplace(tag, index).second) s_.fail(ErrorKind::duplicate, "node tag " + std::to_string(tag) + " appears twice");
  mesh_.positions.push_back(std::move(p));
}

void GmshReader::add_element(std::int64_t type, const std::vector<std::int64_t>& tags, std::size_t line, std::int64_t id) {
  const auto shape = gmsh_element_shape(type);
  if (shape.dim < 3) return;
  if (type != 4 && type != 11)
    s_.fail_at(line, ErrorKind::non_tet_cell,
               "element " + std::to_string(id) + " has type " + std::to_string(type) +
                   (is_higher_order_3d(type) ? " (a second-order or higher-order 3D element)" : "") +
                   "; among 3D elements only 4-node tetrahedra (type 4) and 10-node tetrahedra (type 11, read as their corners) "
                   "are supported");
  Tet t;
  for (std::size_t k = 0; k < tags.size(); ++k) {
    const auto it = node_index_.find(tags[k]);
    if (it == node_index_.end())
      s_.fail_at(line, ErrorKind::index_out_of_range,
                 "element " + std::to_string(id) + " uses node tag " + std::to_string(tags[k]) + ", which is not in $Nodes");
    if (k < 4) t[k] = it->second;
    else higher_order_.add(it->second);
  }
  mesh_.tets.push_back(t);
  tet_lines_.push_back(line);
}

GmshElementShape GmshReader::checked_shape(std::int64_t type) {
  const auto shape = gmsh_element_shape(type);
  if (shape.nodes < 0) s_.fail(ErrorKind::unsupported, "unknown element type " + std::to_string(type));
  return shape;
}

Rational GmshReader::binary_double() {
  const double d = load_double(s_.bytes(8, "coordinate").data(), big_endian_);
  if (!std::isfinite(d)) s_.fail(ErrorKind::not_finite, "a node coordinate is not finite");
  return rational_from_double(d);
}

std::int64_t GmshReader::load_int(int size) { return load_signed(s_.bytes(std::size_t(size), "integer").data(), size, big_endian_); }

void GmshReader::read_nodes2() {
  const auto n = s_.count("node count", max_vertices, binary_ ? 28 : 8);
  if (binary_) s_.rest_of_line();
  mesh_.positions.reserve(std::size_t(n));
  node_index_.reserve(std::size_t(n));
  for (std::uint64_t i = 0; i < n; ++i) {
    Point3 p;
    std::int64_t tag;
    if (binary_) {
      tag = binary_int();
      for (auto& c : p) c = binary_double();
    } else {
      tag = s_.integer("node tag");
      for (auto& c : p) c = s_.rational("node coordinate");
    }
    add_node(tag, std::move(p));
  }
}

void GmshReader::read_elements2() {
  const std::size_t header_line = s_.line();
  const auto n = s_.count("element count", UINT64_MAX / 16, binary_ ? 12 : 8);
  if (binary_) s_.rest_of_line();
  std::vector<std::int64_t> nodes;
  for (std::uint64_t i = 0; i < n;) {
    if (binary_) {
      const auto type = binary_int();
      const auto follow = binary_int();
      const auto ntags = binary_int();
      const auto shape = checked_shape(type);
      if (follow <= 0 || std::uint64_t(follow) > n - i || ntags < 0 || ntags > 1000)
        s_.fail_at(header_line, ErrorKind::count_mismatch, "bad binary element block header");
      for (std::int64_t e = 0; e < follow; ++e, ++i) {
        const auto id = binary_int();
        for (std::int64_t k = 0; k < ntags; ++k) binary_int();
        nodes.clear();
        for (int k = 0; k < shape.nodes; ++k) nodes.push_back(binary_int());
        add_element(type, nodes, header_line, id);
      }
      continue;
    }
    s_.skip_space();
    const std::size_t line = s_.line();
    const auto id = s_.integer("element tag");
    const auto type = s_.integer("element type");
    const auto shape = checked_shape(type);
    const auto ntags = s_.unsigned_integer("tag count");
    if (ntags > 1000) s_.fail(ErrorKind::too_large, "element " + std::to_string(id) + " claims " + std::to_string(ntags) + " tags");
    for (std::uint64_t k = 0; k < ntags; ++k) s_.integer("element tag value");
    nodes.clear();
    for (int k = 0; k < shape.nodes; ++k) nodes.push_back(s_.integer("node tag"));
    if (s_.more_on_line())
      s_.fail(ErrorKind::count_mismatch, "element " + std::to_string(id) + " has more nodes than type " + std::to_string(type) + " allows");
    add_element(type, nodes, line, id);
    ++i;
  }
}

TetMeshData read_gmsh(std::string_view bytes, const std::string& name, const ReadOptions& options) {
  return GmshReader(bytes, name).read(options);
}

}  // namespace cmx::io
