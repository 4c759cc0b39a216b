// Display outputs with point and cell data (VTU, VTK, Gmsh 4.1), the fields of a map
// (io/map_fields.hpp) on tets whose volumes and angles are known, the TetGen writer, and .tmap as
// a source of meshes.
#include <doctest/doctest.h>

#include <cmath>

#include "io/map_fields.hpp"
#include "io/read_mesh.hpp"
#include "io/tmap.hpp"
#include "io/write_mesh.hpp"
#include "io_test_util.hpp"

using namespace cmx;
using namespace cmx::io;
using namespace cmx::io::test;

namespace {

constexpr double degrees = 180 / 3.14159265358979323846;

const CellScalarField& cell_field(const DisplayFields& f, const std::string& name) {
  for (const auto& c : f.cell_scalars)
    if (c.name == name) return c;
  FAIL("no cell field " << name);
  return f.cell_scalars.front();
}

}  // namespace

TEST_CASE("map fields: volumes and smallest dihedral angles of known tets") {
  // The regular tet of edge 2*sqrt(2) (volume edge^3 / (6 sqrt 2) = 8/3, dihedral acos(1/3)), listed positively.
  const std::vector<DoublePoint> regular = {{1, 1, 1}, {1, -1, -1}, {-1, -1, 1}, {-1, 1, -1}};
  CHECK(signed_volume(regular[0], regular[1], regular[2], regular[3]) == doctest::Approx(8.0 / 3).epsilon(1e-14));
  CHECK(min_dihedral_angle_deg(regular[0], regular[1], regular[2], regular[3]) == doctest::Approx(std::acos(1.0 / 3) * degrees).epsilon(1e-13));
  CHECK(min_dihedral_angle_deg(regular[0], regular[1], regular[2], regular[3]) == doctest::Approx(70.528779365509308).epsilon(1e-13));
  // The right-corner tet: volume 1/6; angles 90 at the three axis edges, acos(1/sqrt 3) at the others.
  const DoublePoint o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  CHECK(signed_volume(o, x, y, z) == 1.0 / 6);
  CHECK(signed_volume(o, x, z, y) == -1.0 / 6);
  CHECK(min_dihedral_angle_deg(o, x, y, z) == doctest::Approx(std::acos(1 / std::sqrt(3.0)) * degrees).epsilon(1e-13));
  CHECK(min_dihedral_angle_deg(o, x, z, y) == doctest::Approx(54.735610317245346).epsilon(1e-13));  // orientation-independent
  // A long thin tet: a sliver's smallest angle is small.
  CHECK(min_dihedral_angle_deg(o, x, y, {0.3, 0.3, 0.01}) < 5);
  // Flat tets (four coplanar points, or a repeated point) have angle 0 and volume 0.
  CHECK(min_dihedral_angle_deg(o, x, y, {1, 1, 0}) == 0);
  CHECK(min_dihedral_angle_deg(o, x, x, z) == 0);
  CHECK(signed_volume(o, x, y, {1, 1, 0}) == 0);
}

TEST_CASE("map fields: source vectors, added tets, volumes on both sides") {
  const std::vector<DoublePoint> source = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<DoublePoint> target;
  for (const auto& p : source) target.push_back({2 * p[0], 2 * p[1], 2 * p[2]});
  const std::vector<Tet> tets = {{0, 1, 2, 3}, {0, 2, 1, 4}};
  const auto fields = map_display_fields(source, target, tets, 4);  // vertex 4 was added by refinement
  REQUIRE(fields.point_vectors.size() == 1);
  CHECK(fields.point_vectors[0].name == "source");
  CHECK(fields.point_vectors[0].values == source);
  const auto& added = cell_field(fields, "added");
  CHECK(added.type == ScalarType::uint8);
  CHECK(added.values == std::vector<double>{0, 1});
  CHECK(cell_field(fields, "source_volume").values == std::vector<double>{1.0 / 6, 1.0 / 6});
  CHECK(cell_field(fields, "target_volume").values == std::vector<double>{8.0 / 6, 8.0 / 6});
  CHECK(cell_field(fields, "min_dihedral_deg").values[1] == doctest::Approx(54.735610317245346).epsilon(1e-13));
  expect_io_error([&] { map_display_fields(source, {target.begin(), target.end() - 1}, tets, 4); }, ErrorKind::mismatch);
  expect_io_error([&] { map_display_fields(source, target, {{0, 1, 2, 9}}, 4); }, ErrorKind::index_out_of_range);
}

