// cmx topo-expand, run as a program: complete on grids, stuck on Furch's knotted hole in every
// order (exit 0: stuck is a result), the JSON report's keys and their consistency, exit codes.
#include <doctest/doctest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "run_cmx.hpp"

using cmx::test::run_cmx;
using cmx::test::write_temp_file;

namespace {

// Where the value of "key" starts in a JSON report ("\"key\": " precedes it), or npos. Keys are
// unique in the report ("1", "2", "3" occur only inside "k_manifold").
std::size_t value_position(const std::string& json, const char* key) {
  std::string tag = "\"";  // built piecewise: g++ 12 -Wrestrict misfires on "\"" + std::string
  tag += key;
  tag += "\": ";
  const auto at = json.find(tag);
  return at == std::string::npos ? at : at + tag.size();
}

// The integer value of "key"; -1 when the key is absent.
long json_integer(const std::string& json, const char* key) {
  const std::size_t at = value_position(json, key);
  return at == std::string::npos ? -1 : std::strtol(json.c_str() + at, nullptr, 10);
}

bool json_has(const std::string& json, const std::string& text) {
  return json.find(text) != std::string::npos;
}

// A Medit file of an n x n x n Kuhn grid: vertex (i,j,k) at the integer point, 6 tets per cell
// along the paths corner -> +e_a -> +e_b -> +e_c, each listed positively (odd paths reversed).
std::string grid_medit(int n) {
  const auto id = [n](int i, int j, int k) { return 1 + i + (n + 1) * (j + (n + 1) * k); };  // 1-based
  std::string vertices, tets;
  int num_tets = 0;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        vertices += std::to_string(i) + ' ' + std::to_string(j) + ' ' + std::to_string(k) + " 0\n";
  const std::array<std::array<int, 3>, 6> paths = {
      {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (std::size_t p = 0; p < paths.size(); ++p) {
          std::array<int, 3> at = {i, j, k};
          std::array<int, 4> tet{};
          tet[0] = id(at[0], at[1], at[2]);
          for (std::size_t s = 0; s < 3; ++s) {
            ++at[std::size_t(paths[p][s])];
            tet[s + 1] = id(at[0], at[1], at[2]);
          }
          if (p >= 3) std::swap(tet[2], tet[3]);  // the last three paths are odd permutations
          tets += std::to_string(tet[0]) + ' ' + std::to_string(tet[1]) + ' ' + std::to_string(tet[2]) + ' ' +
                  std::to_string(tet[3]) + " 0\n";
          ++num_tets;
        }
  return "MeshVersionFormatted 1\nDimension 3\nVertices\n" + std::to_string((n + 1) * (n + 1) * (n + 1)) +
         "\n" + vertices + "Tetrahedra\n" + std::to_string(num_tets) + "\n" + tets + "End\n";
}

// `cmx topo-expand --builtin NAME --order ORDER --json`, which must exit 0; returns stdout. The
// shelling fallback is off unless asked for: it is tested on its own below.
std::string expand_json(const char* builtin, const char* order, const char* fallback = "none") {
  const auto r =
      run_cmx({"topo-expand", "--builtin", builtin, "--order", order, "--fallback", fallback, "--json"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  return r.out;
}

// Every count of the report adds up: the sequence is the sum of its kinds, and what was not
// expanded remains.
void check_consistent(const std::string& json) {
  const long length = json_integer(json, "sequence_length");
  CHECK(length == json_integer(json, "1") + json_integer(json, "2") + json_integer(json, "3") +
                      json_integer(json, "other") + json_integer(json, "automatic"));
  CHECK(length + json_integer(json, "remaining_vertices") == json_integer(json, "initial_cluster_vertices"));
  CHECK(json_has(json, "\"seconds\": "));
}

}  // namespace

TEST_CASE("cmx topo-expand completes on a grid file and on the builtin grid") {
  const auto path = write_temp_file(grid_medit(3), ".mesh");
  const auto text = run_cmx({"topo-expand", path});
  INFO(text.err);
  REQUIRE(text.exit_code == 0);
  CHECK(json_has(text.out, "(64 vertices, 162 tets; a ball)"));
  CHECK(json_has(text.out, "order: priority\n"));
  CHECK(json_has(text.out, "initial cluster vertices: 8\n"));
  CHECK(json_has(text.out, "sequence length: 8\n"));
  CHECK(json_has(text.out, "stuck: no"));
  CHECK(json_has(text.out, "time: "));

  for (const char* order : {"priority", "index", "random:7"}) {
    CAPTURE(order);
    const std::string json = expand_json("grid:6,5,4", order);
    CHECK(json_has(json, "\"stuck\": false"));
    CHECK(json_integer(json, "initial_cluster_vertices") == 5 * 4 * 3);
    CHECK(json_integer(json, "sequence_length") == 5 * 4 * 3);
    CHECK(json_integer(json, "remaining_vertices") == 0);
    CHECK(json_integer(json, "automatic") >= 1);  // at least the last vertex
    CHECK(json_has(json, "\"order\": \"" + std::string(order) + "\""));
    check_consistent(json);
  }
}

TEST_CASE("cmx topo-expand --json: one object with every documented key") {
  const auto r = run_cmx({"topo-expand", "--builtin=grid:2,2,2", "--order=index", "--json"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.front() == '{');
  CHECK(r.out.substr(r.out.size() - 2) == "}\n");
  for (const char* key :
       {"source", "vertices", "tets", "order", "initial_cluster_vertices", "sequence_length", "k_manifold",
        "1", "2", "3", "other", "automatic", "stuck", "remaining_vertices", "remaining_euler",
        "remaining_components", "fallback", "seconds", "fallback_seconds"})
    CHECK_MESSAGE(value_position(r.out, key) != std::string::npos, key);
  CHECK(json_has(r.out, "\"source\": \"builtin:grid:2,2,2\""));
  CHECK(json_integer(r.out, "vertices") == 27);
  CHECK(json_integer(r.out, "tets") == 48);
  CHECK(json_integer(r.out, "initial_cluster_vertices") == 1);
  CHECK(json_integer(r.out, "automatic") == 1);        // a lone cluster vertex is expanded automatically
  CHECK(json_integer(r.out, "remaining_euler") == 0);  // the empty cluster mesh
  CHECK(json_integer(r.out, "remaining_components") == 0);
  CHECK(json_has(r.out, "\"fallback\": null"));  // not stuck: no fallback ran
}

TEST_CASE(
    "cmx topo-expand reports stuck on the knotted hole in every order (exit 0) and completes on the "
    "control") {
  for (const char* order : {"priority", "index", "random:1"}) {
    CAPTURE(order);
    const std::string json = expand_json("knotted-hole", order);
    CHECK(json_has(json, "\"stuck\": true"));
    CHECK(json_integer(json, "tets") == 59286);
    CHECK(json_integer(json, "initial_cluster_vertices") == 7944);
    CHECK(json_integer(json, "sequence_length") > 0);
    CHECK(json_integer(json, "remaining_vertices") >= 2);
    // Corollary 1: Eq. (1) expansions keep the cluster mesh simply connected.
    CHECK(json_integer(json, "remaining_euler") == 1);
    CHECK(json_integer(json, "remaining_components") == 1);
    check_consistent(json);
  }
  const auto text = run_cmx({"topo-expand", "--builtin", "knotted-hole", "--fallback", "none"});
  CHECK(text.exit_code == 0);
  CHECK(!json_has(text.out, "fallback"));
  CHECK(json_has(text.out, "stuck: yes: "));
  CHECK(json_has(text.out, "(Euler characteristic 1, b0 1), none satisfies Eq. (1)"));
  for (const char* order : {"priority", "index", "random:1"}) {
    CAPTURE(order);
    const std::string json = expand_json("unknotted-hole", order);
    CHECK(json_has(json, "\"stuck\": false"));
    CHECK(json_integer(json, "sequence_length") == json_integer(json, "initial_cluster_vertices"));
    check_consistent(json);
  }
  // Bing's house: stuck before the first expansion.
  const auto bing = run_cmx({"topo-expand", "--builtin", "bings-house", "--fallback", "none", "--json"});
  CHECK(bing.exit_code == 0);
  CHECK(json_has(bing.out, "\"stuck\": true"));
  CHECK(json_integer(bing.out, "sequence_length") == 0);
  // The same house in a full box: the index order meets it after every other interior vertex
  // (a NOBUENOSS of exactly the house's vertices); strict-index is the same order here (there
  // are no classes in topological expansion); the default order completes.
  const std::string in_box = expand_json("bings-house-box", "index");
  CHECK(json_has(in_box, "\"stuck\": true"));
  const long left = json_integer(in_box, "remaining_vertices");
  CHECK(left > 0);
  CHECK(json_integer(in_box, "sequence_length") + left == json_integer(in_box, "initial_cluster_vertices"));
  CHECK(json_integer(in_box, "remaining_euler") == 1);
  const std::string strict = expand_json("bings-house-box", "strict-index");
  CHECK(json_integer(strict, "remaining_vertices") == left);  // no classes here: the same order
  const auto box_default = run_cmx({"topo-expand", "--builtin", "bings-house-box", "--json"});
  CHECK(json_has(box_default.out, "\"stuck\": false"));
  // cmx generate-mesh writes the same ball, numbering included.
  const std::string file = write_temp_file("", ".ovm");
  std::remove(file.c_str());
  REQUIRE(run_cmx({"generate-mesh", "--shape", "bings-house-box", "-o", file, "-q"}).exit_code == 0);
  const auto from_file = run_cmx({"topo-expand", file, "--order", "index", "--fallback", "none", "--json"});
  CHECK(from_file.exit_code == 0);
  CHECK(json_integer(from_file.out, "remaining_vertices") == left);
  // The compact house in its box: the same in index order, and in the default order once the
  // house (ids 1176 to 1484) is deferred; generate-mesh writes the same ball.
  CHECK(json_integer(expand_json("compact-bings-house-box", "index"), "remaining_vertices") == 309);
  const std::string deferred = expand_json("compact-bings-house-box", "priority,defer:1176-1485");
  CHECK(json_integer(deferred, "remaining_vertices") == 309);
  CHECK(json_has(deferred, "\"order\": \"priority,defer:1176-1485\""));
  CHECK(json_has(run_cmx({"topo-expand", "--builtin", "compact-bings-house-box", "--json"}).out,
                 "\"stuck\": false"));
  std::remove(file.c_str());
  REQUIRE(run_cmx({"generate-mesh", "--shape", "compact-bings-house-box", "-o", file, "-q"}).exit_code == 0);
  const auto compact = run_cmx({"topo-expand", file, "--order", "index", "--fallback", "none", "--json"});
  CHECK(json_integer(compact.out, "remaining_vertices") == 309);
  std::remove(file.c_str());
  for (const char* bad : {"priority,defer:5", "priority,defer:9-9", "index,defer:a-b"}) {
    const auto r = run_cmx({"topo-expand", "--builtin", "grid:2,2,2", "--order", bad});
    CAPTURE(bad);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("unknown order") != std::string::npos);
  }
}

TEST_CASE(
    "cmx topo-expand: when stuck, the shelling fallback replays Alg. 2 on the house box and finds no "
    "shelling of the knot") {
  // Bing's house in a box is shellable: the replay (from the start, boundary in place) expands
  // every interior vertex of the input and the split vertices it makes, each satisfying Eq. (1).
  const std::string box = expand_json("bings-house-box", "index", "shelling");
  CHECK(json_has(box, "\"stuck\": true"));  // the greedy run's own verdict is kept
  CHECK(json_has(box, "\"shelling_found\": true"));
  CHECK(json_has(box, "\"replayed\": true"));
  CHECK(json_has(box, "\"completed\": true"));
  CHECK(json_integer(box, "eq1_failures") == 0);
  CHECK(json_integer(box, "left") == 0);
  CHECK(json_integer(box, "chord_splits") == 0);                          // the box has none
  CHECK(json_integer(box, "best_removed") == json_integer(box, "tets"));  // all peeled, no chord to add tets
  CHECK(json_integer(box, "input_expansions") == json_integer(box, "initial_cluster_vertices"));
  CHECK(json_integer(box, "expansions") ==
        json_integer(box, "input_expansions") + json_integer(box, "cluster_splits"));
  CHECK(json_integer(box, "cluster_splits") > 0);
  CHECK(json_integer(box, "boundary_splits") > 0);
  // The steps whose geometric half is empty are counted, so that the report says what cmx map
  // could not replay (docs/algorithm/expansion.md).
  CHECK(json_integer(box, "empty_cone_edge_splits") > 0);
  CHECK(json_integer(box, "empty_cone_edge_splits") <= json_integer(box, "cluster_splits"));
  // The knotted hole is not shellable: no attempt peels it, and nothing is replayed.
  const auto knot = run_cmx({"topo-expand", "--builtin", "knotted-hole"});
  INFO(knot.err);
  REQUIRE(knot.exit_code == 0);
  CHECK(json_has(knot.out, "stuck: yes: "));
  CHECK(
      json_has(knot.out, "fallback (paper Sec. 4.3, topology only): no shelling found in 8 greedy attempts"));
  CHECK(json_has(knot.out, "the input may not be shellable"));
  CHECK(!json_has(knot.out, "replay:"));
  // Not stuck: the fallback does not run.
  CHECK(json_has(expand_json("bings-house-box", "priority", "shelling"), "\"fallback\": null"));
}

TEST_CASE(
    "cmx topo-expand --fallback always --check: the replay on a grid, its cluster mesh checked at every "
    "step") {
  const auto r =
      run_cmx({"topo-expand", "--builtin", "grid:4,3,3", "--fallback", "always", "--check", "--json"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(json_has(r.out, "\"stuck\": false"));  // the greedy run completes; the replay runs anyway
  CHECK(json_has(r.out, "\"completed\": true"));
  const long expansions = json_integer(r.out, "expansions");
  CHECK(expansions >= json_integer(r.out, "initial_cluster_vertices"));
  CHECK(json_integer(r.out, "checks") == expansions + 1);  // before the first and after each
  // The fallback splits every chord first; their vertices are reported apart from the input's.
  CHECK(json_integer(r.out, "chord_splits") == 0);  // the greedy run's: none needed on a grid
  CHECK(json_integer(r.out, "split_chords") > 0);   // the fallback's: every chord
  CHECK(json_integer(r.out, "chord_expansions") == json_integer(r.out, "split_chords"));
  CHECK(json_integer(r.out, "input_expansions") == json_integer(r.out, "initial_cluster_vertices"));
  CHECK(expansions == json_integer(r.out, "input_expansions") + json_integer(r.out, "chord_expansions") +
                          json_integer(r.out, "cluster_splits"));
  CHECK(json_integer(r.out, "check_failures") == 0);
  const auto text = run_cmx({"topo-expand", "--builtin", "grid:4,3,3", "--fallback", "always", "--check"});
  CHECK(json_has(text.out, "replay checks (--check): " + std::to_string(expansions + 1) +
                               " cluster meshes, 0 not simply connected"));
  // Without --check nothing is counted.
  CHECK(json_integer(expand_json("grid:4,3,3", "index", "always"), "checks") == 0);
}

TEST_CASE("cmx topo-expand: usage errors exit 2") {
  const auto bad_order = run_cmx({"topo-expand", "--builtin", "grid:2,2,2", "--order", "shelling"});
  CHECK(bad_order.exit_code == 2);
  CHECK(json_has(bad_order.err, "unknown order 'shelling'"));
  CHECK(bad_order.out.empty());
  CHECK(run_cmx({"topo-expand", "--builtin", "grid:2,2,2", "--order", "random:"}).exit_code == 2);
  CHECK(run_cmx({"topo-expand", "--builtin", "grid:2,2,2", "--order"}).exit_code == 2);
  const auto bad_fallback = run_cmx({"topo-expand", "--builtin", "grid:2,2,2", "--fallback", "flips"});
  CHECK(bad_fallback.exit_code == 2);
  CHECK(json_has(bad_fallback.err, "--fallback"));
  CHECK(run_cmx({"topo-expand"}).exit_code == 2);
  CHECK(run_cmx({"topo-expand", "a.vtk", "b.vtk"}).exit_code == 2);
  CHECK(run_cmx({"topo-expand", "a.vtk", "--builtin", "knotted-hole"}).exit_code == 2);
  CHECK(run_cmx({"topo-expand", "--frobnicate"}).exit_code == 2);
  const auto unknown = run_cmx({"topo-expand", "--builtin", "trefoil"});
  CHECK(unknown.exit_code == 2);
  CHECK(json_has(unknown.err, "unknown builtin 'trefoil'"));
  for (const char* grid :
       {"grid:0,1,1", "grid:1,1", "grid:1,1,1,", "grid:a,1,1", "grid:100000,100000,100000"}) {
    CAPTURE(grid);
    const auto r = run_cmx({"topo-expand", "--builtin", grid});
    CHECK(r.exit_code == 2);
    CHECK(json_has(r.err, "bad grid size"));
  }
  const auto help = run_cmx({"topo-expand", "--help"});
  CHECK(help.exit_code == 0);
  CHECK(json_has(help.out, "stuck is a result, not an error"));
  CHECK(json_has(run_cmx({"--help"}).out, "topo-expand"));
}

TEST_CASE("cmx topo-expand: unreadable input exits 3 with file:line and a non-ball exits 4 with the reason") {
  const auto missing = run_cmx({"topo-expand", "/nonexistent/domain.ovm"});
  CHECK(missing.exit_code == 3);
  CHECK(json_has(missing.err, "/nonexistent/domain.ovm: "));
  const auto malformed = write_temp_file(
      "# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 2 double\n0 0 0\n1 x 0\n",
      ".vtk");
  const auto bad = run_cmx({"topo-expand", malformed});
  CHECK(bad.exit_code == 3);
  CHECK(bad.err.find("cmx topo-expand: " + malformed + ":7: ") == 0);
  CHECK(bad.out.empty());
  CHECK(run_cmx({"topo-expand", write_temp_file("", ".obj")}).exit_code == 3);  // unknown format

  // Two tets sharing only vertex 0: read fine, but not a manifold.
  const auto pinched = write_temp_file(
      "MeshVersionFormatted 1\nDimension 3\nVertices\n7\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n-1 0 0 0\n0 -1 "
      "0 0\n0 0 -1 0\n"
      "Tetrahedra\n2\n1 2 3 4 0\n1 5 7 6 0\nEnd\n",
      ".mesh");
  const auto r = run_cmx({"topo-expand", pinched, "--json"});
  CHECK(r.exit_code == 4);
  CHECK(json_has(r.err, "is not a ball: vertex 0"));
  CHECK(r.out.empty());
  // Tets listed with inconsistent orientation across their common face: not a ball (combinatorial check).
  const auto twisted = write_temp_file(
      "# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 5 double\n0 0 0\n1 0 0\n0 1 "
      "0\n0 0 1\n1 1 1\n"
      "CELLS 2 10\n4 0 1 2 3\n4 1 3 2 4\nCELL_TYPES 2\n10\n10\n",
      ".vtk");
  const auto t = run_cmx({"topo-expand", twisted});
  CHECK(t.exit_code == 4);
  CHECK(json_has(t.err, "must be opposite"));
}
