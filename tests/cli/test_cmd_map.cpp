// cmx map, run as a program: outputs, report, exit codes, no partial output on failure, and the
// independent checker of ../shared/tools (written apart from the project) when it is present.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "map_case.hpp"
#include "run_cmx.hpp"
#include "skip.hpp"

using cmx::test::Case;
using cmx::test::file_text;
using cmx::test::fresh_directory;
using cmx::test::make_case;
using cmx::test::run_cmx;
using cmx::test::run_program;
using cmx::test::write_temp_file;
namespace fs = std::filesystem;

namespace {

// Two positive tets sharing only vertex 0: readable, not a ball.
std::string bowtie_mesh() {
  return write_temp_file(
      "# vtk DataFile Version 4.2\nbowtie\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 7 double\n"
      "0 0 0 1 0 0 0 1 0 0 0 1 -1 0 0 0 -1 0 0 0 -1\nCELLS 2 10\n4 0 1 2 3\n4 0 5 4 6\nCELL_TYPES 2\n10 10\n",
      ".vtk");
}

bool have_checker() { return cmx::test::have_shared("tools/verify_tmap.py"); }
std::string checker(const char* name) { return (cmx::test::shared_dir() / "tools" / name).string(); }

// The independent checker's verdict on an exact map (true when it says valid).
bool independent_check(const Case& c, const std::string& tmap) {
  const auto r = run_program("/usr/bin/env", {"python3", checker("verify_tmap.py"), c.mesh,
                                              c.boundary, tmap});
  INFO(r.out << r.err);
  return r.exit_code == 0 && r.out.find("\"valid\": true") != std::string::npos;
}

}  // namespace

TEST_CASE("cmx map writes the exact map and the display formats, and reports a verified success") {
  const Case c = make_case("ball:2", "star:4");
  const std::string out = c.dir + "/out";
  const auto r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "-o", out + ".vtu", "--format", "ovm,vtk,mesh",
                          "--report", c.dir + "/report.json", "--check"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("map: success, verified exactly") != std::string::npos);
  for (const char* ext : {".tmap", ".vtu", ".ovm", ".vtk", ".mesh"}) {
    CAPTURE(ext);
    CHECK(fs::file_size(out + ext) > 0);
  }
  const std::string report = file_text(c.dir + "/report.json");
  CHECK(report.find("\"status\": \"success\"") != std::string::npos);
  CHECK(report.find("\"exact_valid\": true") != std::string::npos);
  CHECK(report.find("\"growth_ratio\"") != std::string::npos);
  // The exact map reads back (every tet checked positive in source and target by the reader).
  CHECK(run_cmx({"info", out + ".ovm"}).exit_code == 0);
  if (have_checker()) CHECK(independent_check(c, out + ".tmap"));
}

TEST_CASE("cmx map --snap: every policy runs, and the written doubles are what the report says") {
  const Case c = make_case("ball:2", "star:4");
  for (const char* policy : {"none", "nearest", "chebyshev-pass", "repair"}) {
    CAPTURE(policy);
    const std::string out = c.dir + "/snap_" + policy;
    const auto r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "-o", out, "--format", "vtk", "--snap", policy,
                            "--report", out + ".json", "--quiet"});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const std::string report = file_text(out + ".json");
    CHECK(report.find(std::string("\"snap\": \"") + policy + "\"") != std::string::npos);
    const bool none = std::string(policy) == "none";
    CHECK(report.find(none ? "\"double_checked\": false" : "\"double_checked\": true") != std::string::npos);
    const bool valid = report.find("\"double_valid\": true") != std::string::npos;
    if (std::string(policy) == "repair") CHECK(valid);
    // The doubles in the VTK file, orientations counted by the independent checker.
    if (!have_checker()) continue;
    const auto b = run_program("/usr/bin/env", {"python3", checker("balltopo.py"),
                                                out + ".vtk", "--json"});
    INFO(b.out);
    REQUIRE(b.exit_code == 0);
    const bool all_positive = b.out.find("\"neg\": 0, \"zero\": 0") != std::string::npos;
    if (!none) CHECK(all_positive == valid);
  }
  CHECK(run_cmx({"map", c.mesh, "--shape", "tet", "--snap", "round"}).exit_code == 2);
  CHECK(run_cmx({"map", c.mesh, "--shape", "tet", "--smooth", "-1"}).exit_code == 2);
  CHECK(run_cmx({"map", c.mesh, "--shape", "tet", "--smooth", "ten"}).exit_code == 2);
}

