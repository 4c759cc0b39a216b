// Inputs and earlier results are never destroyed: an output that is an input is refused, the
// report of a failed run does not replace an existing file unless asked, and input files that
// cannot be read say why.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "map_case.hpp"
#include "run_cmx.hpp"

using cmx::test::file_text;
using cmx::test::run_cmx;
namespace fs = std::filesystem;

namespace {

using Files = cmx::test::Case;

Files make_files() { return cmx::test::make_case("grid:2,2,2", "tet"); }

// `args` exit 2 with "refusing to write", and the inputs keep their bytes.
void check_refused(const Files& f, const std::vector<std::string>& args) {
  const std::string mesh = file_text(f.mesh), boundary = file_text(f.boundary);
  const auto r = run_cmx(args);
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("refusing to write") != std::string::npos);
  CHECK(file_text(f.mesh) == mesh);
  CHECK(file_text(f.boundary) == boundary);
}

// A boundary file that is not star-shaped (vertex 22, the centre of the top face, pulled down).
std::string bad_boundary(const Files& f) {
  std::string text, line;
  std::istringstream in(file_text(f.boundary));
  while (std::getline(in, line)) text += (line.rfind("22 ", 0) == 0 ? std::string("22 0 0 -50") : line) + "\n";
  const std::string path = f.dir + "/bad.txt";
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST_CASE("an output that resolves to an input is refused with exit 2, through ./ and symbolic links") {
  const Files f = make_files();
  const std::string dot = f.dir + "/./domain.vtk", link = f.dir + "/link.vtk";
  fs::create_symlink(f.mesh, link);
  check_refused(f, {"map", f.mesh, "--boundary", f.boundary, "-o", dot});
  check_refused(f, {"map", f.mesh, "--boundary", f.boundary, "-o", link});
  check_refused(f, {"map", f.mesh, "--boundary", f.boundary, "-o", f.dir + "/domain", "--format", "vtk"});  // OUT.vtk
  check_refused(f, {"map", f.mesh, "--boundary", f.boundary, "--report", f.boundary});
  check_refused(f, {"map", f.mesh, "--boundary", f.boundary, "--trace", link});
  check_refused(f, {"map", f.mesh, "--codomain", link, "-o", f.dir + "/domain.vtk"});
  check_refused(f, {"map", f.mesh, "--boundary", f.boundary, "-o", f.dir + "/m", "--report", f.dir + "/m.tmap"});
  check_refused(f, {"convert", f.mesh, dot});
  check_refused(f, {"convert", link, f.mesh});
  check_refused(f, {"boundary", f.mesh, "--shape", "tet", "-o", link});
  const std::string trace = f.dir + "/t.csv";
  REQUIRE(run_cmx({"map", f.mesh, "--boundary", f.boundary, "--trace", trace, "-q"}).exit_code == 0);
  const std::string rows = file_text(trace);
  const auto r = run_cmx({"plot", trace, "-o", f.dir + "/./t.csv"});
  CHECK(r.exit_code == 2);
  CHECK(file_text(trace) == rows);
}

TEST_CASE("the report of a failed run does not replace an existing file unless --report-on-failure") {
  const Files f = make_files();
  const std::string bad = bad_boundary(f), report = f.dir + "/r.json", trace = f.dir + "/t.csv";
  // A success writes its report (atomically) over anything.
  std::ofstream(report) << "old\n";
  REQUIRE(run_cmx({"map", f.mesh, "--boundary", f.boundary, "--report", report, "-q"}).exit_code == 0);
  CHECK(file_text(report).find("\"status\": \"success\"") != std::string::npos);
  // A failure keeps the earlier report and trace, and says so.
  const std::string good = file_text(report);
  std::ofstream(trace) << "old trace\n";
  auto r = run_cmx({"map", f.mesh, "--boundary", bad, "--report", report, "--trace", trace});
  CHECK(r.exit_code == 5);
  CHECK(file_text(report) == good);
  CHECK(file_text(trace) == "old trace\n");
  CHECK(r.err.find("not replacing '" + report + "'") != std::string::npos);
  // A failure report goes to a path that does not exist yet.
  const std::string fresh = f.dir + "/fresh.json";
  CHECK(run_cmx({"map", f.mesh, "--boundary", bad, "--report", fresh}).exit_code == 5);
  CHECK(file_text(fresh).find("\"status\": \"not_star_shaped\"") != std::string::npos);
  // Asked for, it replaces the existing one.
  r = run_cmx({"map", f.mesh, "--boundary", bad, "--report", report, "--report-on-failure"});
  CHECK(r.exit_code == 5);
  CHECK(file_text(report).find("\"status\": \"not_star_shaped\"") != std::string::npos);
  for (const auto& entry : fs::directory_iterator(f.dir)) CHECK(entry.path().string().find(".tmp.") == std::string::npos);
}

TEST_CASE("a directory given as an input file is named as a directory, exit 3") {
  const Files f = make_files();
  const std::string dir = f.dir + "/folder.vtk";
  fs::create_directories(dir);
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"map", dir, "--shape", "tet"}, {"map", f.mesh, "--boundary", f.dir}, {"map", f.mesh, "--codomain", dir},
        {"info", dir}, {"convert", dir, f.dir + "/x.mesh"}, {"boundary", dir, "--shape", "tet", "-o", f.dir + "/b2.txt"},
        {"topo-expand", dir}, {"orient3d", f.dir}, {"chebyshev", f.dir}, {"plot", f.dir, "-o", f.dir + "/p.svg"}}) {
    INFO(args[0] << " " << args[1] << " " << args.back());
    const auto r = run_cmx(args);
    CHECK(r.exit_code == 3);
    CHECK(r.err.find(": is a directory") != std::string::npos);
  }
}

TEST_CASE("an input that cannot be opened says why (the system's reason)") {
  const Files f = make_files();
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"info", f.dir + "/none.vtk"}, {"map", f.mesh, "--boundary", f.dir + "/none.txt"},
        {"map", f.dir + "/none.node", "--shape", "tet"}, {"orient3d", f.dir + "/none.txt"}}) {
    INFO(args[0] << " " << args[1] << " " << args.back());
    const auto r = run_cmx(args);
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("none.") != std::string::npos);
    CHECK(r.err.find("No such file or directory") != std::string::npos);
  }
  // cmx map records the failure in its report.
  const std::string report = f.dir + "/missing.json";
  CHECK(run_cmx({"map", f.dir + "/none.vtk", "--shape", "tet", "--report", report}).exit_code == 3);
  CHECK(file_text(report).find("\"status\": \"bad_input\"") != std::string::npos);
  // TetGen: the .node exists, its .ele does not.
  std::ofstream(f.dir + "/half.node") << "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
  const auto r = run_cmx({"info", f.dir + "/half.node"});
  CHECK(r.exit_code == 3);
  CHECK(r.err.find("half.ele: cannot open: No such file or directory") != std::string::npos);
}
