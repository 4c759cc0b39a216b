// Every reader rejects malformed input with an IoError naming the file and the line.
#include <doctest/doctest.h>

#include "io/boundary.hpp"
#include "io/read_mesh.hpp"
#include "io/tmap.hpp"
#include "io_test_util.hpp"

using namespace cmx;
using namespace cmx::io;
using namespace cmx::io::test;

static const std::string vtk_head = "# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n";
static const std::string vtk_points = "POINTS 4 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n";

TEST_CASE("VTK bad input") {
  const auto vtk = [](const std::string& s) { return [s] { read_vtk(s, "bad.vtk"); }; };
  auto e = expect_io_error(vtk(vtk_head + "POINTS 4 double\n0 0 0\n1 0 0\n"), ErrorKind::truncated);
  CHECK(std::string(e.what()).rfind("bad.vtk:", 0) == 0);
  expect_io_error(vtk(vtk_head + "POINTS 1000000000000 double\n0 0 0\n"), ErrorKind::too_large, 5);
  expect_io_error(vtk(vtk_head + "POINTS 4 double\n0 0 0\n1 nan 0\n0 1 0\n0 0 1\n"), ErrorKind::not_finite, 7);
  expect_io_error(vtk(vtk_head + "POINTS 4 double\n0 0 0\n1 inf 0\n0 1 0\n0 0 1\n"), ErrorKind::not_finite, 7);
  expect_io_error(vtk(vtk_head + vtk_points + "CELLS 1 5\n4 0 1 2 9\nCELL_TYPES 1\n10\n"), ErrorKind::index_out_of_range, 11);
  expect_io_error(vtk(vtk_head + vtk_points + "CELLS 1 6\n4 0 1 2 3\nCELL_TYPES 1\n10\n"), ErrorKind::count_mismatch);
  expect_io_error(vtk(vtk_head + vtk_points + "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 2\n10\n10\n"), ErrorKind::count_mismatch);
  expect_io_error(vtk(vtk_head + vtk_points + "CELLS 1 9\n8 0 1 2 3 0 1 2 3\nCELL_TYPES 1\n12\n"), ErrorKind::non_tet_cell, 11);
  expect_io_error(vtk(vtk_head + vtk_points + "CELLS 2 10\n4 0 1 2 3\n4 1 0 2 3\nCELL_TYPES 2\n10\n10\n"), ErrorKind::duplicate, 12);
  expect_io_error(vtk(vtk_head + vtk_points + "CELLS 1 5\n4 0 1 2 2\nCELL_TYPES 1\n10\n"), ErrorKind::degenerate_tet, 11);
  expect_io_error(vtk(vtk_head + "POINTS 4 double\n0 0 0\n1 0 0\n2 0 0\n0 0 1\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n"),
                  ErrorKind::degenerate_tet, 11);
  expect_io_error(vtk("# vtk DataFile Version 4.2\nt\nASCII\nDATASET POLYDATA\n"), ErrorKind::unsupported, 4);
  expect_io_error(vtk("hello"), ErrorKind::syntax, 1);
  expect_io_error(vtk(""), ErrorKind::syntax, 1);
  expect_io_error(vtk(vtk_head + "POINTS 4 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\nCELLS 99999999999 5\n"), ErrorKind::too_large, 10);
  // Binary data cut short.
  expect_io_error(vtk("# vtk DataFile Version 4.2\nt\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 2 double\n\x01\x02"), ErrorKind::truncated);
}