TEST_CASE("cmx map --subclusters: sizes 0 to 4 run and are reported, anything else exits 2") {
  const Case c = make_case("ball:2", "star:4");
  for (const char* size : {"0", "2", "4"}) {
    CAPTURE(size);
    const std::string out = c.dir + "/sub_" + size;
    const auto r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "-o", out, "--subclusters", size, "--report",
                            out + ".json", "--quiet"});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const std::string report = file_text(out + ".json");
    CHECK(report.find(std::string("\"subclusters\": ") + size) != std::string::npos);
    CHECK(report.find("\"subcluster_candidates\": ") != std::string::npos);
    CHECK(report.find("\"subcluster_search\": ") != std::string::npos);
  }
  for (const char* bad : {"5", "-1", "two", "22"}) {
    CAPTURE(bad);
    const auto r = run_cmx({"map", c.mesh, "--shape", "tet", "--subclusters", bad});
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--subclusters") != std::string::npos);
  }
}

TEST_CASE("cmx map --shelled: the three modes run, are reported with the fallback's counts, and a bad one exits 2") {
  const Case c = make_case("ball:2", "star:4");
  for (const char* mode : {"when-stuck", "after-pushes", "first"}) {
    CAPTURE(mode);
    const std::string out = c.dir + "/shelled_" + std::string(mode);
    const auto r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "-o", out, "--shelled", mode, "--init", "shrink",
                            "--report", out + ".json", "--quiet"});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const std::string report = file_text(out + ".json");
    CHECK(report.find(std::string("\"shelled\": \"") + mode + "\"") != std::string::npos);
    CHECK(report.find("\"base_edge_splits\": ") != std::string::npos);
  }
  for (const char* bad : {"always", "", "First"}) {
    CAPTURE(bad);
    const auto r = run_cmx({"map", c.mesh, "--shape", "tet", "--shelled", bad});
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--shelled") != std::string::npos);
  }
}

TEST_CASE(
    "cmx map --replay-shelling: full replays every step and reports it, until-greedy hands over, a bad mode "
    "exits 2") {
  const Case c = make_case("grid:3,3,3", "sphere");
  for (const char* mode : {"full", "until-greedy"}) {
    CAPTURE(mode);
    const std::string out = c.dir + "/replay_" + std::string(mode);
    const auto r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "-o", out, "--replay-shelling", mode,
                            "--init", "shrink", "--check", "--report", out + ".json", "--quiet"});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const std::string report = file_text(out + ".json");
    CHECK(report.find(std::string("\"replay_shelling\": \"") + mode + "\"") != std::string::npos);
    const bool full = std::string(mode) == "full";
    CHECK(report.find(std::string("\"handed_over\": ") + (full ? "false" : "true")) != std::string::npos);
    CHECK((report.find("\"expansions\": 0,") == std::string::npos) == full);
  }
  for (const char* bad : {"always", "", "Full"}) {
    CAPTURE(bad);
    const auto r = run_cmx({"map", c.mesh, "--shape", "tet", "--replay-shelling", bad});
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--replay-shelling") != std::string::npos);
  }
}