TEST_CASE("VTU, VTK and Gmsh 4.1 carry the fields and cmx still reads the files") {
  const auto dir = temp_dir();
  const auto mesh = grid_mesh(2);
  const auto points = nearest_doubles(mesh.positions);
  const auto fields = map_display_fields(points, points, mesh.tets, 20);
  const struct {
    const char* file;
    std::vector<std::string> expected;
  } cases[] = {
      {"f.vtu", {"<PointData Vectors=\"source\">", "Name=\"source\" NumberOfComponents=\"3\"", "<DataArray type=\"UInt8\" Name=\"added\"",
                 "<DataArray type=\"Float64\" Name=\"min_dihedral_deg\""}},
      {"f.vtk", {"POINT_DATA 27\nVECTORS source double\n", "CELL_DATA 48\nSCALARS added unsigned_char 1\nLOOKUP_TABLE default\n",
                 "SCALARS target_volume double 1\n"}},
      {"f.msh", {"$NodeData\n1\n\"source\"\n1\n0\n3\n0\n3\n27\n1 ", "$ElementData\n1\n\"added\"\n1\n0\n3\n0\n1\n48\n1 ",
                 "\"source_volume\""}},
  };
  for (const auto& c : cases) {
    CAPTURE(c.file);
    const auto path = (dir / c.file).string();
    write_display_mesh(path, points, mesh.tets, fields);
    CHECK(carries_display_fields(path));
    const std::string text = slurp(path);
    for (const auto& e : c.expected) CHECK(text.find(e) != std::string::npos);
    const auto back = read_tet_mesh(path);
    CHECK(back.tets == mesh.tets);
    CHECK(back.positions.size() == 27);
  }
  // Formats without a place for fields write the mesh alone.
  write_display_mesh((dir / "f.mesh").string(), points, mesh.tets, fields);
  CHECK_FALSE(carries_display_fields("f.mesh"));
  CHECK(read_tet_mesh((dir / "f.mesh").string()).tets == mesh.tets);
  expect_io_error([&] { write_display_mesh((dir / "f.ovm").string(), points, mesh.tets, fields); }, ErrorKind::unsupported);
}

TEST_CASE("bad fields are refused before anything is written") {
  const auto dir = temp_dir();
  const auto path = (dir / "keep.vtu").string();
  write_text(path, "earlier result");
  const std::vector<DoublePoint> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<Tet> tets = {{0, 1, 2, 3}};
  const auto refused = [&](DisplayFields f, ErrorKind kind) {
    expect_io_error([&] { write_vtu(path, points, tets, f); }, kind);
    expect_io_error([&] { write_vtk(path, points, tets, f); }, kind);
    expect_io_error([&] { write_gmsh41(path, points, tets, f); }, kind);
  };
  refused({{{"short", {{0, 0, 0}}}}, {}}, ErrorKind::mismatch);
  refused({{}, {{"nan", ScalarType::float64, {std::nan("")}}}}, ErrorKind::not_finite);
  refused({{}, {{"big", ScalarType::uint8, {300}}}}, ErrorKind::mismatch);
  refused({{}, {{"has space", ScalarType::float64, {1}}}}, ErrorKind::syntax);
  refused({{}, {{"", ScalarType::float64, {1}}}}, ErrorKind::syntax);
  refused({{}, {{"twice", ScalarType::float64, {1}}, {"twice", ScalarType::float64, {2}}}}, ErrorKind::syntax);
  CHECK(slurp(path) == "earlier result");
}