TEST_CASE("OVM bad input") {
  const auto ovm = [](const std::string& s) { return [s] { read_ovm(s, "bad.ovm"); }; };
  expect_io_error(ovm("OVM BINARY\n"), ErrorKind::unsupported, 1);
  expect_io_error(ovm("OVM ASCII\nVertices\n3\n0 0 0\n"), ErrorKind::truncated, 3);
  expect_io_error(ovm("OVM ASCII\nVertices\n2\n0 0 0\n1 1 1\nEdges\n1\n0 5\n"), ErrorKind::index_out_of_range, 8);
  expect_io_error(ovm("OVM ASCII\nVertices\n100000000000\n0 0 0\n"), ErrorKind::too_large, 3);
  expect_io_error(ovm("OVM ASCII\nVertices\n3\n0 0 0\n1 0 0\n0 1 0\nEdges\n3\n0 1\n1 2\n2 0\nFaces\n1\n4 0 2 4 1\n"), ErrorKind::non_tet_cell, 14);
  expect_io_error(ovm("OVM ASCII\nVertices\n3\n0 0 0\n1 0 0\n0 1 0\nEdges\n3\n0 1\n1 2\n2 0\nFaces\n1\n3 0 3 4\n"), ErrorKind::syntax, 14);
  expect_io_error(ovm("OVM ASCII\nVertices\n1\n0 NaN 0\n"), ErrorKind::not_finite, 4);
  expect_io_error(ovm("OVM ASCII\nVertices\n0\nEdges\n0\nFaces\n0\nPolyhedra\n0\nVProp string s\n"), ErrorKind::syntax, 10);
  expect_io_error(ovm("OVM ASCII\nVertices\n1\n0 0 0\nEdges\n0\nFaces\n0\nPolyhedra\n0\nVProp string \"s\"\n99:abc\n"), ErrorKind::truncated, 12);
  expect_io_error(ovm("OVM ASCII\nVertices\n1\n0 0 0\nEdges\n0\nFaces\n0\nPolyhedra\n0\nWhat\n"), ErrorKind::syntax, 11);
}

TEST_CASE("Medit bad input") {
  const auto medit = [](const std::string& s) { return [s] { read_medit(s, "bad.mesh"); }; };
  const std::string head = "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n";
  expect_io_error(medit(head + "Tetrahedra\n1\n1 2 3 5 0\n"), ErrorKind::index_out_of_range, 11);
  expect_io_error(medit(head + "Tetrahedra\n1\n0 1 2 3 0\n"), ErrorKind::index_out_of_range, 11);
  expect_io_error(medit(head + "Tetrahedra\n2\n1 2 3 4 0\n"), ErrorKind::truncated);
  expect_io_error(medit(head + "Hexahedra\n1\n1 2 3 4 1 2 3 4 0\nTetrahedra\n1\n1 2 3 4 0\n"), ErrorKind::non_tet_cell, 10);
  expect_io_error(medit("MeshVersionFormatted 1\nDimension 2\n"), ErrorKind::unsupported, 2);
  expect_io_error(medit("Dimension 3\nVertices\n0\n"), ErrorKind::syntax, 1);
  expect_io_error(medit("MeshVersionFormatted 1\nDimension 3\nVertices\n4000000000\n"), ErrorKind::truncated, 4);
}

TEST_CASE("Gmsh bad input") {
  const auto msh = [](const std::string& s) { return [s] { read_gmsh(s, "bad.msh"); }; };
  const std::string head = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n";
  expect_io_error(msh(head + "$Elements\n1\n1 4 0 1 2 3 9\n$EndElements\n"), ErrorKind::index_out_of_range, 13);
  expect_io_error(msh(head + "$Elements\n1\n1 5 0 1 2 3 4 1 2 3 4\n$EndElements\n"), ErrorKind::non_tet_cell, 13);
  expect_io_error(msh(head + "$Elements\n2\n1 4 0 1 2 3 4\n$EndElements\n"), ErrorKind::syntax);
  expect_io_error(msh(head + "$Elements\n1\n1 4 0 1 2 3 4 5\n$EndElements\n"), ErrorKind::count_mismatch, 13);
  expect_io_error(msh("$MeshFormat\n3.0 0 8\n$EndMeshFormat\n"), ErrorKind::unsupported, 2);
  expect_io_error(msh("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\n1 1 1 1\n$EndNodes\n"), ErrorKind::duplicate, 7);
  expect_io_error(msh("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n99999999999\n"), ErrorKind::too_large, 5);
}

TEST_CASE("TetGen bad input") {
  expect_io_error([] { read_tetgen("4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n", "b.node", "1 4 0\n1 1 2 3 5\n", "b.ele"); },
                  ErrorKind::index_out_of_range, 2);
  expect_io_error([] { read_tetgen("4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n", "b.node", "1 4 0\n1 0 2 3 4\n", "b.ele"); },
                  ErrorKind::index_out_of_range, 2);
  expect_io_error([] { read_tetgen("4 3 0 0\n1 0 0 0\n3 1 0 0\n2 0 1 0\n4 0 0 1\n", "b.node", "", "b.ele"); }, ErrorKind::syntax, 3);
  expect_io_error([] { read_tetgen("2 3 0 0\n1 0 0 0\n", "b.node", "", "b.ele"); }, ErrorKind::truncated);
  expect_io_error([] { read_tetgen("4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n", "b.node", "1 8 0\n", "b.ele"); },
                  ErrorKind::non_tet_cell, 1);
}

