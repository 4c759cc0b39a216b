// cmx map --init and --threads: the local repair from the command line.
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "map_case.hpp"
#include "run_cmx.hpp"

using namespace cmx::test;

namespace {

// The value of "key" in a JSON report as text up to the next comma or line end (good enough for
// the flat fields these tests read).
std::string field(const std::string& report, const std::string& key) {
  const auto at = report.find("\"" + key + "\": ");
  if (at == std::string::npos) return "(absent)";
  const auto from = at + key.size() + 4;
  return report.substr(from, report.find_first_of(",\n", from) - from);
}

// The mesh's own positions, every vertex ("index x y z", from `cmx convert` to TetGen), and the
// same for its boundary vertices only (those `cmx boundary` wrote): a problem whose initial map
// "every vertex where it is" is already a valid map.
struct Identity {
  std::string init, boundary;
};

Identity identity_files(const Case& c) {
  REQUIRE(run_cmx({"convert", c.mesh, c.dir + "/self.node", "-q"}).exit_code == 0);
  std::string text;
  std::istringstream lines(file_text(c.dir + "/self.node"));
  for (std::string line; std::getline(lines, line);)
    if (line.empty() || line[0] != '#') text += line + '\n';
  std::istringstream node(text);
  std::size_t n = 0, dim = 0, attributes = 0, markers = 0;
  node >> n >> dim >> attributes >> markers;
  std::vector<std::string> rows(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t index = 0;
    std::string x, y, z;
    node >> index >> x >> y >> z;
    rows[i] = x + ' ' + y + ' ' + z;
  }
  std::ostringstream all, boundary;
  for (std::size_t i = 0; i < n; ++i) all << i << ' ' << rows[i] << '\n';
  std::istringstream given(file_text(c.boundary));
  for (std::string line; std::getline(given, line);) {
    std::istringstream fields(line);
    std::size_t index = 0;
    if (fields >> index) boundary << index << ' ' << rows.at(index) << '\n';
  }
  return {write_temp_file(all.str()), write_temp_file(boundary.str())};
}

}  // namespace

TEST_CASE("cmx map --init tutte maps, verifies and reports the stars, the same for any --threads") {
  const Case c = make_case("ball:4", "star:5");
  std::string tmaps[2];
  for (int k = 0; k < 2; ++k) {
    const std::string out = c.dir + "/t" + std::to_string(k), report = out + ".json";
    const auto r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "--init", "tutte", "--threads", k ? "3" : "1", "-o",
                            out, "--report", report, "-q"});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const std::string text = file_text(report);
    CHECK(field(text, "init") == "\"tutte\"");
    CHECK(field(text, "exact_valid") == "true");
    CHECK(field(text, "stars") != "(absent)");
    tmaps[k] = file_text(out + ".tmap");
  }
  CHECK(tmaps[0] == tmaps[1]);
}

TEST_CASE("cmx map --init FILE takes every vertex's position, and a valid one comes back unchanged") {
  const Case c = make_case("grid:3,3,3", "tet");
  const Identity id = identity_files(c);
  const std::string out = c.dir + "/again", report = out + ".json";
  const auto r = run_cmx({"map", c.mesh, "--boundary", id.boundary, "--init", id.init, "-o", out, "--report", report, "-q"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const std::string text = file_text(report);
  CHECK(field(text, "stars") == "0");
  CHECK(field(text, "growth_ratio") == "1");
  // Every vertex's target is its source: the map is the identity.
  std::istringstream in(file_text(out + ".tmap"));
  std::string word;
  std::size_t n = 0;
  in >> word >> word >> word >> n;
  std::size_t same = 0;
  for (std::size_t i = 0; i < n; ++i) {
    std::string sx, sy, sz, tx, ty, tz;
    in >> sx >> sy >> sz >> tx >> ty >> tz;
    same += sx == tx && sy == ty && sz == tz;
  }
  CHECK(n == 64);
  CHECK(same == n);
}

TEST_CASE("cmx map --init: bad values, a short file and codomain without --codomain are refused") {
  const Case c = make_case("grid:2,2,2", "tet");
  auto r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "--init", "given"});
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("--init") != std::string::npos);
  r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "--init", "codomain"});
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("--codomain") != std::string::npos);
  r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "--init", c.dir + "/missing.txt"});
  CHECK(r.exit_code == 3);
  CHECK(r.err.find("missing.txt") != std::string::npos);
  const std::string short_file = write_temp_file("0 0 0 0\n");
  r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "--init", short_file});
  CHECK(r.exit_code == 4);
  CHECK(r.err.find("one per vertex") != std::string::npos);
  for (const char* bad : {"-1", "x", "2000"}) {
    r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "--threads", bad});
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--threads") != std::string::npos);
  }
  // An output over the initial map's file is refused like any output over an input.
  r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "--init", short_file, "--report", short_file});
  CHECK(r.exit_code == 2);
}

TEST_CASE("cmx map: auto runs the global method when the stars' stitched doubles are not valid") {
  // One of the project's generated dataset cases (bench/dataset/generate.sh: ball_7_s2_stiff-tet):
  // its stars' doubles leave 2 tets inverted, the global method's are valid.
  Case c;
  c.dir = fresh_directory();
  c.mesh = c.dir + "/domain.vtk";
  c.boundary = c.dir + "/boundary.txt";
  REQUIRE(run_cmx({"generate-mesh", "--shape", "ball:7", "--perturb", "2", "-o", c.mesh, "-q"}).exit_code == 0);
  REQUIRE(run_cmx({"boundary", c.mesh, "--shape", "stiff-tet", "-o", c.boundary, "-q"}).exit_code == 0);
  std::string report[2];
  for (int k = 0; k < 2; ++k) {
    const std::string out = c.dir + (k ? "/auto" : "/tutte");
    const auto r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "--init", k ? "auto" : "tutte", "-o", out,
                            "--report", out + ".json", "-q"});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    report[k] = file_text(out + ".json");
    CHECK(field(report[k], "exact_valid") == "true");
  }
  // The explicit choice keeps the local repair's doubles; auto leaves them for the global method's.
  const auto local = [](const std::string& text) { return text.substr(text.find("\"local\": {")); };
  CHECK(field(local(report[0]), "init") == "\"tutte\"");
  CHECK(field(report[0], "double_valid") == "false");
  CHECK(field(local(report[1]), "init") == "\"shrink\"");
  CHECK(field(report[1], "double_valid") == "true");
  CHECK(field(report[1], "fallback").find("stitched doubles leave 2 tets inverted or flat") != std::string::npos);
}