TEST_CASE("cmx map --trace writes a row per expansion, and cmx plot draws it") {
  const Case c = make_case("grid:3,3,3", "stiff-tet");
  const std::string trace = c.dir + "/t.csv", svg = c.dir + "/t.svg";
  const auto r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "-o", c.dir + "/out", "--trace", trace, "--report",
                          c.dir + "/r.json", "--init", "shrink", "--quiet"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  std::istringstream in(file_text(trace));
  std::string line;
  REQUIRE(std::getline(in, line));
  CHECK(line == "step,kind,vertex,cone_rows,lp,bits,max_bits,mean_bits,added_vertices,degenerate_left,cluster_left,seconds,star");
  std::size_t rows = 0;
  std::string last;
  while (std::getline(in, line)) {
    ++rows;
    CHECK(std::count(line.begin(), line.end(), ',') == 12);
    last = line;
  }
  // One row per expansion: the report's simple + star-shapified + automatic expansions.
  const std::string report = file_text(c.dir + "/r.json");
  auto number = [&](const std::string& key) {
    const auto at = report.find("\"" + key + "\": ");
    REQUIRE(at != std::string::npos);
    return std::stoul(report.substr(at + key.size() + 4));
  };
  CHECK(rows == number("simple") + number("star_shapified") + number("automatic"));
  CHECK(rows >= 8);  // the 3x3x3 grid has 8 interior vertices
  // The last row: no cluster vertex and no degenerate tet left.
  CHECK(last.substr(last.size() - 1) != ",");
  const std::vector<std::string> cells = [&] {
    std::vector<std::string> out;
    std::stringstream ss(last);
    for (std::string cell; std::getline(ss, cell, ',');) out.push_back(cell);
    return out;
  }();
  REQUIRE(cells.size() == 13);
  CHECK(cells[9] == "0");
  CHECK(cells[10] == "0");
  CHECK(cells[12] == "0");  // the global method: no star

  const auto p = run_cmx({"plot", trace, "-o", svg});
  INFO(p.err);
  REQUIRE(p.exit_code == 0);
  const std::string text = file_text(svg);
  CHECK(text.find("<svg") != std::string::npos);
  CHECK(text.find("<polyline") != std::string::npos);
  CHECK(text.find("degenerate tets left") != std::string::npos);

  // A malformed trace: exit 3, the line named, no output.
  const std::string bad = write_temp_file(
      "step,kind,vertex,cone_rows,lp,bits,max_bits,mean_bits,added_vertices,degenerate_left,cluster_left,seconds\n"
      "1,simple,3,4,certified,54,60,40,0,10,5,0.1\n2,simple,4,4,certified,nan,60,40,0,9,4,0.2\n");
  const auto b = run_cmx({"plot", bad, "-o", c.dir + "/bad.svg"});
  CHECK(b.exit_code == 3);
  CHECK(b.err.find(":3") != std::string::npos);
  CHECK_FALSE(fs::exists(c.dir + "/bad.svg"));
  CHECK(run_cmx({"plot", trace}).exit_code == 2);
}

TEST_CASE("cmx map --shape generates the boundary itself, and reruns give identical bytes") {
  const Case c = make_case("grid:3,3,2", "tet");
  const std::string a = c.dir + "/a", b = c.dir + "/b";
  REQUIRE(run_cmx({"map", c.mesh, "--shape", "stiff-tet", "-o", a, "--quiet"}).exit_code == 0);
  REQUIRE(run_cmx({"map", c.mesh, "--shape", "stiff-tet", "-o", b, "--quiet"}).exit_code == 0);
  CHECK(file_text(a + ".tmap") == file_text(b + ".tmap"));
  CHECK(file_text(a + ".tmap").rfind("tmap 1\n", 0) == 0);
}

TEST_CASE("cmx map takes the boundary from a codomain mesh with the same connectivity") {
  const Case c = make_case("grid:2,2,2", "tet");
  // The domain itself as codomain: its boundary positions are the prescribed ones.
  const auto r = run_cmx({"map", c.mesh, "--codomain", c.mesh, "-o", c.dir + "/out", "--quiet"});
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(fs::exists(c.dir + "/out.tmap"));
}

TEST_CASE("cmx map: a boundary that is not star-shaped exits 5, writes nothing and names a triangle") {
  const Case c = make_case("grid:2,2,2", "tet");
  // Grid vertex 22 is the centre of the top face of the 3x3x3 vertex grid: pull it far down.
  std::istringstream in(file_text(c.boundary));
  std::string text, line;
  while (std::getline(in, line)) text += (line.rfind("22 ", 0) == 0 ? std::string("22 0 0 -50") : line) + "\n";
  const std::string bad = write_temp_file(text);
  const std::string out = c.dir + "/never";
  const auto r = run_cmx({"map", c.mesh, "--boundary", bad, "-o", out, "--report", c.dir + "/r.json"});
  CHECK(r.exit_code == 5);
  CHECK(r.err.find("not star-shaped") != std::string::npos);
  CHECK(r.err.find("boundary triangle") != std::string::npos);
  CHECK_FALSE(fs::exists(out + ".tmap"));
  CHECK(file_text(c.dir + "/r.json").find("\"status\": \"not_star_shaped\"") != std::string::npos);
}

