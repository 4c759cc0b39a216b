// cmx boundary and cmx generate-mesh, run as programs. The meshes come from `cmx generate-mesh`
// (written as legacy VTK, which this file parses itself to find the boundary vertices), so the
// tests need no data files and no library beyond the program.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "run_cmx.hpp"

using cmx::test::file_text;
using cmx::test::run_cmx;
using cmx::test::write_temp_file;
namespace fs = std::filesystem;

namespace {

// A fresh path in the temporary directory that does not exist yet.
std::string fresh_path(const std::string& suffix) {
  const auto path = write_temp_file("", suffix);
  fs::remove(path);
  return path;
}

// The boundary vertices of a legacy VTK tet mesh as written by cmx: vertices of faces in one tet.
std::set<std::uint32_t> vtk_boundary_vertices(const std::string& path) {
  std::istringstream in(file_text(path));
  std::string word;
  std::size_t points = 0, cells = 0, size = 0;
  while (in >> word && word != "POINTS") {
  }
  in >> points >> word;
  for (std::size_t i = 0; i < 3 * points; ++i) in >> word;
  in >> word >> cells >> size;
  REQUIRE(word == "CELLS");
  std::vector<std::array<std::uint32_t, 3>> faces;
  for (std::size_t c = 0; c < cells; ++c) {
    std::uint32_t n = 0;
    std::array<std::uint32_t, 4> t{};
    in >> n >> t[0] >> t[1] >> t[2] >> t[3];
    REQUIRE(n == 4);
    for (int skip = 0; skip < 4; ++skip) {
      std::array<std::uint32_t, 3> f{};
      for (int k = 0, j = 0; k < 4; ++k)
        if (k != skip) f[std::size_t(j++)] = t[std::size_t(k)];
      std::sort(f.begin(), f.end());
      faces.push_back(f);
    }
  }
  std::sort(faces.begin(), faces.end());
  std::set<std::uint32_t> boundary;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i;
    while (j < faces.size() && faces[j] == faces[i]) ++j;
    if (j - i == 1) boundary.insert(faces[i].begin(), faces[i].end());
    i = j;
  }
  return boundary;
}

// True when `text` is a plain decimal: optional '-', digits, optionally '.' and digits.
bool is_plain_decimal(const std::string& text) {
  std::size_t i = text[0] == '-' ? 1 : 0;
  const std::size_t digits = text.find_first_not_of("0123456789", i);
  if (digits == i) return false;
  if (digits == std::string::npos) return true;
  return text[digits] == '.' && digits + 1 < text.size() && text.find_first_not_of("0123456789", digits + 1) == std::string::npos;
}

// Checks a boundary file: "index x y z" lines, ascending indices covering exactly `boundary`,
// exact decimals. Returns the radii of the points.
std::vector<double> check_boundary_file(const std::string& path, const std::set<std::uint32_t>& boundary) {
  std::istringstream in(file_text(path));
  std::string line;
  std::vector<std::uint32_t> indices;
  std::vector<double> radii;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::uint32_t index = 0;
    std::string x[3], extra;
    REQUIRE(static_cast<bool>(fields >> index >> x[0] >> x[1] >> x[2]));
    CHECK_FALSE(static_cast<bool>(fields >> extra));
    double r2 = 0;
    for (const auto& c : x) {
      CHECK_MESSAGE(is_plain_decimal(c), c);
      char* end = nullptr;
      const double v = std::strtod(c.c_str(), &end);
      CHECK(*end == '\0');
      CHECK(std::isfinite(v));
      r2 += v * v;
    }
    indices.push_back(index);
    radii.push_back(std::sqrt(r2));
  }
  CHECK(std::is_sorted(indices.begin(), indices.end()));
  CHECK(std::set<std::uint32_t>(indices.begin(), indices.end()) == boundary);
  CHECK(indices.size() == boundary.size());
  return radii;
}

std::string generated_mesh(const std::string& shape, const std::string& suffix = ".vtk") {
  const auto path = fresh_path(suffix);
  const auto r = run_cmx({"generate-mesh", "--shape", shape, "--perturb", "3", "-o", path});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  return path;
}

}  // namespace

