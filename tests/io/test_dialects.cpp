// Each reader on small hand-written files of each dialect. All describe the unit tetrahedron
// (0,0,0), (1,0,0), (0,1,0), (0,0,1) plus, where useful, extra lower-dimensional cells.
#include <doctest/doctest.h>

#include <cstring>

#include "io/read_mesh.hpp"
#include "io_test_util.hpp"

using namespace cmx;
using namespace cmx::io;
using namespace cmx::io::test;

static void check_unit_tet(const TetMeshData& m, bool flipped = false) {
  REQUIRE(m.positions.size() >= 4);
  CHECK(m.positions[1] == Point3{Rational(1), Rational(0), Rational(0)});
  REQUIRE(m.tets.size() == 1);
  CHECK(m.orientation_flipped == flipped);
  CHECK(m.tets[0] == Tet{0, 1, 2, 3});  // a negatively listed file had (0, 1, 3, 2)
}

TEST_CASE("legacy VTK 4.2 and 5.1 ASCII") {
  const std::string points = "POINTS 4 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  check_unit_tet(read_vtk("# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n" + points +
                              "CELLS 2 8\n4 0 1 2 3\n2 0 1\nCELL_TYPES 2\n10\n3\nCELL_DATA 2\nSCALARS a int 1\n",
                          "a.vtk"));
  check_unit_tet(read_vtk("# vtk DataFile Version 5.1\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n" + points +
                              "METADATA\nINFORMATION 0\n\nCELLS 2 4\nOFFSETS vtktypeint64\n0 4\n"
                              "CONNECTIVITY vtktypeint64\n0 1 2 3\nCELL_TYPES 1\n10\n",
                          "b.vtk"));
  // Exact decimals: 0.1 is read as 1/10, not as the double nearest to it.
  const auto m = read_vtk("# vtk DataFile Version 2.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 float\n"
                          "0.1 0 0\n1 0 0\n0 1 0\n0 0 1\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n",
                          "c.vtk");
  CHECK(m.positions[0][0] == Rational(1, 10));
}

static void put_be(std::string& out, std::uint64_t v, int size) {
  for (int i = size - 1; i >= 0; --i) out += char((v >> (8 * i)) & 0xFF);
}
static void put_be_double(std::string& out, double d) {
  std::uint64_t u;
  std::memcpy(&u, &d, 8);
  put_be(out, u, 8);
}