TEST_CASE("cmx map: wrong boundary vertex set, non-ball mesh, bad numbers and bad options") {
  const Case c = make_case("grid:2,2,2", "tet");
  const std::string out = c.dir + "/never";
  // A boundary file without its last line: a vertex lacks its position (exit 4).
  std::string text = file_text(c.boundary);
  text.erase(text.rfind('\n', text.size() - 2) + 1);
  auto r = run_cmx({"map", c.mesh, "--boundary", write_temp_file(text), "-o", out});
  CHECK(r.exit_code == 4);
  CHECK(r.err.find("boundary vertex") != std::string::npos);
  // NaN in the boundary file: a malformed file (exit 3) naming the line.
  r = run_cmx({"map", c.mesh, "--boundary", write_temp_file("0 nan 0 0\n"), "-o", out});
  CHECK(r.exit_code == 3);
  CHECK(r.err.find(":1:") != std::string::npos);
  // Two tets sharing only a vertex: not a ball (exit 4).
  const std::string bowtie = bowtie_mesh();
  r = run_cmx({"map", bowtie, "--shape", "tet", "-o", out});
  CHECK(r.exit_code == 4);
  CHECK_FALSE(fs::exists(out + ".tmap"));
  // Usage errors exit 2.
  CHECK(run_cmx({"map", c.mesh}).exit_code == 2);
  CHECK(run_cmx({"map", c.mesh, "--boundary", c.boundary, "--shape", "tet"}).exit_code == 2);
  CHECK(run_cmx({"map", c.mesh, "--shape", "tet", "--precision", "fast"}).exit_code == 2);
  CHECK(run_cmx({"map", c.mesh, "--shape", "tet", "--filter", "naive"}).exit_code == 2);
  CHECK(run_cmx({"map", c.mesh, "--shape", "tet", "--format", "stl"}).exit_code == 2);
  CHECK(run_cmx({"map", c.mesh, "--shape", "tet", "--init", "shrink", "--order", "priority,defer:3"})
            .exit_code == 2);
  // A deferred id range needs the input's numbering, which the local repair's stars do not keep.
  r = run_cmx({"map", c.mesh, "--shape", "tet", "--order", "priority,defer:0-5", "-o", out});
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("--init shrink") != std::string::npos);
  r = run_cmx(
      {"map", c.mesh, "--shape", "tet", "--init", "shrink", "--order", "priority,defer:0-5", "-o", out});
  CHECK(r.exit_code == 0);
  CHECK(fs::exists(out + ".tmap"));
  CHECK(run_cmx({"map", "--help"}).exit_code == 0);
}

TEST_CASE("cmx map: the time limit exits 6 and leaves no output, an existing output untouched") {
  const Case c = make_case("ball:3", "star:1");
  const std::string out = c.dir + "/kept";
  std::ofstream(out + ".tmap") << "old content\n";
  const auto r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "-o", out, "--time-limit", "1e-9"});
  CHECK(r.exit_code == 6);
  CHECK(file_text(out + ".tmap") == "old content\n");
}

TEST_CASE("cmx map --no-merge keeps the vertices merges would remove, and both maps verify") {
  const Case c = make_case("slab:8,6", "star:2");  // one layer: every input vertex on the boundary
  const std::string merged = c.dir + "/merged", plain = c.dir + "/plain";
  auto r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "-o", merged, "--report", merged + ".json"});
  REQUIRE(r.exit_code == 0);
  r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "-o", plain, "--report", plain + ".json", "--no-merge"});
  REQUIRE(r.exit_code == 0);
  const std::string with = file_text(merged + ".json"), without = file_text(plain + ".json");
  CHECK(with.find("\"merge\": true") != std::string::npos);
  CHECK(without.find("\"merge\": false") != std::string::npos);
  CHECK(without.find("\"merged\": 0,") != std::string::npos);
  CHECK(with.find("\"merged\": 0,") == std::string::npos);
  if (have_checker()) {
    CHECK(independent_check(c, merged + ".tmap"));
    CHECK(independent_check(c, plain + ".tmap"));
  }
}

TEST_CASE("cmx map --no-flip-collapse makes no flip collapse, and both maps verify") {
  const Case c = make_case("slab:12,9", "star:2");  // one layer: every input vertex on the boundary
  const std::string flipped = c.dir + "/flipped", plain = c.dir + "/plain";
  auto r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "-o", flipped, "--report", flipped + ".json"});
  REQUIRE(r.exit_code == 0);
  r = run_cmx(
      {"map", c.mesh, "--boundary", c.boundary, "-o", plain, "--report", plain + ".json", "--no-flip-collapse"});
  REQUIRE(r.exit_code == 0);
  const std::string with = file_text(flipped + ".json"), without = file_text(plain + ".json");
  CHECK(with.find("\"flip_collapse\": true") != std::string::npos);
  CHECK(without.find("\"flip_collapse\": false") != std::string::npos);
  CHECK(without.find("\"flip_collapses\": 0,") != std::string::npos);
  CHECK(with.find("\"flip_collapses\": 0,") == std::string::npos);
  CHECK(without.find("\"merge\": true") != std::string::npos);  // the merges themselves stay on
  if (have_checker()) {
    CHECK(independent_check(c, flipped + ".tmap"));
    CHECK(independent_check(c, plain + ".tmap"));
  }
}