TEST_CASE("cmx boundary: every shape on generated meshes covers exactly the boundary vertices") {
  for (const std::string mesh_shape : {"grid:3,3,2", "ball:3", "slab:6,4"}) {
    CAPTURE(mesh_shape);
    const auto mesh = generated_mesh(mesh_shape);
    const auto boundary = vtk_boundary_vertices(mesh);
    REQUIRE(boundary.size() >= 4);
    for (const std::string shape : {"tet", "stiff-tet", "sphere", "star", "star:77"}) {
      CAPTURE(shape);
      const auto out = fresh_path(".txt");
      const auto r = run_cmx({"boundary", mesh, "--shape", shape, "-o", out});
      INFO(r.err);
      REQUIRE(r.exit_code == 0);
      CHECK(r.out.empty());
      const auto radii = check_boundary_file(out, boundary);
      for (double radius : radii) {
        if (std::string(shape) == "sphere") CHECK(std::abs(radius - 1) < 1e-15);
        else if (std::string(shape).rfind("star", 0) == 0) CHECK((radius > 1 - 1e-15 && radius < 10));
        else CHECK((radius <= 1 + 1e-15 && radius >= 1.0 / 3 - 1e-15));
      }
    }
  }
}

TEST_CASE("cmx boundary: the same seed gives the same bytes, another seed another file") {
  const auto mesh = generated_mesh("grid:3,2,2", ".ovm");
  const auto a = fresh_path(".txt"), b = fresh_path(".txt"), c = fresh_path(".txt"), d = fresh_path(".txt");
  REQUIRE(run_cmx({"boundary", mesh, "--shape", "star:5", "-o", a}).exit_code == 0);
  REQUIRE(run_cmx({"boundary", mesh, "--shape", "star", "--seed", "5", "-o", b}).exit_code == 0);
  REQUIRE(run_cmx({"boundary", mesh, "--shape", "star:6", "--output", c}).exit_code == 0);
  REQUIRE(run_cmx({"boundary", mesh, "--shape", "tet", "--seed", "5", "-o", d}).exit_code == 0);
  CHECK(file_text(a) == file_text(b));
  CHECK(file_text(a) != file_text(c));
  CHECK(file_text(a) != file_text(d));
  // The same mesh in another format (same exact positions) gives the same boundary.
  const auto vtk = fresh_path(".vtk");
  REQUIRE(run_cmx({"generate-mesh", "--shape", "grid:3,2,2", "--perturb", "3", "-o", vtk}).exit_code == 0);
  const auto e = fresh_path(".txt");
  REQUIRE(run_cmx({"boundary", vtk, "--shape", "star:5", "-o", e}).exit_code == 0);
  CHECK(file_text(a) == file_text(e));
}

TEST_CASE("cmx boundary: bad command lines exit 2 and write nothing") {
  const auto mesh = generated_mesh("grid:2,2,2");
  const auto out = fresh_path(".txt");
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"boundary", mesh, "--shape", "cube", "-o", out},
        {"boundary", mesh, "--shape", "star:x", "-o", out},
        {"boundary", mesh, "-o", out},
        {"boundary", mesh, "--shape", "tet"},
        {"boundary", "--shape", "tet", "-o", out},
        {"boundary", mesh, "--shape", "tet", "-o", out, "--seed", "-3"},
        {"boundary", mesh, "--shape", "star:4", "-o", out, "--seed", "5"},
        {"boundary", mesh, "--shape", "tet", "-o", out, "--spread", "101"},
        {"boundary", mesh, "--shape", "tet", "-o", out, "--spread", "-1"},
        {"boundary", mesh, "--shape", "tet", "-o", out, "--spread", "x"},
        {"boundary", mesh, "--shape", "tet", "-o", out, "--frobnicate"},
        {"boundary", mesh, mesh, "--shape", "tet", "-o", out},
        {"boundary", mesh, "--shape"}}) {
    const auto r = run_cmx(args);
    CAPTURE(args.size());
    CHECK(r.exit_code == 2);
    CHECK_FALSE(r.err.empty());
    CHECK_FALSE(fs::exists(out));
  }
  CHECK(run_cmx({"boundary", "--help"}).exit_code == 0);
}

