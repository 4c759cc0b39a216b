// cmx/io.hpp: write then read in every format gives the same doubles and tets; exact formats keep
// exact coordinates; every failure is a cmx::Error naming the file; a failed write keeps the file.
#include <doctest/doctest.h>

#include <filesystem>
#include <limits>
#include <string>

#include "api_test_util.hpp"
#include "cmx/io.hpp"
#include "io/io_test_util.hpp"

namespace {

using cmx::test::error_of;

// Two positive tets on the face (0, 1, 2), coordinates that need all 17 digits.
cmx::Mesh two_tets() {
  cmx::Mesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1.0 / 3, 0.1, 1}, {0.2, 1.0 / 7, -2}};
  m.tets = {{0, 1, 2, 3}, {0, 2, 1, 4}};
  return m;
}

std::string path_in(const std::filesystem::path& dir, const std::string& name) {
  return (dir / name).string();
}

}  // namespace

TEST_CASE("api write and read: a round trip in every mesh format keeps doubles and tets") {
  const auto dir = cmx::io::test::temp_dir();
  const cmx::Mesh m = two_tets();
  for (const char* ext : {"ovm", "vtu", "vtk", "mesh", "msh", "node", "ele", "OVM", "Mesh"}) {
    INFO("format ." << ext);
    const std::string path = path_in(dir, std::string("m_") + ext + "." + ext);
    cmx::write(path, m);
    const cmx::Mesh r = cmx::read(path);
    CHECK(r.points == m.points);
    CHECK(r.tets == m.tets);
    CHECK(r.points_exact.size() == m.points.size());  // every format is read exactly
    CHECK(r.target.empty());
    CHECK(r.target_exact.empty());
  }
  // TetGen: one call writes both files, and either name reads them.
  CHECK(std::filesystem::exists(dir / "m_node.ele"));
  CHECK(cmx::read(path_in(dir, "m_node.ele")).points == m.points);
}

TEST_CASE("api write and read: exact coordinates survive .ovm and .tmap") {
  const auto dir = cmx::io::test::temp_dir();
  cmx::Mesh m;
  m.points_exact = {
      {"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"}, {"1/3", "1/3", "1"}, {"0.2", "1/7", "-2"}};
  m.tets = {{0, 1, 2, 3}, {0, 2, 1, 4}};
  const cmx::ExactPoint3 canonical{"1/5", "1/7", "-2"};
  const std::string ovm = path_in(dir, "exact.ovm");
  cmx::write(ovm, m);  // points empty: the nearest doubles are written beside the exact property
  const cmx::Mesh r = cmx::read(ovm);
  CHECK(r.points_exact[3] == cmx::ExactPoint3{"1/3", "1/3", "1"});
  CHECK(r.points_exact[4] == canonical);
  CHECK(r.points[3] == cmx::Point3d{1.0 / 3, 1.0 / 3, 1});
  CHECK(r.tets == m.tets);

  // A map: source as given, target scaled by 2 with a fraction (positive in both).
  m.target_exact = {
      {"0", "0", "0"}, {"2", "0", "0"}, {"0", "2", "0"}, {"2/3", "2/3", "2"}, {"2/5", "2/7", "-4"}};
  const std::string tmap = path_in(dir, "exact.tmap");
  cmx::write(tmap, m);
  const cmx::Mesh t = cmx::read(tmap);
  CHECK(t.points_exact[4] == canonical);
  CHECK(t.target_exact == m.target_exact);
  CHECK(t.target[3] == cmx::Point3d{2.0 / 3, 2.0 / 3, 2});
  CHECK(t.points[4] == cmx::Point3d{0.2, 1.0 / 7, -2});
  CHECK(t.tets == m.tets);

  // Doubles as the target of a map are taken exactly.
  cmx::Mesh d = two_tets();
  d.target = d.points;
  cmx::write(path_in(dir, "doubles.tmap"), d);
  const cmx::Mesh dt = cmx::read(path_in(dir, "doubles.tmap"));
  CHECK(dt.target == d.points);
  CHECK(dt.points == d.points);
}