TEST_CASE("cmx map: a NOBUENOSS cluster mesh exits 7 (stuck), says so in the report and writes no map") {
  // Bing's house: the interior vertices span a 2-complex in which every edge lies in two or more
  // triangles, so no cluster vertex satisfies Eq. (1) and nothing can be expanded.
  const Case c = make_case("bings-house", "tet");
  const std::string out = c.dir + "/stuck";
  const std::string report = c.dir + "/stuck.json";
  const auto r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "-o", out, "--report", report});
  CHECK(r.exit_code == 7);
  CHECK(r.err.find("NOBUENOSS") != std::string::npos);
  CHECK_FALSE(fs::exists(out + ".tmap"));
  const std::string json = file_text(report);
  CHECK(json.find("\"status\": \"stuck\"") != std::string::npos);
  CHECK(json.find("none satisfies Eq. (1)") != std::string::npos);
  // The fallback's shelling search ran on the input and found none (greedy shelling of this ball
  // gets stuck), and the message says that the fallback needs one.
  CHECK(json.find("\"nobuenoss\": true") != std::string::npos);
  CHECK(json.find("\"input_shelling\"") != std::string::npos);
  CHECK(json.find("\"found\": false") != std::string::npos);
  CHECK(json.find("\"attempts\": 8") != std::string::npos);
  CHECK(json.find("\"shelling_search\": 0,") == std::string::npos);  // timed, and it took a while
  // The report names the mesh searched: the input with every chord split (none in this house).
  CHECK(json.find("\"split_chords\": 0") != std::string::npos);
  CHECK(json.find("\"replay_completed\": false") != std::string::npos);
  CHECK(r.err.find("no shelling of the input found") != std::string::npos);
}

TEST_CASE("cmx map --arith: double maps and verifies, too few bits exits 8 saying where, bad names exit 2") {
  const Case c = make_case("grid:3,3,3", "sphere");
  const std::string out = c.dir + "/dbl";
  auto r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "-o", out, "--arith", "double", "--report", out + ".json"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("coordinates in double") != std::string::npos);
  CHECK(file_text(out + ".json").find("\"arith\": \"double\"") != std::string::npos);
  CHECK(file_text(out + ".json").find("\"snap\": \"nearest\"") != std::string::npos);
  if (have_checker()) CHECK(independent_check(c, out + ".tmap"));

  // An unperturbed integer grid survives 8-bit rounding; the sphere's expansions do not.
  const std::string grid = c.dir + "/grid.vtk", sphere = c.dir + "/sphere.txt";
  REQUIRE(run_cmx({"generate-mesh", "--shape", "grid:4,4,4", "-o", grid}).exit_code == 0);
  REQUIRE(run_cmx({"boundary", grid, "--shape", "sphere", "-o", sphere}).exit_code == 0);
  const std::string lost = c.dir + "/lost";
  r = run_cmx({"map", grid, "--boundary", sphere, "-o", lost, "--arith", "mpfr:8", "--report", lost + ".json"});
  CHECK(r.exit_code == 8);
  CHECK(r.err.find("precision_lost: validity lost in") != std::string::npos);
  CHECK(r.err.find("tet (") != std::string::npos);
  CHECK_FALSE(fs::exists(lost + ".tmap"));
  const std::string report = file_text(lost + ".json");
  CHECK(report.find("\"status\": \"precision_lost\"") != std::string::npos);
  CHECK(report.find("\"precision_loss\"") != std::string::npos);
  CHECK(report.find("\"orientation\"") != std::string::npos);
  CHECK(report.find("\"exact_valid\": false") != std::string::npos);

  for (const char* bad : {"float", "mpfr:1", "mpfr:"}) {
    CAPTURE(bad);
    r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "--arith", bad});
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("rational, double or mpfr:BITS") != std::string::npos);
  }
}

TEST_CASE("cmx map: an output that cannot be written exits 9 before computing, naming the path") {
  const Case c = make_case("grid:3,3,3", "tet");
  fs::create_directories(c.dir + "/sub.tmap");  // an output path that is a directory
  for (const std::vector<std::string>& where :
       {std::vector<std::string>{"-o", c.dir + "/missing/out"}, std::vector<std::string>{"--report", c.dir + "/missing/r.json"},
        std::vector<std::string>{"--trace", c.dir + "/missing/t.csv"}, std::vector<std::string>{"-o", c.dir + "/sub.tmap"}}) {
    CAPTURE(where[1]);
    std::vector<std::string> args = {"map", c.mesh, "--boundary", c.boundary};
    args.insert(args.end(), where.begin(), where.end());
    const auto r = run_cmx(args);
    CHECK(r.exit_code == 9);
    CHECK(r.err.find("cannot write") != std::string::npos);
    CHECK(r.out.find("map: success") == std::string::npos);  // nothing was computed
  }
}

