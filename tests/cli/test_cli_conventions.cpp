// What every subcommand shares: --help, --version, --quiet, --opt=VALUE, bad values as exit 2
// naming the option, messages that start with "cmx CMD: " and show no raw control bytes, the
// version in every JSON output.
#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "run_cmx.hpp"

using cmx::test::file_text;
using cmx::test::fresh_directory;
using cmx::test::run_cmx;
using cmx::test::run_program;
using cmx::test::write_temp_file;
namespace fs = std::filesystem;

namespace {

const std::vector<std::string> all_commands = {"boundary", "chebyshev", "convert", "generate-mesh", "info",
                                               "map",      "orient3d",  "plot",    "topo-expand"};

// The version `cmx --version` prints ("cmx VERSION").
std::string version() {
  const auto r = run_cmx({"--version"});
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.out.rfind("cmx ", 0) == 0);
  REQUIRE(r.out.back() == '\n');
  return r.out.substr(4, r.out.size() - 5);
}

// Every line of `err` starts with "cmx CMD: ".
bool every_line_prefixed(const std::string& err, const std::string& command) {
  const std::string prefix = "cmx " + command + ": ";
  std::size_t start = 0;
  while (start < err.size()) {
    const std::size_t end = err.find('\n', start);
    if (err.compare(start, prefix.size(), prefix) != 0) return false;
    start = end == std::string::npos ? err.size() : end + 1;
  }
  return !err.empty();
}

std::string joined(const std::vector<std::string>& args) {
  std::string out;
  for (const auto& a : args) out += (out.empty() ? "" : " ") + a;
  return out;
}

// A bad command line: exit 2, nothing on stdout, one message "cmx CMD: ..." naming `option`.
void check_rejected(const std::vector<std::string>& args, const std::string& option) {
  INFO(joined(args));
  const auto r = run_cmx(args);
  CHECK(r.exit_code == 2);
  CHECK(r.out.empty());
  CHECK(every_line_prefixed(r.err, args[0]));
  CHECK(r.err.find(option) != std::string::npos);
}

std::string grid_mesh(const std::string& dir) {
  const std::string mesh = dir + "/grid.vtk";
  REQUIRE(run_cmx({"generate-mesh", "--shape", "grid:2,2,2", "--perturb", "1", "-o", mesh, "--quiet"}).exit_code == 0);
  return mesh;
}

}  // namespace

TEST_CASE("cmx --version and cmx CMD --version print the configure-time version") {
  const std::string v = version();
  CHECK_FALSE(v.empty());
  CHECK(v.find_first_not_of("0123456789abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ._+-") == std::string::npos);
  for (const auto& command : all_commands) {
    CAPTURE(command);
    const auto r = run_cmx({command, "--version"});
    CHECK(r.exit_code == 0);
    CHECK(r.out == "cmx " + v + "\n");
  }
}

TEST_CASE("outside a git checkout of its own the version is the project version") {
  // cmake/CmxVersion.cmake, run as a script on a folder that is no checkout (a temporary one).
  const std::string dir = fresh_directory();
  const auto r = run_program(CMX_CMAKE, {"-DCMX_VERSION_SOURCE_DIR=" + dir, "-DCMX_VERSION_FALLBACK=" CMX_PROJECT_VERSION, "-P",
                                         std::string(CMX_SOURCE_DIR) + "/cmake/CmxVersion.cmake"});
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(r.out == CMX_PROJECT_VERSION "\n");
  // On the sources themselves: git's description when they are a checkout, else the fallback.
  const auto git = run_program("/usr/bin/env", {"git", "-C", CMX_SOURCE_DIR, "describe", "--tags", "--always", "--dirty"});
  const auto here = run_program(CMX_CMAKE, {"-DCMX_VERSION_SOURCE_DIR=" CMX_SOURCE_DIR, "-DCMX_VERSION_FALLBACK=none", "-P",
                                            std::string(CMX_SOURCE_DIR) + "/cmake/CmxVersion.cmake"});
  CHECK(here.out == (git.exit_code == 0 ? git.out : "none\n"));
}