TEST_CASE("legacy VTK BINARY, 4.2 and 5.1 layouts, big-endian") {
  std::string pts = "POINTS 4 double\n";
  const double coords[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  for (double c : coords) put_be_double(pts, c);
  std::string v4 = "# vtk DataFile Version 4.2\nt\nBINARY\nDATASET UNSTRUCTURED_GRID\n" + pts + "\nCELLS 1 5\n";
  for (int v : {4, 0, 1, 2, 3}) put_be(v4, std::uint64_t(v), 4);
  v4 += "\nCELL_TYPES 1\n";
  put_be(v4, 10, 4);
  v4 += "\n";
  check_unit_tet(read_vtk(v4, "bin42.vtk"));
  std::string v5 = "# vtk DataFile Version 5.1\nt\nBINARY\nDATASET UNSTRUCTURED_GRID\n" + pts +
                   "\nCELLS 2 4\nOFFSETS vtktypeint64\n";
  for (int v : {0, 4}) put_be(v5, std::uint64_t(v), 8);
  v5 += "\nCONNECTIVITY vtktypeint64\n";
  for (int v : {0, 1, 2, 3}) put_be(v5, std::uint64_t(v), 8);
  v5 += "\nCELL_TYPES 1\n";
  put_be(v5, 10, 4);
  check_unit_tet(read_vtk(v5, "bin51.vtk"));
}

TEST_CASE("VTU ascii and raw appended") {
  const std::string ascii =
      "<?xml version=\"1.0\"?>\n<!-- comment -->\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "<UnstructuredGrid><Piece NumberOfPoints=\"4\" NumberOfCells=\"2\">\n"
      "<PointData></PointData><Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">\n"
      "0 0 0 1 0 0 0 1 0 0 0 1</DataArray></Points>\n<Cells>\n"
      "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2 3 0 1 2</DataArray>\n"
      "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">4 7</DataArray>\n"
      "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">10 5</DataArray>\n"
      "</Cells></Piece></UnstructuredGrid></VTKFile>\n";
  check_unit_tet(read_vtu(ascii, "a.vtu"));
  // Appended raw, UInt64 headers, Float64 points, Int64 connectivity, little-endian.
  std::string blob;
  const auto put_le = [&](std::uint64_t v, int size) {
    for (int i = 0; i < size; ++i) blob += char((v >> (8 * i)) & 0xFF);
  };
  put_le(96, 8);
  const double coords[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  for (double c : coords) {
    std::uint64_t u;
    std::memcpy(&u, &c, 8);
    put_le(u, 8);
  }
  const std::size_t conn_offset = blob.size();
  put_le(32, 8);
  for (int v : {0, 1, 2, 3}) put_le(std::uint64_t(v), 8);
  const std::size_t off_offset = blob.size();
  put_le(8, 8);
  put_le(4, 8);
  const std::size_t type_offset = blob.size();
  put_le(1, 8);
  put_le(10, 1);
  const std::string appended =
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      "<UnstructuredGrid><Piece NumberOfPoints=\"4\" NumberOfCells=\"1\"><Points>"
      "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"appended\" offset=\"0\"/></Points><Cells>"
      "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"appended\" offset=\"" + std::to_string(conn_offset) + "\"/>"
      "<DataArray type=\"Int64\" Name=\"offsets\" format=\"appended\" offset=\"" + std::to_string(off_offset) + "\"/>"
      "<DataArray type=\"UInt8\" Name=\"types\" format=\"appended\" offset=\"" + std::to_string(type_offset) + "\"/>"
      "</Cells></Piece></UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n _" + blob + "\n</AppendedData></VTKFile>\n";
  check_unit_tet(read_vtu(appended, "b.vtu"));
}

TEST_CASE("Medit: Dimension on the next line, CRLF, comments, unknown sections, version 2") {
  const std::string text =
      "MeshVersionFormatted 2\r\n# a comment\r\nDimension\r\n3\r\nVertices\r\n4\r\n0 0 0 1\r\n1 0 0 1\r\n0 1 0 1\r\n0 0 1 1\r\n"
      "Triangles\r\n1\r\n1 2 3 7\r\nSomeUnknownKeyword\r\n2\r\nfoo bar\r\nbaz\r\n"
      "Tetrahedra\r\n1\r\n1 2 4 3 0\r\nEnd\r\n";
  check_unit_tet(read_medit(text, "a.mesh"), true);  // listed negatively: flipped
}

TEST_CASE("Gmsh 2.2 ASCII, 2.2 binary and 4.1 ASCII") {
  check_unit_tet(read_gmsh("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n3 1 \"v\"\n$EndPhysicalNames\n"
                           "$Nodes\n4\n10 0 0 0\n20 1 0 0\n30 0 1 0\n40 0 0 1\n$EndNodes\n"
                           "$Elements\n2\n1 2 2 0 1 10 20 30\n2 4 2 1 1 10 20 30 40\n$EndElements\n",
                           "a.msh"));
  std::string bin = "$MeshFormat\n2.2 1 8\n";
  const auto put_le = [&](std::uint64_t v, int size) {
    for (int i = 0; i < size; ++i) bin += char((v >> (8 * i)) & 0xFF);
  };
  put_le(1, 4);
  bin += "\n$EndMeshFormat\n$Nodes\n4\n";
  const double coords[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  for (int i = 0; i < 4; ++i) {
    put_le(std::uint64_t(i + 1), 4);
    for (int k = 0; k < 3; ++k) {
      std::uint64_t u;
      std::memcpy(&u, &coords[3 * i + k], 8);
      put_le(u, 8);
    }
  }
  bin += "\n$EndNodes\n$Elements\n1\n";
  for (int v : {4, 1, 2, 1, 1, 1, 1, 2, 3, 4}) put_le(std::uint64_t(v), 4);  // type, follow, ntags; id, tags, nodes
  bin += "\n$EndElements\n";
  check_unit_tet(read_gmsh(bin, "b.msh"));
  check_unit_tet(read_gmsh("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 0 1\n1 0 0 0 1 1 1 0 0\n$EndEntities\n"
                           "$Nodes\n2 4 1 4\n0 1 0 1\n1\n0 0 0\n3 1 0 3\n2\n3\n4\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n"
                           "$Elements\n2 2 1 2\n2 1 2 1\n1 1 2 3\n3 1 4 1\n2 1 2 3 4\n$EndElements\n",
                           "c.msh"));
}

TEST_CASE("TetGen 0- and 1-based, attributes and markers") {
  check_unit_tet(read_tetgen("# nodes\n4 3 1 1\n1 0 0 0 5 1\n2 1 0 0 5 1\n3 0 1 0 5 1\n4 0 0 1 5 0\n", "a.node",
                             "1 4 1\n1 1 2 3 4 7\n", "a.ele"));
  check_unit_tet(read_tetgen("4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n", "b.node", "1 4 0\n0 0 1 3 2\n", "b.ele"), true);
  // Via the path dispatch: reading the .ele finds the .node.
  const auto dir = temp_dir();
  write_text(dir / "c.node", "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n");
  write_text(dir / "c.ele", "1 4 0\n1 1 2 3 4\n");
  check_unit_tet(read_tet_mesh((dir / "c.ele").string()));
  check_unit_tet(read_tet_mesh((dir / "c.node").string()));
}

TEST_CASE("OVM: properties skipped or kept, and cell order from the first half-face") {
  // Unit tet: edges 0:(0,1) 1:(1,2) 2:(2,0) 3:(0,3) 4:(1,3) 5:(2,3).
  // Faces (vertex cycles): 0:(0,1,2) 1:(0,2,3) 2:(0,3,1) 3:(1,3,2) - all pointing into the tet.
  const std::string text =
      "OVM ASCII\nVertices\n4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\nEdges\n6\n0 1\n1 2\n2 0\n0 3\n1 3\n2 3\n"
      "Faces\n4\n3 0 2 4\n3 5 10 7\n3 6 9 1\n3 8 11 3\nPolyhedra\n1\n4 0 2 4 6\n"
      "VProp int \"some:int\"\n1\n2\n3\n4\nEProp bool \"flag\"\n0\n0\n0\n0\n0\n1\n"
      "VProp string \"str_exact_position\"\n5:0;0;0\n5:1;0;0\n7:0;1/1;0\n5:0;0;1\nCProp double \"q\"\n0.5\n";
  const auto m = read_ovm(text, "a.ovm");
  check_unit_tet(m);
  REQUIRE(m.vertex_string_properties.size() == 1);
  CHECK(m.vertex_string_properties[0].values[2] == "0;1/1;0");
}