TEST_CASE("cmx map --time-limit takes huge limits and inf (no limit), and rejects the rest naming the option") {
  const Case c = make_case("grid:2,2,2", "tet");
  // The report of a run that stops before the clock matters shows the limit as a number.
  const std::string bowtie = bowtie_mesh();
  for (const auto& [given, shown] : std::vector<std::pair<std::string, std::string>>{
           {"1e10", "10000000000"}, {"1e300", "1.0000000000000001e+300"}, {"inf", "0"}, {"1e999", "0"}, {"2.5", "2.5"}}) {
    CAPTURE(given);
    const std::string report = c.dir + "/tl_" + given + ".json";
    const auto r = run_cmx({"map", bowtie, "--shape", "tet", "--time-limit", given, "--report", report});
    CHECK(r.exit_code == 4);
    CHECK(file_text(report).find("\"time_limit\": " + shown + "\n") != std::string::npos);
  }
  // inf is no limit, and limits beyond the clock's range saturate to none: the runs complete.
  const auto done = run_cmx({"map", c.mesh, "--boundary", c.boundary, "--time-limit=inf", "--report", c.dir + "/inf.json", "-q"});
  CHECK(done.exit_code == 0);
  CHECK(file_text(c.dir + "/inf.json").find("\"time_limit\": 0\n") != std::string::npos);
  for (const char* huge : {"1e10", "1e300"}) {
    CAPTURE(huge);
    const auto r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "--time-limit", huge, "-q"});
    CHECK(r.exit_code == 0);
  }
  for (const char* bad : {"0", "-1", "-inf", "nan", "NaN", "abc", "5s", "", " 5", "0x"}) {
    CAPTURE(bad);
    const auto r = run_cmx({"map", c.mesh, "--boundary", c.boundary, "--time-limit", bad});
    CHECK(r.exit_code == 2);
    CHECK(r.err.rfind("cmx map: --time-limit: ", 0) == 0);
  }
}

TEST_CASE("cmx map names the culprit: the non-ball domain, the boundary file and its missing vertices") {
  const Case c = make_case("grid:2,2,2", "tet");
  const std::string pinched = bowtie_mesh();
  for (const char* shape : {"tet", "sphere"}) {
    const auto r = run_cmx({"map", pinched, "--shape", shape});
    CHECK(r.exit_code == 4);
    CHECK(r.err.find("cmx map: " + pinched + " is not a ball: ") == 0);
  }
  auto r = run_cmx({"map", c.mesh, "--codomain", pinched});
  CHECK(r.exit_code == 4);  // two inputs that do not fit together
  CHECK(r.err.find(pinched) != std::string::npos);
  // Drop the first three lines of the boundary file: three boundary vertices lack positions.
  std::string text = file_text(c.boundary);
  const std::string first = text.substr(0, text.find(' '));
  for (int i = 0; i < 3; ++i) text.erase(0, text.find('\n') + 1);
  const std::string partial = write_temp_file(text);
  r = run_cmx({"map", c.mesh, "--boundary", partial, "--report", c.dir + "/partial.json"});
  CHECK(r.exit_code == 4);
  CHECK(r.err.find("cmx map: " + partial + ": 3 boundary vertices have no prescribed position; first: vertex " + first) == 0);
  CHECK(file_text(c.dir + "/partial.json").find("\"status\": \"boundary_mismatch\"") != std::string::npos);
}