TEST_CASE("api read: a missing, malformed or unknown file throws cmx::Error naming it") {
  const auto dir = cmx::io::test::temp_dir();
  const std::string missing = path_in(dir, "missing.vtu");
  CHECK(error_of([&] { (void)cmx::read(missing); }).find(missing) != std::string::npos);
  const std::string medit = cmx::io::test::write_text(
      dir / "bad.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n2\n0 0 0 0\n1 zero 0 0\nEnd\n");
  const std::string m = error_of([&] { (void)cmx::read(medit); });
  CHECK(m.find(medit + ":6") != std::string::npos);  // file and line
  const std::string stl = cmx::io::test::write_text(dir / "x.stl", "solid x\n");
  CHECK(error_of([&] { (void)cmx::read(stl); }).find("unknown mesh format '.stl'") != std::string::npos);
  const std::string tmap = cmx::io::test::write_text(dir / "bad.tmap", "tmap 1\nvertices 1\n0 0 0 0 0\n");
  CHECK(error_of([&] { (void)cmx::read(tmap); }).find(tmap) != std::string::npos);
  // A tet listed with the other orientation among positive ones: inconsistent, refused.
  cmx::Mesh mixed = two_tets();
  mixed.tets[1] = {0, 1, 2, 4};
  const std::string vtk = path_in(dir, "mixed.vtk");
  cmx::write(vtk, mixed);  // written as given
  CHECK(error_of([&] { (void)cmx::read(vtk); }).find(vtk) != std::string::npos);
}

TEST_CASE("api write: bad meshes throw cmx::Error naming the file and keep an existing file") {
  const auto dir = cmx::io::test::temp_dir();
  const std::string path = path_in(dir, "keep.vtu");
  cmx::write(path, two_tets());
  const std::string before = cmx::io::test::slurp(path);

  cmx::Mesh bad_index = two_tets();
  bad_index.tets[1][3] = 9;
  CHECK(error_of([&] { cmx::write(path, bad_index); }).find(path) != std::string::npos);
  cmx::Mesh nan = two_tets();
  nan.points[2][1] = std::numeric_limits<double>::quiet_NaN();
  CHECK(error_of([&] { cmx::write(path, nan); }).find("point 2, coordinate y is NaN") != std::string::npos);
  CHECK(cmx::io::test::slurp(path) == before);

  cmx::Mesh sizes = two_tets();
  sizes.points_exact = {{"0", "0", "0"}};
  CHECK(error_of([&] { cmx::write(path, sizes); }).find("5 doubles but 1 exact points") != std::string::npos);
  cmx::Mesh text = two_tets();
  text.points.clear();
  text.points_exact = {
      {"0", "0", "0"}, {"1", "0", "0"}, {"0", "1", "0"}, {"1/3", "one", "1"}, {"0", "0", "-1"}};
  CHECK(error_of([&] {
          cmx::write(path, text);
        }).find("point 3, coordinate y 'one' is not an exact number") != std::string::npos);
  CHECK(cmx::io::test::slurp(path) == before);

  const std::string stl = path_in(dir, "x.stl");
  CHECK(error_of([&] { cmx::write(stl, two_tets()); }).find("cannot write format '.stl'") !=
        std::string::npos);
  CHECK_FALSE(std::filesystem::exists(stl));
  const std::string tmap = path_in(dir, "no_target.tmap");
  CHECK(error_of([&] { cmx::write(tmap, two_tets()); }).find("needs one target point per point") !=
        std::string::npos);
  const std::string nowhere = path_in(dir, "no/such/dir/x.vtk");
  CHECK(error_of([&] { cmx::write(nowhere, two_tets()); }).find(nowhere) != std::string::npos);
}