TEST_CASE("the version header is written from its template, and left alone when the version is the same") {
  // What the build runs before compiling the commands (cli/CMakeLists.txt, cmx_version_header).
  const std::string dir = fresh_directory();
  const std::string out = dir + "/cmx_version.hpp";
  const std::vector<std::string> args{
      "-DCMX_VERSION_SOURCE_DIR=" + dir,
      "-DCMX_VERSION_FALLBACK=" CMX_PROJECT_VERSION,
      "-DCMX_VERSION_TEMPLATE=" + std::string(CMX_SOURCE_DIR) + "/cmake/cmx_version.hpp.in",
      "-DCMX_VERSION_OUTPUT=" + out,
      "-P",
      std::string(CMX_SOURCE_DIR) + "/cmake/CmxVersion.cmake"};
  const auto first = run_program(CMX_CMAKE, args);
  INFO(first.err);
  REQUIRE(first.exit_code == 0);
  CHECK(first.out.empty());
  CHECK(file_text(out).find("cmx_version = \"" CMX_PROJECT_VERSION "\";") != std::string::npos);
  // Marked old by hand: written again with the same text, it would get a new time.
  const auto old = fs::file_time_type::clock::now() - std::chrono::hours(1);
  fs::last_write_time(out, old);
  REQUIRE(run_program(CMX_CMAKE, args).exit_code == 0);
  CHECK(fs::last_write_time(out) == old);
  // A stale text (another version) is replaced.
  std::ofstream(out) << "stale\n";
  REQUIRE(run_program(CMX_CMAKE, args).exit_code == 0);
  CHECK(file_text(out).find(CMX_PROJECT_VERSION) != std::string::npos);
}

TEST_CASE("every JSON output carries the version") {
  const std::string v = "\"cmx_version\": \"" + version() + "\"";
  const std::string dir = fresh_directory();
  const std::string mesh = grid_mesh(dir);
  const auto info = run_cmx({"info", mesh, "--json"});
  CHECK(info.out.find(v) != std::string::npos);
  const auto topo = run_cmx({"topo-expand", mesh, "--json"});
  CHECK(topo.out.find(v) != std::string::npos);
  const auto cheb = run_cmx({"chebyshev", "--json"}, "1 0 0 1\n-1 0 0 0\n0 1 0 1\n0 -1 0 0\n0 0 1 1\n0 0 -1 0\n");
  CHECK(cheb.out.find(v) != std::string::npos);
  REQUIRE(run_cmx({"map", mesh, "--shape", "tet", "-o", dir + "/m", "--report", dir + "/r.json", "--quiet"}).exit_code == 0);
  CHECK(file_text(dir + "/r.json").find(v) != std::string::npos);
  // A failure report too.
  REQUIRE(run_cmx({"map", mesh, "--shape", "tet", "--time-limit", "1e-9", "--report", dir + "/f.json"}).exit_code == 6);
  CHECK(file_text(dir + "/f.json").find(v) != std::string::npos);
}

TEST_CASE("every command has --help (exit 0, on stdout, with its synopsis and exit codes) and --quiet") {
  for (const auto& command : all_commands) {
    CAPTURE(command);
    const auto h = run_cmx({command, "--help"});
    CHECK(h.exit_code == 0);
    CHECK(h.err.empty());
    CHECK(h.out.find("usage: cmx " + command) == 0);
    CHECK(h.out.find("--quiet") != std::string::npos);
    CHECK(h.out.find("--version") != std::string::npos);
    CHECK(h.out.find("Exit") != std::string::npos);
  }
  CHECK(run_cmx({"map", "--help"}).out.find("NOBUENOSS") != std::string::npos);
  CHECK(run_cmx({"map", "--help"}).out.find("default 1234") != std::string::npos);
  const auto list = run_cmx({"--help"});
  for (const auto& command : all_commands) CHECK(list.out.find("  " + command + " ") != std::string::npos);
}

