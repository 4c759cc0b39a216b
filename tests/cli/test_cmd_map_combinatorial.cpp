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

TEST_CASE("the dunce-hat ball as a facet list: generate-mesh writes it, topo-expand and map meet the hat") {
  const auto dir = fs::path(fresh_stem());
  fs::create_directories(dir);
  const std::string file = (dir / "dunce.facets").string();
  // Without positions it can only be written as a facet list; --perturb has nothing to move.
  const auto ovm = run_cmx({"generate-mesh", "--shape", "dunce-hat-ball", "-o", (dir / "d.ovm").string()});
  CHECK(ovm.exit_code == 2);
  CHECK(ovm.err.find("dunce-hat-ball has no positions: write it as a .facets file") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "d.ovm"));
  CHECK(run_cmx({"generate-mesh", "--shape", "dunce-hat-ball", "--perturb", "1", "-o", file}).exit_code == 2);
  CHECK_FALSE(fs::exists(file));
  const auto g = run_cmx({"generate-mesh", "--shape", "dunce-hat-ball", "-o", file});
  INFO(g.err);
  REQUIRE(g.exit_code == 0);
  CHECK(g.err.find("27 vertices, 90 tets") != std::string::npos);
  // topo-expand reads the facet list (orienting it) and, the hat last, is stuck on exactly it.
  const auto t = run_cmx({"topo-expand", file, "--order", "index"});
  INFO(t.out << t.err);
  REQUIRE(t.exit_code == 0);
  CHECK(t.out.find("(27 vertices, 90 tets; a ball)") != std::string::npos);
  CHECK(t.out.find("stuck: yes: 8 cluster vertices remain (Euler characteristic 1, b0 1)") !=
        std::string::npos);
  CHECK(t.out.find("a shelling of the 90 tets found") != std::string::npos);
  const auto b = run_cmx({"topo-expand", "--builtin", "dunce-hat-ball", "--order", "index"});
  CHECK(b.out.find("builtin:dunce-hat-ball (27 vertices, 90 tets; a ball)") != std::string::npos);
  CHECK(b.out.find("stuck: yes: 8 cluster vertices remain (Euler characteristic 1, b0 1)") !=
        std::string::npos);
  // Collars: dunce-hat-ball:C, C from 1 to 64, the hat still on the last 8 ids.
  const auto c3 =
      run_cmx({"topo-expand", "--builtin", "dunce-hat-ball:3", "--order", "index", "--fallback", "none"});
  CHECK(c3.out.find("(39 vertices, 138 tets; a ball)") != std::string::npos);
  CHECK(c3.out.find("stuck: yes: 8 cluster vertices remain") != std::string::npos);
  CHECK(run_cmx({"topo-expand", "--builtin", "dunce-hat-ball:0"}).exit_code == 2);
  CHECK(run_cmx({"generate-mesh", "--shape", "dunce-hat-ball:65", "-o", file}).exit_code == 2);
  const std::string file3 = (dir / "dunce3.facets").string();
  const auto g3 = run_cmx({"generate-mesh", "--shape", "dunce-hat-ball:3", "-o", file3});
  CHECK(g3.exit_code == 0);
  CHECK(g3.err.find("39 vertices, 138 tets") != std::string::npos);
  // map accepts the deferral with --combinatorial (a combinatorial run starts shrunk); the greedy
  // run meets the hat, a NOBUENOSS, and the run replays a shelling from the start and maps.
  const std::string stem = (dir / "m").string();
  const auto m = run_cmx({"map", file, "--shape", "sphere", "--order", "priority,defer:19-27", "-o", stem,
                          "--report", stem + ".json"});
  INFO(m.out << m.err);
  CHECK(m.exit_code == 0);
  CHECK(fs::exists(stem + ".tmap"));
  const std::string report = file_text(stem + ".json");
  CHECK(report.find("\"nobuenoss\": true") != std::string::npos);
  CHECK(report.find("\"after_nobuenoss\": true") != std::string::npos);
  CHECK(report.find("\"input_vertices\": [") != std::string::npos);
  CHECK(report.find("\"plans_tried\": 1") != std::string::npos);
  // --replay-shelling off: stuck on the hat, exit 7, with the shelling verdict; nothing written.
  const std::string off = (dir / "off").string();
  const auto o = run_cmx({"map", file, "--shape", "sphere", "--order", "priority,defer:19-27",
                          "--replay-shelling", "off", "-o", off});
  CHECK(o.exit_code == 7);
  CHECK(o.err.find("NOBUENOSS: 8 cluster vertices left") != std::string::npos);
  CHECK(o.err.find("a shelling of its 90 tets was found") != std::string::npos);
  CHECK(o.err.find("not replayed (--replay-shelling off)") != std::string::npos);
  CHECK_FALSE(fs::exists(off + ".tmap"));
  // A grid written as a facet list reads back as the same complex.
  const std::string grid = (dir / "grid.facets").string();
  REQUIRE(run_cmx({"generate-mesh", "--shape", "grid:2,2,2", "-o", grid, "-q"}).exit_code == 0);
  const auto tg = run_cmx({"topo-expand", grid});
  CHECK(tg.out.find("(27 vertices, 48 tets; a ball)") != std::string::npos);
  fs::remove_all(dir);
}