TEST_CASE("TetGen writer: both files, 0-based, read back, .node and .ele are writable paths") {
  const auto dir = temp_dir();
  const auto mesh = grid_mesh(2);
  CHECK(is_writable_mesh_path("a.node"));
  CHECK(is_writable_mesh_path("a.ELE"));
  for (const char* name : {"t.node", "u.ele", "V.NODE"}) {
    CAPTURE(name);
    const auto path = (dir / name).string();
    write_tet_mesh(path, mesh);
    const auto files = tetgen_paths(path);
    const std::string node = slurp(files.node), ele = slurp(files.ele);
    CHECK(node.find("\n27 3 0 0\n0 0 0 0\n1 ") != std::string::npos);
    CHECK(ele.find("\n48 4 0\n0 ") != std::string::npos);
    const auto back = read_tet_mesh(path);
    CHECK(back.tets == mesh.tets);
    CHECK(back.positions.size() == 27);
  }
  CHECK(tetgen_paths((dir / "V.NODE").string()).ele == (dir / "V.ele").string());
  expect_io_error([] { tetgen_paths("x.vtk"); }, ErrorKind::unsupported);
}

TEST_CASE("TetGen writer: a failure leaves both existing files as they were") {
  const auto dir = temp_dir();
  const auto node = (dir / "p.node").string(), ele = (dir / "p.ele").string();
  write_text(node, "old node");
  write_text(ele, "old ele");
  expect_io_error([&] { write_tetgen(node, {{0, 0, std::nan("")}}, {}); }, ErrorKind::not_finite);
  expect_io_error([&] { write_tetgen(ele, {{0, 0, 0}}, {{0, 0, 0, 7}}); }, ErrorKind::index_out_of_range);
  CHECK(slurp(node) == "old node");
  CHECK(slurp(ele) == "old ele");
  // A missing directory: nothing is created.
  expect_io_error([&] { write_tetgen((dir / "missing" / "q.node").string(), {{0, 0, 0}}, {}); }, ErrorKind::write_failed);
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++files;
  CHECK(files == 2);
}

TEST_CASE(".tmap as a mesh: the caller picks source or target, read_tet_mesh refuses it") {
  const auto dir = temp_dir();
  const auto mesh = two_tets();
  TetMap map;
  map.source = mesh.positions;
  for (const auto& p : mesh.positions) map.target.push_back({p[0] * 2, p[1] * 3, p[2] + 1});
  map.tets = mesh.tets;
  const auto path = (dir / "m.tmap").string();
  write_tmap(path, map);
  const auto source = read_map_as_mesh(path, MapGeometry::source);
  const auto target = read_map_as_mesh(path, MapGeometry::target);
  CHECK(source.positions == map.source);  // exact
  CHECK(target.positions == map.target);
  CHECK(source.tets == map.tets);
  CHECK(target.tets == map.tets);
  CHECK(mesh_of_map(map, MapGeometry::target).positions[4][0] == Rational(2, 5));
  CHECK(is_map_path("X.TMAP"));
  CHECK_FALSE(is_readable_mesh_path(path));
  const auto e = expect_io_error([&] { read_tet_mesh(path); }, ErrorKind::unsupported);
  CHECK(std::string(e.what()).find(".tmap") != std::string::npos);
  // A converted map is any display format, e.g. for a viewer.
  write_tet_mesh((dir / "m.vtu").string(), target);
  CHECK(read_tet_mesh((dir / "m.vtu").string()).tets == map.tets);
  TetMap bad = map;
  bad.target.pop_back();
  expect_io_error([&] { mesh_of_map(bad, MapGeometry::source); }, ErrorKind::mismatch);
}