TEST_CASE("--opt=VALUE works like --opt VALUE, and --quiet drops the notes but not the results") {
  const std::string dir = fresh_directory();
  const std::string mesh = dir + "/m.vtk", b = dir + "/b.txt", converted = dir + "/c.mesh";
  auto r = run_cmx({"generate-mesh", "--shape=grid:2,2,2", "--perturb=4", "--output=" + mesh, "--quiet"});
  CHECK(r.exit_code == 0);
  CHECK(r.err.empty());
  r = run_cmx({"boundary", mesh, "--shape=star", "--seed=9", "--output=" + b});
  CHECK(r.exit_code == 0);
  CHECK(r.err.rfind("cmx boundary: wrote " + b, 0) == 0);
  r = run_cmx({"map", mesh, "--boundary=" + b, "--output=" + dir + "/out", "--format=vtk", "--time-limit=100", "--quiet"});
  CHECK(r.exit_code == 0);
  CHECK(r.out.empty());
  CHECK(file_text(dir + "/out.vtk").size() > 0);
  r = run_cmx({"convert", mesh, converted, "-q"});
  CHECK(r.exit_code == 0);
  CHECK(r.err.empty());
  r = run_cmx({"info", converted, "--json", "--quiet"});
  CHECK(r.out.find("\"is_ball\": true") != std::string::npos);  // the result stays
  r = run_cmx({"orient3d", "--filter=exact", "--quiet"}, "0 0 0 1 0 0 0 1 0 0 0 1\n");
  CHECK(r.out == "+\n");
  r = run_cmx({"topo-expand", "--builtin=grid:2,2,2", "--order=random:3", "--quiet"});
  CHECK(r.out.find("stuck: no") != std::string::npos);
}

TEST_CASE("bad option values are exit 2 naming the option, never wrapped or cut") {
  const std::string dir = fresh_directory();
  const std::string mesh = grid_mesh(dir), out = dir + "/never";
  check_rejected({"map", mesh, "--shape", "cube"}, "--shape");
  check_rejected({"boundary", mesh, "--shape", "cube", "-o", out}, "--shape");
  check_rejected({"map", mesh, "--shape", "tet", "--seed", "-1"}, "--seed");
  check_rejected({"map", mesh, "--shape", "tet", "--seed", "99999999999999999999999"}, "--seed");
  check_rejected({"boundary", mesh, "--shape", "tet", "-o", out, "--seed", "18446744073709551616"}, "--seed");
  check_rejected({"map", mesh, "--shape", "tet", "--seed", "12abc"}, "--seed");
  check_rejected({"map", mesh, "--shape", "tet", "--format", "vtu,stl"}, "--format");
  check_rejected({"map", mesh, "--shape", "tet", "--smooth", "1000001"}, "--smooth");
  check_rejected({"map", mesh, "--shape", "tet", "--smooth", "10x"}, "--smooth");
  check_rejected({"map", mesh, "--shape", "tet", "--subclusters", "+2"}, "--subclusters");
  check_rejected({"chebyshev", "--weight-bits", "54"}, "--weight-bits");
  check_rejected({"chebyshev", "--weight-bits", "24 "}, "--weight-bits");
  check_rejected({"generate-mesh", "--shape", "ball:2", "--perturb", "-5", "-o", out + ".vtk"}, "--perturb");
  check_rejected({"generate-mesh", "--shape", "ball:2", "--perturb", "1", "--amplitude", "0.1x", "-o", out + ".vtk"}, "--amplitude");
  check_rejected({"generate-mesh", "--shape", "grid:4294967296,1,1", "-o", out + ".vtk"}, "--shape");
  check_rejected({"orient3d", "--filter", "mpfr:0"}, "--filter");
  check_rejected({"topo-expand", "--builtin", "grid:2,2,2", "--order", "random:-1"}, "--order");
  check_rejected({"map", mesh, "--shape", "tet", "--arith", "mpfr:99999999"}, "--arith");
  // CLI11's own errors become exit 2 in the same form.
  check_rejected({"map", mesh, "--shape"}, "--shape");
  check_rejected({"map", mesh, "--shape", "tet", "--frobnicate"}, "--frobnicate");
  check_rejected({"map", "--shape", "tet"}, "DOMAIN");
  check_rejected({"plot", "t.csv"}, "--output");
  check_rejected({"info", "a.vtk", "b.vtk"}, "b.vtk");
  CHECK_FALSE(std::filesystem::exists(out));
}

TEST_CASE("CMX_SYNC_OUTPUT: 1 writes the same files as unset, a bad value is exit 2 before any work") {
  const std::string dir = fresh_directory();
  const std::string plain = dir + "/plain.vtk", synced = dir + "/synced.vtk", refused = dir + "/refused.vtk";
  const std::vector<std::string> make = {"generate-mesh", "--shape", "grid:2,2,2", "--quiet", "-o"};
  auto args = make;
  args.push_back(plain);
  REQUIRE(run_cmx(args).exit_code == 0);
  args = {"CMX_SYNC_OUTPUT=1", CMX_EXE};
  args.insert(args.end(), make.begin(), make.end());
  args.push_back(synced);
  REQUIRE(cmx::test::run_program("/usr/bin/env", args).exit_code == 0);
  CHECK(cmx::test::file_text(synced) == cmx::test::file_text(plain));
  args = {"CMX_SYNC_OUTPUT=yes", CMX_EXE};
  args.insert(args.end(), make.begin(), make.end());
  args.push_back(refused);
  const auto r = cmx::test::run_program("/usr/bin/env", args);
  CHECK(r.exit_code == 2);
  CHECK(every_line_prefixed(r.err, "generate-mesh"));
  CHECK(r.err.find("CMX_SYNC_OUTPUT: 'yes'") != std::string::npos);
  CHECK(!std::filesystem::exists(refused));
}