TEST_CASE("cmx boundary: unreadable input exits 3, a non-ball exits 4, and no file is written") {
  const auto out = fresh_path(".txt");
  auto r = run_cmx({"boundary", "/nonexistent/mesh.vtk", "--shape", "tet", "-o", out});
  CHECK(r.exit_code == 3);
  CHECK_FALSE(fs::exists(out));
  const auto garbage = write_temp_file("# vtk DataFile Version 4.2\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 2 double\n0 0 zero\n", ".vtk");
  r = run_cmx({"boundary", garbage, "--shape", "tet", "-o", out});
  CHECK(r.exit_code == 3);
  CHECK(r.err.find("cmx boundary: " + garbage + ":") == 0);
  CHECK_FALSE(fs::exists(out));
  // Two positive tets sharing only vertex 0: readable, consistently oriented, not a ball.
  const auto pinched = write_temp_file(
      "# vtk DataFile Version 4.2\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 7 double\n"
      "0 0 0\n1 0 0\n0 1 0\n0 0 1\n-1 0 0\n0 -1 0\n0 0 -1\n"
      "CELLS 2 10\n4 0 1 2 3\n4 0 4 6 5\nCELL_TYPES 2\n10\n10\n",
      ".vtk");
  r = run_cmx({"boundary", pinched, "--shape", "sphere", "-o", out});
  CHECK(r.exit_code == 4);
  CHECK(r.err.find("not a ball") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
  // A failure keeps an existing output file as it was.
  std::ofstream(out) << "keep me\n";
  r = run_cmx({"boundary", pinched, "--shape", "sphere", "-o", out});
  CHECK(r.exit_code == 4);
  CHECK(file_text(out) == "keep me\n");
}

TEST_CASE("cmx generate-mesh: every shape and format gives a ball") {
  for (const std::string shape : {"grid:2,3,4", "ball:2", "slab:5,4", "slab:5,4,2", "fingers:2,2,6"})
    for (const std::string suffix : {".vtk", ".ovm", ".vtu", ".mesh"}) {
      CAPTURE(shape);
      CAPTURE(suffix);
      const auto out = fresh_path(suffix);
      const auto r = run_cmx({"generate-mesh", "--shape", shape, "--perturb", "9", "-o", out});
      INFO(r.err);
      REQUIRE(r.exit_code == 0);
      const auto info = run_cmx({"info", out, "--json"});
      CHECK(info.out.find("\"is_ball\": true") != std::string::npos);
      CHECK(info.out.find("\"negative\": 0, \"zero\": 0") != std::string::npos);
    }
  const auto ovm = fresh_path(".ovm");
  REQUIRE(run_cmx({"generate-mesh", "--shape", "grid:2,2,2", "--perturb", "1", "--amplitude", "0.1", "-o", ovm}).exit_code == 0);
  CHECK(file_text(ovm).find("str_exact_position") != std::string::npos);
  // Deterministic; unperturbed meshes have integer coordinates.
  const auto a = fresh_path(".vtk"), b = fresh_path(".vtk"), plain = fresh_path(".vtk");
  REQUIRE(run_cmx({"generate-mesh", "--shape", "ball:3", "--perturb", "4", "-o", a}).exit_code == 0);
  REQUIRE(run_cmx({"generate-mesh", "--shape", "ball:3", "--perturb", "4", "-o", b}).exit_code == 0);
  CHECK(file_text(a) == file_text(b));
  REQUIRE(run_cmx({"generate-mesh", "--shape", "grid:1,1,1", "-o", plain}).exit_code == 0);
  CHECK(file_text(plain).find("POINTS 8 double\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n") != std::string::npos);
}

TEST_CASE("cmx generate-mesh: bad command lines exit 2") {
  const auto out = fresh_path(".vtk");
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"generate-mesh", "--shape", "grid:2,2", "-o", out},
        {"generate-mesh", "--shape", "grid:0,2,2", "-o", out},
        {"generate-mesh", "--shape", "ball:", "-o", out},
        {"generate-mesh", "--shape", "slab:3,3,3", "-o", out},
        {"generate-mesh", "--shape", "torus:3", "-o", out},
        {"generate-mesh", "--shape", "bings-house:5", "-o", out},
        {"generate-mesh", "--shape", "bings-house:2", "-o", out},
        {"generate-mesh", "--shape", "bings-house-box:3", "-o", out},
        {"generate-mesh", "--shape", "bings-house-box:0", "-o", out},
        {"generate-mesh", "--shape", "bings-house-box:66", "-o", out},
        {"generate-mesh", "--shape", "knotted-hole:0", "-o", out},
        {"generate-mesh", "--shape", "knotted-hole:6", "-o", out},
        {"generate-mesh", "--shape", "knotted-hole:2,2", "-o", out},
        {"generate-mesh", "--shape", "fingers:2,1,6", "-o", out},
        {"generate-mesh", "--shape", "fingers:2,2", "-o", out},
        {"generate-mesh", "--shape", "fingers:17,2,6", "-o", out},
        {"generate-mesh", "--shape", "fingers:16,8,400", "-o", out},
        {"generate-mesh", "--shape", "grid:1000,1000,1000", "-o", out},
        {"generate-mesh", "--shape", "ball:2", "-o", fresh_path(".stl")},
        {"generate-mesh", "--shape", "ball:2"},
        {"generate-mesh", "--shape", "ball:2", "--perturb", "x", "-o", out},
        {"generate-mesh", "--shape", "ball:2", "--amplitude", "0.1", "-o", out},
        {"generate-mesh", "--shape", "ball:2", "--perturb", "1", "--amplitude", "-1", "-o", out},
        {"generate-mesh", "ball:2", "-o", out}}) {
    CAPTURE(args.size());
    CHECK(run_cmx(args).exit_code == 2);
    CHECK_FALSE(fs::exists(out));
  }
}

