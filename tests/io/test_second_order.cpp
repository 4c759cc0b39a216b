// Second-order (10-node) tetrahedra in every format that has them — TetGen .ele with 10 nodes,
// VTK type 24 (legacy and XML), Gmsh type 11 (2.2 and 4.1), Medit TetrahedraP2 — are read as
// their corners, the mid-edge nodes dropped and the other vertices renumbered in file order; other
// higher-order 3D cells are refused with a message that names the type and says "second-order".
#include <doctest/doctest.h>

#include <algorithm>
#include <functional>
#include <map>

#include "arith/rounding.hpp"
#include "io/read_mesh.hpp"
#include "io/write_mesh.hpp"
#include "io_test_util.hpp"

using namespace cmx;
using namespace cmx::io;
using namespace cmx::io::test;

namespace {

// two_tets() as 10-node tets, with the file's nodes interleaved: mid-edge nodes before, between
// and after the corners, and one vertex that no cell uses (kept, as in linear files).
struct QuadraticFile {
  std::vector<DoublePoint> nodes;                // in file order
  std::vector<std::array<std::uint32_t, 10>> tets;  // 0-based file indices: corners, then edge midpoints
  std::vector<DoublePoint> expected_positions;  // what the reader must keep, in order
  std::vector<Tet> expected_tets;
};

QuadraticFile quadratic_two_tets() {
  const auto mesh = two_tets();
  const auto corners = nearest_doubles(mesh.positions);
  // File order: m m c0 c1 m c2 isolated m c3 m m m m c4 m.
  const std::string layout = "mmccmcimcmmmmcm";
  QuadraticFile f;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid_of;
  std::vector<DoublePoint> mids;
  const int edges[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
  std::vector<std::array<std::uint32_t, 10>> local;  // corners 0..4, mids 100 + k
  for (const auto& t : mesh.tets) {
    std::array<std::uint32_t, 10> row{t[0], t[1], t[2], t[3]};
    for (int e = 0; e < 6; ++e) {
      const auto key = std::minmax(t[std::size_t(edges[e][0])], t[std::size_t(edges[e][1])]);
      if (!mid_of.count(key)) {
        mid_of[key] = std::uint32_t(100 + mids.size());
        const auto& a = corners[key.first];
        const auto& b = corners[key.second];
        mids.push_back({(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2});
      }
      row[std::size_t(4 + e)] = mid_of[key];
    }
    local.push_back(row);
  }
  REQUIRE(mids.size() == 9);
  std::map<std::uint32_t, std::uint32_t> file_index;  // local -> file
  std::uint32_t next_corner = 0, next_mid = 100;
  for (std::size_t i = 0; i < layout.size(); ++i) {
    const auto at = std::uint32_t(i);
    if (layout[i] == 'c') {
      file_index[next_corner] = at;
      f.nodes.push_back(corners[next_corner++]);
      f.expected_positions.push_back(f.nodes.back());
    } else if (layout[i] == 'm') {
      file_index[next_mid] = at;
      f.nodes.push_back(mids[next_mid++ - 100]);
    } else {
      f.nodes.push_back({7, 7, 7});
      f.expected_positions.push_back(f.nodes.back());
    }
  }
  for (auto row : local) {
    for (auto& v : row) v = file_index.at(v);
    f.tets.push_back(row);
  }
  // Kept vertices in file order: c0 c1 c2 isolated c3 c4 -> 0 1 2 (3) 4 5.
  f.expected_tets = {{0, 1, 2, 4}, {0, 2, 1, 5}};
  return f;
}

std::string number(double x) { return format_double(x); }

std::string point_line(const DoublePoint& p) { return number(p[0]) + " " + number(p[1]) + " " + number(p[2]); }

std::string indices(const std::array<std::uint32_t, 10>& row, std::uint32_t base) {
  std::string s;
  for (auto v : row) {
    s += ' ';  // not " " + to_string(...): g++ 12 warns falsely (-Wrestrict) on that form
    s += std::to_string(v + base);
  }
  return s;
}

void check_corners(const TetMeshData& m, const QuadraticFile& f) {
  CHECK(m.tets == f.expected_tets);
  CHECK(m.dropped_higher_order_nodes == 9);
  REQUIRE(m.positions.size() == f.expected_positions.size());
  for (std::size_t i = 0; i < m.positions.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k) CHECK(to_double(m.positions[i][k]) == f.expected_positions[i][k]);  // decimals: exact, 17 digits
  // Every vertex but the isolated one is a corner of a tet: nothing left for "used by no tet".
  std::vector<bool> used(m.positions.size(), false);
  for (const auto& t : m.tets)
    for (auto v : t) used[v] = true;
  CHECK(std::count(used.begin(), used.end(), false) == 1);
  CHECK_FALSE(used[3]);
}

}  // namespace

TEST_CASE("second-order TetGen .ele: corners kept, mid-edge nodes dropped, vertices renumbered") {
  const auto f = quadratic_two_tets();
  std::string node = std::to_string(f.nodes.size()) + " 3 0 0\n", ele = "2 10 0\n";
  for (std::size_t i = 0; i < f.nodes.size(); ++i) node += std::to_string(i + 1) + " " + point_line(f.nodes[i]) + "\n";
  for (std::size_t t = 0; t < f.tets.size(); ++t) ele += std::to_string(t + 1) + indices(f.tets[t], 1) + "\n";
  check_corners(read_tetgen(node, "q.node", ele, "q.ele"), f);
}

TEST_CASE("second-order VTK type 24, legacy and XML") {
  const auto f = quadratic_two_tets();
  std::string points, cells, vtu_points, vtu_conn;
  for (const auto& p : f.nodes) points += point_line(p) + "\n";
  for (const auto& t : f.tets) cells += "10" + indices(t, 0) + "\n", vtu_conn += indices(t, 0) + "\n";
  check_corners(read_vtk("# vtk DataFile Version 4.2\nq\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 15 double\n" + points +
                             "CELLS 3 26\n" + cells + "3 0 2 3\nCELL_TYPES 3\n24\n24\n5\n",
                         "q.vtk"),
                f);
  const std::string vtu =
      "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid><Piece NumberOfPoints=\"15\" NumberOfCells=\"2\"><Points>"
      "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">" + points + "</DataArray></Points><Cells>"
      "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">" + vtu_conn + "</DataArray>"
      "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">10 20</DataArray>"
      "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">24 24</DataArray></Cells></Piece></UnstructuredGrid></VTKFile>";
  check_corners(read_vtu(vtu, "q.vtu"), f);
}

TEST_CASE("second-order Gmsh type 11, MSH 2.2 and 4.1") {
  const auto f = quadratic_two_tets();
  std::string nodes22, elements22, tags41, coords41, elements41;
  for (std::size_t i = 0; i < f.nodes.size(); ++i) {
    nodes22 += std::to_string(i + 1) + " " + point_line(f.nodes[i]) + "\n";
    tags41 += std::to_string(i + 1) + "\n";
    coords41 += point_line(f.nodes[i]) + "\n";
  }
  for (std::size_t t = 0; t < f.tets.size(); ++t) {
    elements22 += std::to_string(t + 1) + " 11 2 1 1" + indices(f.tets[t], 1) + "\n";
    elements41 += std::to_string(t + 1) + indices(f.tets[t], 1) + "\n";
  }
  check_corners(read_gmsh("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n15\n" + nodes22 + "$EndNodes\n$Elements\n2\n" + elements22 +
                              "$EndElements\n",
                          "q22.msh"),
                f);
  check_corners(read_gmsh("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 15 1 15\n3 1 0 15\n" + tags41 + coords41 +
                              "$EndNodes\n$Elements\n1 2 1 2\n3 1 11 2\n" + elements41 + "$EndElements\n",
                          "q41.msh"),
                f);
}

TEST_CASE("second-order Medit TetrahedraP2") {
  const auto f = quadratic_two_tets();
  std::string text = "MeshVersionFormatted 2\nDimension 3\nVertices\n15\n";
  for (const auto& p : f.nodes) text += point_line(p) + " 0\n";
  text += "TetrahedraP2\n2\n";
  for (const auto& t : f.tets) text += indices(t, 1).substr(1) + " 3\n";
  check_corners(read_medit(text + "End\n", "q.mesh"), f);
}

TEST_CASE("linear and 10-node tets mixed: a node that is a corner of any tet is kept") {
  // Tet 1 is linear (1 2 3 4); tet 2 is quadratic (1 3 2 5) and lists node 4, a corner of tet 1,
  // among its mid-edge nodes, with nodes 6-10.
  std::string nodes = "$Nodes\n10\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 0 0 -1\n";
  for (int i = 6; i <= 10; ++i) nodes += std::to_string(i) + " 0." + std::to_string(i) + " 0.1 0\n";
  const auto m = read_gmsh("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n" + nodes +
                               "$EndNodes\n$Elements\n2\n1 4 0 1 2 3 4\n2 11 0 1 3 2 5 4 6 7 8 9 10\n$EndElements\n",
                           "mixed.msh");
  CHECK(m.positions.size() == 5);
  CHECK(m.dropped_higher_order_nodes == 5);
  CHECK(m.tets == std::vector<Tet>{{0, 1, 2, 3}, {0, 2, 1, 4}});
}

TEST_CASE("linear files keep every vertex and report no dropped nodes") {
  const auto m = read_tetgen("5 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n4 5 5 5\n", "l.node", "1 4 0\n0 0 1 2 3\n", "l.ele");
  CHECK(m.positions.size() == 5);
  CHECK(m.dropped_higher_order_nodes == 0);
}

TEST_CASE("other higher-order 3D cells are refused naming the type and saying second-order") {
  const auto says = [](const std::function<void()>& read, const std::string& type) {
    const auto e = expect_io_error(read, ErrorKind::non_tet_cell);
    CHECK(std::string(e.what()).find("second-order") != std::string::npos);
    CHECK(std::string(e.what()).find(type) != std::string::npos);
  };
  std::string points = "POINTS 20 double\n";
  for (int i = 0; i < 20; ++i) points += std::to_string(i) + " " + std::to_string(i * i) + " " + std::to_string(i * i * i) + "\n";
  std::string hex20 = "20";
  for (int i = 0; i < 20; ++i) (hex20 += ' ') += std::to_string(i);
  says([&] { read_vtk("# vtk DataFile Version 4.2\nq\nASCII\nDATASET UNSTRUCTURED_GRID\n" + points + "CELLS 1 21\n" + hex20 +
                          "\nCELL_TYPES 1\n25\n", "hex20.vtk"); },
       "type 25");
  std::string nodes = "$Nodes\n20\n", tet20 = "1 29 0";
  for (int i = 1; i <= 20; ++i) {
    nodes += std::to_string(i) + " " + std::to_string(i) + " " + std::to_string(i * i) + " 0\n";
    (tet20 += ' ') += std::to_string(i);
  }
  says([&] { read_gmsh("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n" + nodes + "$EndNodes\n$Elements\n1\n" + tet20 + "\n$EndElements\n", "t20.msh"); },
       "type 29");
  says([] { read_medit("MeshVersionFormatted 2\nDimension 3\nVertices\n0\nHexahedraQ2\n1\n", "q2.mesh"); }, "HexahedraQ2");
}