TEST_CASE("VTU bad input") {
  const auto vtu = [](const std::string& s) { return [s] { read_vtu(s, "bad.vtu"); }; };
  expect_io_error(vtu("<VTKFile type=\"PolyData\">"), ErrorKind::unsupported, 1);
  expect_io_error(vtu("<VTKFile type=\"UnstructuredGrid\" compressor=\"vtkLZ4DataCompressor\">"), ErrorKind::unsupported, 1);
  expect_io_error(vtu("<VTKFile type=\"UnstructuredGrid\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"99999999\" NumberOfCells=\"1\">"),
                  ErrorKind::too_large, 3);
  expect_io_error(vtu("<VTKFile type=\"UnstructuredGrid\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"1\" NumberOfCells=\"0\">\n<Points>\n"
                      "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">0 0</DataArray></Points>\n<Cells>"
                      "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\"></DataArray>"
                      "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\"></DataArray>"
                      "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\"></DataArray></Cells></Piece></UnstructuredGrid></VTKFile>"),
                  ErrorKind::truncated, 5);
  expect_io_error(vtu("<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid><Piece NumberOfPoints=\"1\" NumberOfCells=\"0\">"
                      "<Points><DataArray type=\"Float64\" format=\"binary\">AAAA</DataArray></Points><Cells>"
                      "<DataArray Name=\"connectivity\"/><DataArray Name=\"offsets\"/><DataArray Name=\"types\"/></Cells></Piece>"),
                  ErrorKind::truncated, 1);  // "AAAA" is 3 bytes: less than the 4-byte block header
}

TEST_CASE("orientation normalisation: all negative flipped, mixed rejected naming the minority tet") {
  // Three positive tets around the z axis and one negative one listed third.
  const std::string head = vtk_head + "POINTS 6 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n-1 0 0\n0 -1 0\n";
  const auto mesh = read_vtk(head + "CELLS 2 10\n4 0 2 1 3\n4 0 4 2 3\nCELL_TYPES 2\n10\n10\n", "neg.vtk");
  CHECK(mesh.orientation_flipped);
  CHECK(mesh.tets == std::vector<Tet>{{0, 2, 3, 1}, {0, 4, 3, 2}});
  const auto e = expect_io_error(
      [&] { read_vtk(head + "CELLS 3 15\n4 0 1 2 3\n4 0 2 4 3\n4 0 5 4 3\nCELL_TYPES 3\n10\n10\n10\n", "mixed.vtk"); },
      ErrorKind::inconsistent_orientation, 15);
  CHECK(e.message().find("tet 2") != std::string::npos);
  // keep: no check at all.
  ReadOptions keep;
  keep.orientation = Orientation::keep;
  CHECK(read_vtk(head + "CELLS 3 15\n4 0 1 2 3\n4 0 2 4 3\n4 0 5 4 3\nCELL_TYPES 3\n10\n10\n10\n", "mixed.vtk", keep).tets.size() == 3);
  // allow_degenerate: positions without geometry are accepted.
  ReadOptions flat;
  flat.allow_degenerate = true;
  const auto zero = read_vtk(vtk_head + "POINTS 4 double\n0 0 0\n0 0 0\n0 0 0\n0 0 0\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n", "z.vtk", flat);
  CHECK_FALSE(zero.orientation_flipped);
}

