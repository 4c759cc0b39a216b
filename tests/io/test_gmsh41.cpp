// Gmsh MSH 4.1: the binary dialect meshio writes by default (read), and the ASCII writer that
// `.msh` now means (read back by cmx; its structure is what Gmsh 4.1 requires).
#include <doctest/doctest.h>

#include <cstring>

#include "arith/rounding.hpp"
#include "io/read_mesh.hpp"
#include "io/write_mesh.hpp"
#include "io_test_util.hpp"

using namespace cmx;
using namespace cmx::io;
using namespace cmx::io::test;

namespace {

// Binary MSH 4.1 numbers: int (4 bytes), size_t (`size` bytes), double, in either byte order.
struct Binary {
  int size = 8;
  bool big_endian = false;
  std::string out;

  void number(std::uint64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) out += char((v >> (8 * (big_endian ? bytes - 1 - i : i))) & 0xFF);
  }
  void integer(std::int64_t v) { number(std::uint64_t(v), 4); }
  void size_t_(std::uint64_t v) { number(v, size); }
  void real(double d) {
    std::uint64_t u;
    std::memcpy(&u, &d, 8);
    number(u, 8);
  }
};

// The unit tet (0,0,0) (1,0,0) (0,1,0) (0,0,1) with node tags 10, 20, 30, 40 in two node blocks,
// a binary $Entities section (a point, a surface and a volume), a triangle block and a tet block.
std::string binary41(int size, bool big_endian) {
  Binary b{size, big_endian, ""};
  b.integer(1);
  std::string text = "$MeshFormat\n4.1 1 " + std::to_string(size) + "\n" + b.out + "\n$EndMeshFormat\n$Entities\n";
  b.out.clear();
  for (std::uint64_t n : {1, 0, 1, 1}) b.size_t_(n);
  b.integer(7);  // point 7 at the origin, one physical tag
  for (int k = 0; k < 3; ++k) b.real(0);
  b.size_t_(1);
  b.integer(3);
  b.integer(1);  // surface 1: bounding box, no physical tags, bounded by curve -1
  for (int k = 0; k < 6; ++k) b.real(k < 3 ? 0 : 1);
  b.size_t_(0);
  b.size_t_(1);
  b.integer(-1);
  b.integer(1);  // volume 1: bounded by surface 1
  for (int k = 0; k < 6; ++k) b.real(k < 3 ? 0 : 1);
  b.size_t_(0);
  b.size_t_(1);
  b.integer(1);
  text += b.out + "\n$EndEntities\n$Nodes\n";
  b.out.clear();
  for (std::uint64_t n : {2, 4, 10, 40}) b.size_t_(n);
  b.integer(2), b.integer(1), b.integer(0), b.size_t_(1), b.size_t_(10);  // block on surface 1
  for (int k = 0; k < 3; ++k) b.real(0);
  b.integer(3), b.integer(1), b.integer(0), b.size_t_(3);  // block on volume 1
  for (std::uint64_t tag : {20, 30, 40}) b.size_t_(tag);
  for (double c : {1., 0., 0., 0., 1., 0., 0., 0., 1.}) b.real(c);
  text += b.out + "\n$EndNodes\n$Elements\n";
  b.out.clear();
  for (std::uint64_t n : {2, 2, 1, 2}) b.size_t_(n);
  b.integer(2), b.integer(1), b.integer(2), b.size_t_(1);  // one triangle
  for (std::uint64_t v : {1, 10, 20, 30}) b.size_t_(v);
  b.integer(3), b.integer(1), b.integer(4), b.size_t_(1);  // one tet
  for (std::uint64_t v : {2, 10, 20, 30, 40}) b.size_t_(v);
  return text + b.out + "\n$EndElements\n$NodeData\n1\n\"d\"\n1\n0\n3\n0\n1\n1\n" + std::string(12, '\x01') + "\n$EndNodeData\n";
}

void check_gmsh_unit_tet(const TetMeshData& m) {
  REQUIRE(m.positions.size() == 4);
  CHECK(m.positions[1] == Point3{Rational(1), Rational(0), Rational(0)});
  CHECK(m.positions[3] == Point3{Rational(0), Rational(0), Rational(1)});
  REQUIRE(m.tets.size() == 1);
  CHECK(m.tets[0] == Tet{0, 1, 2, 3});
  CHECK_FALSE(m.orientation_flipped);
}

}  // namespace

TEST_CASE("Gmsh 4.1 binary: entities, node and element blocks, both byte orders, 4- and 8-byte size_t") {
  for (int size : {8, 4})
    for (bool big : {false, true}) {
      CAPTURE(size);
      CAPTURE(big);
      check_gmsh_unit_tet(read_gmsh(binary41(size, big), "bin41.msh"));
    }
}

TEST_CASE("Gmsh 4.1 binary bad input: truncated blocks and absurd counts") {
  const std::string good = binary41(8, false);
  const auto nodes = good.find("$Nodes\n") + 7;
  // Cut inside the node coordinates.
  expect_io_error([&] { read_gmsh(good.substr(0, nodes + 80), "cut.msh"); }, ErrorKind::truncated);
  // A node count of 2^24 + 4 in a small file.
  std::string huge = good;
  huge[nodes + 8 + 3] = '\x01';
  expect_io_error([&] { read_gmsh(huge, "huge.msh"); }, ErrorKind::truncated);
  // An entity count of 2^56.
  std::string entities = good;
  entities[good.find("$Entities\n") + 10 + 7] = '\x01';
  expect_io_error([&] { read_gmsh(entities, "entities.msh"); }, ErrorKind::truncated);
  // A bad size_t size.
  expect_io_error([] { read_gmsh("$MeshFormat\n4.1 1 2\n\x01\0\0\0\n$EndMeshFormat\n", "size.msh"); }, ErrorKind::unsupported, 2);
}

TEST_CASE("write_tet_mesh .msh writes Gmsh 4.1 ASCII with one volume entity, one node and one element block") {
  const auto dir = temp_dir();
  const auto mesh = grid_mesh(2);
  const auto path = (dir / "g.msh").string();
  write_tet_mesh(path, mesh);
  const std::string text = slurp(path);
  CHECK(text.rfind("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 0 1\n1 0 0 0 ", 0) == 0);
  CHECK(text.find("\n$Nodes\n1 27 1 27\n3 1 0 27\n1\n2\n") != std::string::npos);
  CHECK(text.find("\n$Elements\n1 48 1 48\n3 1 4 48\n1 ") != std::string::npos);
  const auto back = read_tet_mesh(path);
  CHECK(back.tets == mesh.tets);
  REQUIRE(back.positions.size() == mesh.positions.size());
  CHECK(to_double(back.positions[13][0]) == 1.0 / 3.0);
  // The 2.2 writer remains for older readers.
  write_gmsh((dir / "g22.msh").string(), nearest_doubles(mesh.positions), mesh.tets);
  CHECK(slurp(dir / "g22.msh").rfind("$MeshFormat\n2.2 0 8\n", 0) == 0);
  CHECK(read_tet_mesh((dir / "g22.msh").string()).tets == mesh.tets);
}

TEST_CASE("Gmsh 4.1 writer: an empty mesh still reads back") {
  const auto dir = temp_dir();
  write_gmsh41((dir / "e.msh").string(), {{0, 0, 0}}, {});
  const auto back = read_tet_mesh((dir / "e.msh").string());
  CHECK(back.positions.size() == 1);
  CHECK(back.tets.empty());
}