TEST_CASE("cmx map: a domain with inverted or flat tets is not a valid problem (exit 4), a syntax error is malformed (3)") {
  const auto two_tets = [](const std::string& fifth) {
    return write_temp_file("# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 5 double\n"
                           "0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + fifth + "\nCELLS 2 10\n4 0 1 2 3\n4 1 2 3 4\nCELL_TYPES 2\n10\n10\n",
                           ".vtk");
  };
  const std::string inverted = two_tets("0.1 0.1 0.1"), flat = two_tets("0.5 0.5 0");
  for (const auto& [mesh, what] : {std::pair{inverted, "orientation"}, std::pair{flat, "zero volume"}}) {
    const auto r = run_cmx({"map", mesh, "--shape", "tet", "--report", mesh + ".json"});
    CHECK(r.exit_code == 4);
    CHECK(r.err.find("cmx map: " + mesh + ":") == 0);
    CHECK(r.err.find(what) != std::string::npos);
    CHECK(file_text(mesh + ".json").find("\"status\": \"source_not_positive\"") != std::string::npos);
    CHECK(run_cmx({"boundary", mesh, "--shape", "tet", "-o", mesh + ".txt"}).exit_code == 4);
  }
  const std::string syntax = two_tets("0.1 zero 0.1");
  CHECK(run_cmx({"map", syntax, "--shape", "tet"}).exit_code == 3);
  const std::string repeated = write_temp_file(
      "# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
      "CELLS 1 5\n4 0 1 2 2\nCELL_TYPES 1\n10\n",
      ".vtk");
  CHECK(run_cmx({"map", repeated, "--shape", "tet"}).exit_code == 3);  // a tet repeating a vertex: malformed
}

TEST_CASE("cmx map shows a progress line naming the phase only on a terminal and not with --quiet") {
  const Case c = make_case("grid:3,3,3", "tet");
  const auto r = run_program(CMX_EXE, {"map", c.mesh, "--boundary", c.boundary}, "", true);
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(r.err.find("\r  expansion: expanded ") != std::string::npos);
  CHECK(r.err.find("\x1b[K") != std::string::npos);
  const auto q = run_program(CMX_EXE, {"map", c.mesh, "--boundary", c.boundary, "--quiet"}, "", true);
  CHECK(q.exit_code == 0);
  CHECK(q.err.empty());
  const auto piped = run_cmx({"map", c.mesh, "--boundary", c.boundary});
  CHECK(piped.err.find("expansion:") == std::string::npos);
}

TEST_CASE("cmx map --shape S --corners farthest generates the boundary cmx boundary does, and --corners needs --shape") {
  // Two fingers two cells wide and 80 long: drawn corners find no sphere boundary (exit 4), the
  // ends of the longest stretch do, and the map is the one of the same boundary given as a file.
  const std::string dir = fresh_directory();
  const std::string mesh = dir + "/fingers.vtk", boundary = dir + "/far.txt";
  REQUIRE(run_cmx({"generate-mesh", "--shape", "fingers:2,2,80", "-o", mesh, "-q"}).exit_code == 0);
  const auto drawn = run_cmx({"map", mesh, "--shape", "sphere", "-o", dir + "/drawn", "-q"});
  CHECK(drawn.exit_code == 4);
  CHECK(drawn.err.find("no valid 'sphere' boundary") != std::string::npos);
  CHECK_FALSE(fs::exists(dir + "/drawn.tmap"));
  const auto far = run_cmx({"map", mesh, "--shape", "sphere", "--corners", "farthest", "-o", dir + "/far", "-q"});
  INFO(far.err);
  REQUIRE(far.exit_code == 0);
  REQUIRE(run_cmx({"boundary", mesh, "--shape", "sphere", "--corners", "farthest", "-o", boundary, "-q"}).exit_code == 0);
  REQUIRE(run_cmx({"map", mesh, "--boundary", boundary, "-o", dir + "/file", "-q"}).exit_code == 0);
  CHECK(file_text(dir + "/far.tmap") == file_text(dir + "/file.tmap"));
  // Without a generated shape the option has nothing to choose: a usage error naming it.
  const auto lone = run_cmx({"map", mesh, "--boundary", boundary, "--corners", "farthest", "-o", dir + "/lone"});
  CHECK(lone.exit_code == 2);
  CHECK(lone.err.find("--corners") != std::string::npos);
  CHECK_FALSE(fs::exists(dir + "/lone.tmap"));
  CHECK(run_cmx({"map", mesh, "--shape", "sphere", "--corners", "nearest", "-o", dir + "/bad"}).exit_code == 2);
  // Nor does a seed: ignoring it silently would let a user believe it chose something.
  const auto seeded = run_cmx({"map", mesh, "--boundary", boundary, "--seed", "5", "-o", dir + "/seeded"});
  CHECK(seeded.exit_code == 2);
  CHECK(seeded.err.find("--seed") != std::string::npos);
  CHECK(seeded.err.find("--shape") != std::string::npos);
  CHECK_FALSE(fs::exists(dir + "/seeded.tmap"));
}

