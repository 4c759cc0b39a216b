// cmx map --combinatorial (implied by a .facets DOMAIN): a ball given by its tets alone is
// realised in the target; the program orients the facets, takes the orientation the prescribed
// boundary asks for, and refuses what is not an orientable ball with the usual exit codes.
#include <doctest/doctest.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "arith/rational.hpp"
#include "io/tmap.hpp"
#include "run_cmx.hpp"
#include "support/combinatorial_balls.hpp"

using cmx::test::file_text;
using cmx::test::run_cmx;
using cmx::test::write_temp_file;
namespace fs = std::filesystem;

namespace {

std::string facet_file(const std::vector<std::array<std::uint32_t, 4>>& facets, bool one_based) {
  std::string text = "# a facet list\n";
  for (const auto& f : facets)
    text += std::to_string(f[0] + one_based) + " " + std::to_string(f[1] + one_based) + " " +
            std::to_string(f[2] + one_based) + " " + std::to_string(f[3] + one_based) + "\n";
  return write_temp_file(text, ".facets");
}

std::string fresh_stem() {
  const auto path = write_temp_file("", "");
  fs::remove(path);
  return path;
}

}  // namespace

TEST_CASE("cmx map on Ziegler's ball as a facet list: a verified realisation, the same map again") {
  const auto facets = facet_file(cmx::test::ziegler_ball(), true);
  const auto out = fresh_stem(), again = fresh_stem();
  const auto r = run_cmx({"map", facets, "--shape", "star", "-o", out, "--report", out + ".json"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("a realisation verified exactly") != std::string::npos);
  const std::string report = file_text(out + ".json");
  CHECK(report.find("\"combinatorial\": true") != std::string::npos);
  CHECK(report.find("\"exact_valid\": true") != std::string::npos);
  // The .tmap reads back with every tet positive in both columns (both are the realisation).
  const cmx::io::TetMap m = cmx::io::read_tmap(out + ".tmap");
  CHECK(m.source == m.target);
  CHECK(m.tets.size() > cmx::test::ziegler_ball().size());
  REQUIRE(run_cmx({"map", facets, "--shape", "star", "-o", again, "--quiet"}).exit_code == 0);
  CHECK(file_text(out + ".tmap") == file_text(again + ".tmap"));
}

TEST_CASE("cmx map --combinatorial turns the tets over when the prescribed boundary asks for it") {
  const auto facets = facet_file(cmx::test::ziegler_ball(), false);
  const auto first = fresh_stem();
  REQUIRE(run_cmx({"map", facets, "--shape", "sphere", "-o", first, "--quiet"}).exit_code == 0);
  // The same boundary positions mirrored (x negated) enclose the domain with the other orientation.
  const cmx::io::TetMap m = cmx::io::read_tmap(first + ".tmap");
  std::string mirrored;
  for (std::size_t v = 0; v < 10; ++v)  // every vertex of Ziegler's ball is on the boundary
    mirrored += std::to_string(v) + " " + cmx::Rational(-m.target[v][0]).get_str() + " " + m.target[v][1].get_str() + " " +
                m.target[v][2].get_str() + "\n";
  const auto boundary = write_temp_file(mirrored, ".txt");
  const auto second = fresh_stem();
  const auto r = run_cmx({"map", facets, "--boundary", boundary, "-o", second, "--quiet"});
  INFO(r.err);
  CHECK(r.exit_code == 0);
  // Without --combinatorial a mesh file's positions would be used; with it they are ignored: the
  // realisation of the written map, read as a mesh, maps again combinatorially.
  const auto mesh = fresh_stem() + ".vtk";
  REQUIRE(run_cmx({"convert", second + ".tmap", mesh}).exit_code == 0);
  CHECK(run_cmx({"map", mesh, "--combinatorial", "--shape", "tet", "-o", fresh_stem(), "--quiet"}).exit_code == 0);
}

TEST_CASE("cmx map --combinatorial refuses what is not an orientable ball, and malformed facet lists") {
  // Two tets sharing one edge: orientable, not a ball (exit 4).
  const auto two = write_temp_file("0 1 2 3\n0 1 4 5\n", ".facets");
  const auto a = run_cmx({"map", two, "--shape", "tet", "-o", fresh_stem()});
  CHECK(a.exit_code == 4);
  CHECK(a.err.find("not a ball") != std::string::npos);
  // A face in three tets: cannot be oriented alike (exit 4, naming the face).
  const auto three = write_temp_file("0 1 2 3\n0 1 2 4\n0 1 2 5\n", ".facets");
  const auto b = run_cmx({"map", three, "--shape", "tet", "-o", fresh_stem()});
  CHECK(b.exit_code == 4);
  CHECK(b.err.find("oriented alike") != std::string::npos);
  // Three ids on a line: malformed (exit 3, file and line named), nothing written.
  const auto bad = write_temp_file("0 1 2 3\n0 1 2\n", ".facets");
  const auto out = fresh_stem();
  const auto c = run_cmx({"map", bad, "--shape", "tet", "-o", out});
  CHECK(c.exit_code == 3);
  CHECK(c.err.find(bad + ":2:") != std::string::npos);
  CHECK_FALSE(fs::exists(out + ".tmap"));
}