TEST_CASE("boundary files: exact numbers, comments, and every kind of error with file:line") {
  const auto b = parse_boundary_positions("# header\n\n3 0.1 -1/3 0x1.8p1\n0 1 2 3  # trailing\n", "b.txt", 5);
  CHECK(b.vertices == std::vector<std::uint32_t>{3, 0});
  CHECK(b.positions[0] == Point3{Rational(1, 10), Rational(-1, 3), Rational(3)});
  const auto bad = [](const std::string& s) { return [s] { parse_boundary_positions(s, "b.txt", 5); }; };
  expect_io_error(bad("0 1 2 3\n\n0 1 2 3\n"), ErrorKind::duplicate, 3);
  expect_io_error(bad("5 1 2 3\n"), ErrorKind::index_out_of_range, 1);
  expect_io_error(bad("1 1 2\n"), ErrorKind::count_mismatch, 1);
  expect_io_error(bad("1 1 2 3 4\n"), ErrorKind::count_mismatch, 1);
  expect_io_error(bad("1 1 nan 3\n"), ErrorKind::not_finite, 1);
  expect_io_error(bad("\n\n-1 1 2 3\n"), ErrorKind::syntax, 3);
  expect_io_error(bad("1 1 2 1/0\n"), ErrorKind::syntax, 1);
  expect_io_error([] { read_boundary_positions(std::string("/nonexistent/b.txt"), 5); }, ErrorKind::open_failed);
}

TEST_CASE("codomain boundary: identical connectivity required") {
  auto domain = two_tets();
  auto codomain = two_tets();
  for (auto& p : codomain.positions) p[0] += 10;
  std::swap(codomain.tets[0][0], codomain.tets[0][1]);  // order within a tet does not matter
  const auto b = read_boundary_positions_from_codomain(domain, codomain, "c.vtk");
  CHECK(b.vertices == std::vector<std::uint32_t>{0, 1, 2, 3, 4});
  CHECK(b.positions[1][0] == 11);
  codomain.tets[1][3] = 3;
  expect_io_error([&] { read_boundary_positions_from_codomain(domain, codomain, "c.vtk"); }, ErrorKind::mismatch);
  codomain.positions.pop_back();
  expect_io_error([&] { read_boundary_positions_from_codomain(domain, codomain, "c.vtk"); }, ErrorKind::mismatch);
  // Interior vertices are not part of the boundary.
  const auto grid = grid_mesh(2);
  const auto boundary = mesh_boundary(grid);
  CHECK(boundary.vertices.size() == 26);
  CHECK(boundary.faces.size() == 6 * 8);
}

TEST_CASE("tmap bad input") {
  const auto tm = [](const std::string& s) { return [s] { parse_tmap(s, "bad.tmap"); }; };
  const std::string verts = "tmap 1\nvertices 4\n0 0 0 0 0 0\n1 0 0 2 0 0\n0 1 0 0 2 0\n0 0 1 0 0 2\n";
  CHECK(parse_tmap(verts + "tets 1\n0 1 2 3\n", "ok.tmap").tets.size() == 1);
  expect_io_error(tm(verts + "tets 1\n0 1 3 2\n"), ErrorKind::inconsistent_orientation, 8);
  expect_io_error(tm("tmap 1\nvertices 4\n0 0 0 0 0 0\n1 0 0 0 0 0\n0 1 0 0 2 0\n0 0 1 0 0 2\ntets 1\n0 1 2 3\n"), ErrorKind::degenerate_tet, 8);
  expect_io_error(tm(verts + "tets 1\n0 1 2 4\n"), ErrorKind::index_out_of_range, 8);
  expect_io_error(tm(verts + "tets 2\n0 1 2 3\n"), ErrorKind::truncated);
  expect_io_error(tm(verts + "tets 2\n0 1 2 3\n1 0 3 2\n"), ErrorKind::duplicate, 9);
  expect_io_error(tm("tmap 2\n"), ErrorKind::unsupported, 1);
  expect_io_error(tm("tmap 1\nvertices 1\n0 0 0 0 0\ntets 0\n"), ErrorKind::syntax, 4);
  expect_io_error(tm("tmap 1\nvertices 1\n0 0 0 0 0 0 0\ntets 0\n"), ErrorKind::count_mismatch, 3);
  expect_io_error(tm("tmap 1\nvertices 99999999999\n"), ErrorKind::too_large, 2);
}

TEST_CASE("unknown extension and missing file") {
  expect_io_error([] { read_tet_mesh("x.obj"); }, ErrorKind::unsupported);
  expect_io_error([] { read_tet_mesh("/nonexistent/x.vtk"); }, ErrorKind::open_failed);
}