TEST_CASE("messages start with cmx CMD: and show control bytes and broken UTF-8 escaped") {
  // A token with an escape sequence and a byte that is not UTF-8: the message quotes it escaped.
  const auto r = run_cmx({"orient3d"}, "0 0 0 1 0 0 0 1 0 0 0 \x1b[31mX\xff\n");
  CHECK(r.exit_code == 3);
  CHECK(every_line_prefixed(r.err, "orient3d"));
  CHECK(r.err.find('\x1b') == std::string::npos);
  CHECK(r.err.find("\\x1B[31mX\\xFF") != std::string::npos);
  // A path with a control character, and one with UTF-8 (kept as it is).
  const auto p = run_cmx({"info", "/nonexistent/\x07\xc3\xa9.vtk"});
  CHECK(p.exit_code == 3);
  CHECK(p.err.find("/nonexistent/\\x07\xc3\xa9.vtk") != std::string::npos);
  // Binary garbage as a mesh: a message, no raw bytes.
  std::string garbage = "<VTKFile";
  for (int i = 0; i < 512; ++i) garbage += char((i * 37 + 11) % 256);
  const auto g = run_cmx({"info", write_temp_file(garbage, ".vtu")});
  CHECK(g.exit_code == 3);
  CHECK(every_line_prefixed(g.err, "info"));
  CHECK(std::none_of(g.err.begin(), g.err.end() - 1, [](char c) { return (unsigned char)c < 0x20; }));
}

TEST_CASE("an output that cannot be written is exit 9 in every command, before any work") {
  const std::string dir = fresh_directory();
  const std::string mesh = grid_mesh(dir), missing = dir + "/missing/";
  const std::string trace = write_temp_file("step,bits,max_bits,mean_bits,added_vertices,degenerate_left\n1,2,3,4,5,6\n");
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"convert", mesh, missing + "x.vtu"}, {"boundary", mesh, "--shape", "tet", "-o", missing + "b.txt"},
        {"generate-mesh", "--shape", "grid:1,1,1", "-o", missing + "g.vtk"}, {"plot", trace, "-o", missing + "t.svg"},
        {"map", mesh, "--shape", "tet", "-o", missing + "m"}}) {
    INFO(joined(args));
    const auto r = run_cmx(args);
    CHECK(r.exit_code == 9);
    CHECK(every_line_prefixed(r.err, args[0]));
    CHECK(r.err.find("cannot write") != std::string::npos);
  }
  // Checked before the input is even read: a missing input with an unwritable output is 9.
  CHECK(run_cmx({"boundary", dir + "/none.vtk", "--shape", "tet", "-o", missing + "b.txt"}).exit_code == 9);
}

TEST_CASE("notes and errors of every command start with cmx CMD:") {
  const std::string dir = fresh_directory();
  const std::string mesh = dir + "/g.vtk";
  auto r = run_cmx({"generate-mesh", "--shape", "grid:1,1,1", "-o", mesh});
  CHECK(every_line_prefixed(r.err, "generate-mesh"));
  r = run_cmx({"convert", mesh, dir + "/g.mesh"});
  CHECK(every_line_prefixed(r.err, "convert"));
  r = run_cmx({"chebyshev"}, "1 2 3\n");
  CHECK(every_line_prefixed(r.err, "chebyshev"));
  r = run_cmx({"info", dir});
  CHECK(every_line_prefixed(r.err, "info"));
  r = run_cmx({"topo-expand", dir + "/none.ovm"});
  CHECK(every_line_prefixed(r.err, "topo-expand"));
  r = run_cmx({"nosuchcommand"});
  CHECK(r.exit_code == 2);
  CHECK(r.err.rfind("cmx: unknown command 'nosuchcommand'", 0) == 0);
}
