// Write -> read round-trips of every format: identical connectivity; positions exact for OVM
// (exact property) and tmap, equal after rounding to the nearest double for display formats.
#include <doctest/doctest.h>

#include <cmath>

#include "arith/rounding.hpp"
#include "io/atomic_file.hpp"
#include "io/read_mesh.hpp"
#include "io/tmap.hpp"
#include "io/write_mesh.hpp"
#include "io_test_util.hpp"

using namespace cmx;
using namespace cmx::io;
using namespace cmx::io::test;

static void check_same_doubles(const TetMeshData& a, const TetMeshData& b) {
  REQUIRE(a.positions.size() == b.positions.size());
  for (std::size_t i = 0; i < a.positions.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k) CHECK(to_double(a.positions[i][k]) == to_double(b.positions[i][k]));
}

TEST_CASE("display formats round-trip connectivity and doubles") {
  const auto dir = temp_dir();
  for (const auto& mesh : {two_tets(), grid_mesh(3)}) {
    for (const char* ext : {"vtu", "vtk", "mesh", "msh", "ovm"}) {
      CAPTURE(ext);
      const auto path = (dir / (std::string("m.") + ext)).string();
      write_tet_mesh(path, mesh);
      const auto back = read_tet_mesh(path);
      CHECK(back.tets == mesh.tets);
      CHECK_FALSE(back.orientation_flipped);
      check_same_doubles(mesh, back);
    }
  }
}

TEST_CASE("OVM keeps exact positions and string properties") {
  const auto dir = temp_dir();
  auto mesh = two_tets();
  mesh.vertex_string_properties.push_back({"label", {"a", "b c", "", "d;e", "5:x"}});
  const auto path = (dir / "exact.ovm").string();
  write_tet_mesh(path, mesh);
  const auto back = read_tet_mesh(path);
  CHECK(back.positions == mesh.positions);
  CHECK(back.tets == mesh.tets);
  REQUIRE(back.vertex_string_properties.size() == 2);
  CHECK(back.vertex_string_properties[0].name == "str_exact_position");
  CHECK(back.vertex_string_properties[0].values[3] == "1/3;1/3;1/1");
  CHECK(back.vertex_string_properties[1].name == "label");
  CHECK(back.vertex_string_properties[1].values == mesh.vertex_string_properties[0].values);
  // Without the exact property, the doubles are what is read.
  ReadOptions doubles;
  doubles.use_exact_position_property = false;
  const auto rounded = read_tet_mesh(path, doubles);
  CHECK(rounded.positions[3][0] != Rational(1, 3));
  CHECK(to_double(rounded.positions[3][0]) == to_double(Rational(1, 3)));
}

TEST_CASE("OVM writer's half-face structure gives the documented cell order") {
  // Read with orientation kept: the cell order recovered from the half-faces must be the tets
  // exactly as written (first half-face cycle, then the remaining vertex).
  const auto dir = temp_dir();
  const auto mesh = grid_mesh(2);
  const auto path = (dir / "g.ovm").string();
  write_tet_mesh(path, mesh);
  ReadOptions keep;
  keep.orientation = Orientation::keep;
  CHECK(read_tet_mesh(path, keep).tets == mesh.tets);
  const auto text = slurp(path);
  CHECK(text.rfind("OVM ASCII\nVertices\n27\n", 0) == 0);
}

TEST_CASE("tmap round-trips exactly") {
  const auto dir = temp_dir();
  const auto mesh = grid_mesh(2);
  TetMap map;
  map.source = mesh.positions;
  for (const auto& p : mesh.positions) {
    Point3 t{p[0] * 2 + Rational(1, 7), p[1] * 3, p[2] + Rational(-5, 11)};
    for (auto& c : t) c.canonicalize();
    map.target.push_back(t);
  }
  map.tets = mesh.tets;
  const auto path = (dir / "m.tmap").string();
  write_tmap(path, map);
  const auto back = read_tmap(path);
  CHECK(back.source == map.source);
  CHECK(back.target == map.target);
  CHECK(back.tets == map.tets);
  const auto text = slurp(path);
  CHECK(text.rfind("tmap 1\nvertices 27\n0 0 0 1/7 0 -5/11\n", 0) == 0);
}

TEST_CASE("writers are atomic: a failing write leaves the old file") {
  const auto dir = temp_dir();
  const auto path = (dir / "keep.vtk").string();
  write_text(path, "old content");
  auto bad = two_tets();
  bad.tets.push_back({0, 1, 2, 99});  // index out of range -> the writer refuses
  expect_io_error([&] { write_tet_mesh(path, bad); }, ErrorKind::index_out_of_range);
  CHECK(slurp(path) == "old content");
  std::vector<DoublePoint> nan_points{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, std::nan("")}};
  expect_io_error([&] { write_vtu(path, nan_points, {{0, 1, 2, 3}}); }, ErrorKind::not_finite);
  CHECK(slurp(path) == "old content");
  // An unwritable directory: write_failed, nothing created.
  expect_io_error([&] { write_tet_mesh((dir / "missing" / "x.vtk").string(), two_tets()); }, ErrorKind::write_failed);
  // No temporary files are left behind.
  std::size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
  CHECK(files == 1);
}

TEST_CASE("synced writes: the same bytes, in a subdirectory and in the working directory") {
  const auto dir = temp_dir();
  REQUIRE(output_durability() == Durability::atomic);  // the default
  set_output_durability(Durability::synced);
  const auto restore = [] { set_output_durability(Durability::atomic); };
  const auto path = (dir / "synced.vtk").string();
  const auto cwd = std::filesystem::current_path();
  try {
    write_tet_mesh(path, two_tets());
    const std::string synced = slurp(path);
    std::filesystem::current_path(dir);
    write_tet_mesh("here.vtk", two_tets());  // no directory in the name: the directory is "."
    std::filesystem::current_path(cwd);
    set_output_durability(Durability::atomic);
    write_tet_mesh((dir / "plain.vtk").string(), two_tets());
    CHECK(synced == slurp((dir / "plain.vtk").string()));
    CHECK(slurp((dir / "here.vtk").string()) == synced);
  } catch (...) {
    std::filesystem::current_path(cwd);
    restore();
    throw;
  }
  restore();
  std::size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
  CHECK(files == 3);  // no temporaries left
}
