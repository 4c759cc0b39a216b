#pragma once
// The Gmsh .msh reader's state, shared by the MSH 2.x part (read_gmsh.cpp) and the MSH 4.1 part
// (read_gmsh4.cpp). Internal to io/; the entry point is read_gmsh (io/read_mesh.hpp).
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "io/scanner.hpp"
#include "io/second_order.hpp"
#include "io/tet_mesh_data.hpp"

namespace cmx::io {

struct GmshElementShape {
  int nodes = -1;  // -1: unknown type
  int dim = 0;
};

// Nodes and dimension of a Gmsh element type.
GmshElementShape gmsh_element_shape(std::int64_t type);

class GmshReader {
 public:
  GmshReader(std::string_view bytes, const std::string& name) : s_(bytes, name) {}
  TetMeshData read(const ReadOptions& options);

 private:
  // Common to both versions (read_gmsh.cpp).
  void read_format();
  void expect_end(const std::string& name);
  void skip_section(const std::string& name);
  void add_node(std::int64_t tag, Point3 p);
  void add_element(std::int64_t type, const std::vector<std::int64_t>& tags, std::size_t line, std::int64_t id);
  GmshElementShape checked_shape(std::int64_t type);
  Rational binary_double();
  std::int64_t binary_int() { return load_int(4); }
  std::int64_t load_int(int size);

  // MSH 2.x (read_gmsh.cpp).
  void read_nodes2();
  void read_elements2();

  // MSH 4.1, ASCII or binary (read_gmsh4.cpp): numbers are read as the file type says.
  void skip_entities4();
  void read_nodes4();
  void read_elements4();
  std::uint64_t size_value(std::string_view what);  // size_t: data-size bytes in binary files
  std::int64_t int_value(std::string_view what);    // int: 4 bytes in binary files
  Rational real_value(std::string_view what);       // double: 8 bytes in binary files
  // A count bounded by `limit` and by the items of `ascii_bytes` / `binary_bytes` each that fit
  // in the rest of the file.
  std::uint64_t count_value(std::string_view what, std::uint64_t limit, std::size_t ascii_bytes, std::size_t binary_bytes);

  Scanner s_;
  int version_ = 2;
  bool binary_ = false;
  bool big_endian_ = false;
  int size_t_bytes_ = 8;
  TetMeshData mesh_;
  std::vector<std::size_t> tet_lines_;
  std::unordered_map<std::int64_t, std::uint32_t> node_index_;
  HigherOrderNodes higher_order_;
};

}  // namespace cmx::io