TEST_CASE("cmx boundary --spread: another valid boundary, the same bytes again") {
  const auto mesh = generated_mesh("fingers:1,2,40");
  const auto plain = fresh_path(".txt"), spread = fresh_path(".txt"), again = fresh_path(".txt");
  REQUIRE(run_cmx({"boundary", mesh, "--shape", "sphere", "-o", plain}).exit_code == 0);
  REQUIRE(run_cmx({"boundary", mesh, "--shape", "sphere", "--spread", "30", "-o", spread}).exit_code == 0);
  REQUIRE(run_cmx({"boundary", mesh, "--shape", "sphere", "--spread=30", "-o", again}).exit_code == 0);
  CHECK(file_text(plain) != file_text(spread));
  CHECK(file_text(spread) == file_text(again));
  // The spread file is a valid boundary for the mesh: cmx map accepts it (validation alone would
  // refuse a boundary that is not star-shaped or has a flat triangle; the map itself is checked
  // elsewhere).
  const auto info = run_cmx({"map", mesh, "--boundary", spread, "-o", fresh_path(""), "--quiet"});
  CHECK(info.exit_code == 0);
}

TEST_CASE("cmx boundary --corners farthest: a boundary where drawn corners find none") {
  // Two fingers two cells wide and 80 long: drawn corners fail on every attempt (exit 4, no
  // file); the ends of the longest stretch give a valid boundary, the same bytes again, which
  // cmx map accepts and maps.
  const auto mesh = generated_mesh("fingers:2,2,80");
  const auto drawn = fresh_path(".txt"), far = fresh_path(".txt"), again = fresh_path(".txt");
  const auto r = run_cmx({"boundary", mesh, "--shape", "sphere", "-o", drawn});
  CHECK(r.exit_code == 4);
  CHECK(r.err.find("no valid 'sphere' boundary") != std::string::npos);
  CHECK_FALSE(fs::exists(drawn));
  REQUIRE(run_cmx({"boundary", mesh, "--shape", "sphere", "--corners", "farthest", "-o", far}).exit_code == 0);
  REQUIRE(run_cmx({"boundary", mesh, "--shape", "sphere", "--corners=farthest", "-o", again}).exit_code == 0);
  CHECK(file_text(far) == file_text(again));
  const auto radii = check_boundary_file(far, vtk_boundary_vertices(mesh));
  for (double radius : radii) CHECK(radius == doctest::Approx(1).epsilon(1e-15));
  const auto map = run_cmx({"map", mesh, "--boundary", far, "-o", fresh_path(""), "--quiet"});
  INFO(map.err);
  CHECK(map.exit_code == 0);
  // A bad choice is a usage error naming the option.
  const auto bad = run_cmx({"boundary", mesh, "--shape", "sphere", "--corners", "nearest", "-o", drawn});
  CHECK(bad.exit_code == 2);
  CHECK(bad.err.find("--corners") != std::string::npos);
  CHECK_FALSE(fs::exists(drawn));
}

TEST_CASE("cmx boundary --threads: the same boundary, attempt count and failure message for every count") {
  // Two fingers two cells wide: drawn corners fail 22 attempts before the 23rd gives a stiff tet,
  // so batches of attempts end on either side of the one that is kept; 80 cells long, every one
  // of the 100 attempts fails, and the message quotes the first and the last failure.
  const auto mesh = generated_mesh("fingers:2,2,40");
  std::string first_text, first_note;
  for (const char* threads : {"1", "2", "3", "8"}) {
    CAPTURE(threads);
    const auto out = fresh_path(".txt");
    const auto r = run_cmx({"boundary", mesh, "--shape", "stiff-tet", "--threads", threads, "-o", out});
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.find("23 attempts") != std::string::npos);
    if (first_text.empty()) first_text = file_text(out), first_note = r.err;
    CHECK(file_text(out) == first_text);
    CHECK(r.err.substr(r.err.find(':', r.err.find("wrote"))) ==
          first_note.substr(first_note.find(':', first_note.find("wrote"))));
  }
  const auto long_fingers = generated_mesh("fingers:2,2,80");
  std::string failure;
  for (const char* threads : {"1", "3"}) {
    CAPTURE(threads);
    const auto out = fresh_path(".txt");
    const auto r = run_cmx({"boundary", long_fingers, "--shape", "sphere", "--threads", threads, "-o", out});
    CHECK(r.exit_code == 4);
    CHECK_FALSE(fs::exists(out));
    CHECK(r.err.find("100 attempts") != std::string::npos);
    if (failure.empty()) failure = r.err;
    CHECK(r.err == failure);
  }
  CHECK(
      run_cmx({"boundary", mesh, "--shape", "tet", "--threads", "-1", "-o", fresh_path(".txt")}).exit_code ==
      2);
}