TEST_CASE("cmx map --combinatorial on Furch's knotted hole ends as a reported NOBUENOSS, not a bare stuck") {
  // Mapped from its tets alone onto a tet with farthest corners, greedy expansion reaches a state
  // where every remaining candidate's refinement failed and no cluster vertex is left that
  // satisfies Eq. (1): the run says NOBUENOSS (exit 7, "nobuenoss": true in the report) and what
  // the fallback's shelling search found, instead of a failure with no reason behind it.
  const std::string dir = fresh_directory();
  const std::string mesh = dir + "/knotted.ovm", report = dir + "/r.json";
  REQUIRE(run_cmx({"generate-mesh", "--shape", "knotted-hole", "-o", mesh, "-q"}).exit_code == 0);
  const auto r = run_cmx({"map", mesh, "--combinatorial", "--shape", "tet", "--corners", "farthest", "-o",
                          dir + "/out", "--report", report, "--threads", "1"});
  INFO(r.err);
  CHECK(r.exit_code == 7);
  CHECK(r.err.find("NOBUENOSS") != std::string::npos);
  CHECK(r.err.find("no shelling of the input found") != std::string::npos);
  CHECK_FALSE(fs::exists(dir + "/out.tmap"));
  const std::string json = file_text(report);
  CHECK(json.find("\"nobuenoss\": true") != std::string::npos);
  CHECK(json.find("\"combinatorial\": true") != std::string::npos);
}

TEST_CASE("cmx map --shelled after-pushes on Furch's knotted hole: the fallback expands where bends and pushes failed") {
  // The knotted hole's bases where bends and pushes fail go to the shelling star-shapification;
  // each of its edits and each expansion is checked exactly around the vertex it touched (an
  // internal error, exit 10, otherwise). The cone always opened once one fan of the witness was
  // left; what it cannot change is the topology: the run still ends on the NOBUENOSS ahead.
  const std::string dir = fresh_directory();
  const std::string mesh = dir + "/knotted.ovm", report = dir + "/r.json";
  REQUIRE(run_cmx({"generate-mesh", "--shape", "knotted-hole", "-o", mesh, "-q"}).exit_code == 0);
  const auto r = run_cmx({"map", mesh, "--shape", "stiff-tet", "--corners", "farthest", "--shelled", "after-pushes",
                          "-o", dir + "/out", "--report", report, "--threads", "1"});
  INFO(r.err);
  CHECK(r.exit_code == 7);
  CHECK(r.err.find("NOBUENOSS") != std::string::npos);
  const std::string json = file_text(report);
  CHECK(json.find("\"shelled\": \"after-pushes\"") != std::string::npos);
  CHECK(json.find("\"shelled\": 0,") == std::string::npos);  // it ran at least once
  CHECK(json.find("\"nobuenoss\": true") != std::string::npos);
}

TEST_CASE("cmx map on Furch's knotted hole stalls, finds a NOBUENOSS ahead and ends there (exit 7)") {
  // With its geometry and a sphere boundary of farthest corners, greedy expansion stops making
  // the cluster smaller (onto the stiff tet it now meets the NOBUENOSS itself); the early check (after 64,
  // 128, ... stalled expansions) expands the cluster mesh left topologically in four orders, each stops at a
  // NOBUENOSS, and the run ends as one, without restarts and long before the stall bound.
  const std::string dir = fresh_directory();
  const std::string mesh = dir + "/knotted.ovm", report = dir + "/r.json";
  REQUIRE(run_cmx({"generate-mesh", "--shape", "knotted-hole", "-o", mesh, "-q"}).exit_code == 0);
  const auto r = run_cmx({"map", mesh, "--shape", "sphere", "--corners", "farthest", "-o", dir + "/out",
                          "--report", report, "--threads", "1"});
  INFO(r.err);
  CHECK(r.exit_code == 7);
  CHECK(r.err.find("stalled: ") != std::string::npos);
  CHECK(r.err.find("NOBUENOSS ahead: topological expansion from the cluster mesh left stops at one") != std::string::npos);
  // "the last N expansions never left fewer than ...": N is one of the early checks, below the
  // stall bound of 1,024 + L/4.
  const std::size_t last = r.err.find("the last ");
  REQUIRE(last != std::string::npos);
  const int stalled_for = std::atoi(r.err.c_str() + last + 9);
  CHECK(stalled_for >= 64);
  CHECK(stalled_for < 512);
  CHECK(r.err.find("no shelling of the input found") != std::string::npos);
  CHECK_FALSE(fs::exists(dir + "/out.tmap"));
  const std::string json = file_text(report);
  CHECK(json.find("\"nobuenoss\": true") != std::string::npos);
  CHECK(json.find("\"restarts\": 0") != std::string::npos);
}
