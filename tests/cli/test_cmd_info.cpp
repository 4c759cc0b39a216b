// cmx info and cmx convert, run as a program.
#include <doctest/doctest.h>

#include <filesystem>

#include "run_cmx.hpp"

using cmx::test::run_cmx;
using cmx::test::write_temp_file;

static const char* unit_tet_vtk =
    "# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 5 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n"
    "CELLS 2 10\n4 0 1 2 3\n4 1 3 2 4\nCELL_TYPES 2\n10\n10\n";

TEST_CASE("cmx info --json: counts and ball verdict") {
  const auto path = write_temp_file(unit_tet_vtk, ".vtk");
  const auto r = run_cmx({"info", path, "--json"});
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(r.out.find("\"vertices\": 5") != std::string::npos);
  CHECK(r.out.find("\"tets\": 2") != std::string::npos);
  CHECK(r.out.find("\"boundary_vertices\": 5") != std::string::npos);
  CHECK(r.out.find("\"reason\": ") != std::string::npos);
  // (0,1,2,3) and (1,3,2,4) list their common face in the same order: not a ball as listed
  // (topology), and (0,1,2,3) is positive, (1,3,2,4) negative (geometry).
  CHECK(r.out.find("\"is_ball\": false") != std::string::npos);
  CHECK(r.out.find("must be opposite") != std::string::npos);
  CHECK(r.out.find("\"verdict\": \"inverted tets\", \"inverted\": 1, \"flat\": 0, \"first_inverted\": 1") !=
        std::string::npos);
}

// Two tets on the face (1, 2, 3), listed as a ball is (the face in opposite orders), with the
// fifth vertex where given: across the face (an embedding), on vertex 0's side (the second tet
// inverted) or on the face's plane (flat).
std::string two_tet_ball(const std::string& fifth) {
  return write_temp_file("# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 5 double\n"
                         "0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + fifth + "\nCELLS 2 10\n4 0 1 2 3\n4 1 2 3 4\nCELL_TYPES 2\n10\n10\n",
                         ".vtk");
}

TEST_CASE("cmx info: a ball is a ball whatever its coordinates, and the orientation verdict is separate") {
  for (const auto& [fifth, verdict] : {std::pair{"1 1 1", "consistent"}, std::pair{"0.1 0.1 0.1", "inverted tets"},
                                       std::pair{"0.5 0.5 0", "flat tets"}}) {
    CAPTURE(fifth);
    const std::string path = two_tet_ball(fifth);
    const auto j = run_cmx({"info", path, "--json"});
    INFO(j.out << j.err);
    CHECK(j.exit_code == 0);
    CHECK(j.out.find("\"is_ball\": true") != std::string::npos);
    CHECK(j.out.find("\"verdict\": \"" + std::string(verdict) + "\"") != std::string::npos);
    const auto t = run_cmx({"info", path});
    CHECK(t.out.find("ball: yes (") != std::string::npos);
    CHECK(t.out.find("orientation det[b-a,c-a,d-a]: " + std::string(verdict) + " (") != std::string::npos);
  }
  const auto inverted = run_cmx({"info", two_tet_ball("0.1 0.1 0.1"), "--json"});
  CHECK(inverted.out.find("\"positive\": 1, \"negative\": 1, \"zero\": 0, \"verdict\": \"inverted tets\", "
                          "\"inverted\": 1, \"flat\": 0, \"first_inverted\": 1}") != std::string::npos);
  const auto flat = run_cmx({"info", two_tet_ball("0.5 0.5 0")});
  CHECK(flat.out.find("flat tets (1 positive, 0 negative, 1 zero; first flat: tet 1)") != std::string::npos);
}

TEST_CASE("cmx info on a ball, text output") {
  const auto path = write_temp_file(
      "MeshVersionFormatted 1\nDimension 3\nVertices\n5\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n1 1 1 0\n"
      "Tetrahedra\n2\n1 2 3 4 0\n2 3 4 5 0\nEnd\n",
      ".mesh");
  const auto r = run_cmx({"info", path});
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(r.out.find("ball: yes") != std::string::npos);
  CHECK(r.out.find("Euler characteristic 1 (boundary 2)") != std::string::npos);
}

TEST_CASE("cmx info: read errors exit 3 with file:line") {
  const auto path = write_temp_file("# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 2 double\n0 0 0\n1 x 0\n", ".vtk");
  const auto r = run_cmx({"info", path});
  CHECK(r.exit_code == 3);
  CHECK(r.err.find("cmx info: " + path + ":7: ") == 0);
  CHECK(run_cmx({"info"}).exit_code == 2);
  CHECK(run_cmx({"info", "/nonexistent.vtk"}).exit_code == 3);
}

TEST_CASE("cmx convert: by extension, normalising orientation") {
  const auto dir = std::filesystem::temp_directory_path();
  const auto in = write_temp_file(
      "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\nTetrahedra\n1\n1 3 2 4 0\nEnd\n", ".mesh");
  const auto out = in + ".ovm";
  const auto r = run_cmx({"convert", in, out});
  INFO(r.err);
  CHECK(r.exit_code == 0);
  const auto info = run_cmx({"info", out, "--json"});
  CHECK(info.out.find("\"is_ball\": true") != std::string::npos);
  CHECK(info.out.find("\"positive\": 1") != std::string::npos);
  CHECK(run_cmx({"convert", in, in + ".obj"}).exit_code == 2);
  CHECK(run_cmx({"convert", in + ".missing.vtk", out}).exit_code == 3);
}

TEST_CASE("cmx info on facet lists: oriented first, then counted and checked, with no coordinates") {
  // Four tets around the edge (1, 2), listed in arbitrary vertex orders, numbered from 1.
  const auto path = write_temp_file("octahedron = [[1,2,3,4], [2,1,4,5],\n [1,2,5,6], [6,3,2,1]]\n", ".facets");
  const auto t = run_cmx({"info", path});
  INFO(t.out << t.err);
  CHECK(t.exit_code == 0);
  CHECK(t.out.find("facet list octahedron: ids numbered from 1 (named below from 0") != std::string::npos);
  CHECK(t.out.find("vertices 6, edges 13, faces 12, tets 4") != std::string::npos);
  CHECK(t.out.find("ball: yes (") != std::string::npos);
  CHECK(t.out.find("orientation: the tets can be oriented alike (") != std::string::npos);
  CHECK(t.out.find("bounding box") == std::string::npos);
  const auto j = run_cmx({"info", path, "--json"});
  CHECK(j.out.find("\"facet_list\": true, \"numbered_from\": 1, \"label\": \"octahedron\"") != std::string::npos);
  CHECK(j.out.find("\"is_ball\": true") != std::string::npos);
  CHECK(j.out.find("\"interior_vertices\": 0") != std::string::npos);
  CHECK(j.out.find("\"edge_valence_histogram\": {\"1\": 4, \"2\": 8, \"4\": 1}") != std::string::npos);
  // Any file with --facets; a face in three tets is no ball, and says why.
  const auto three = write_temp_file("0 1 2 3\n0 1 2 4\n0 1 2 5\n", ".txt");
  const auto n = run_cmx({"info", three, "--facets"});
  CHECK(n.exit_code == 0);
  CHECK(n.out.find("ball: no (face (0 1 2) lies in three or more tets)") != std::string::npos);
  // Malformed: exit 3 with file:line.
  const auto bad = write_temp_file("0 1 2 3\n0 1 2\n", ".facets");
  const auto b = run_cmx({"info", bad});
  CHECK(b.exit_code == 3);
  CHECK(b.err.find("cmx info: " + bad + ":2: ") == 0);
}

TEST_CASE("cmx info on Rudin's ball as a facet list: a ball with the published f-vector, every vertex on the boundary") {
  // Rudin's unshellable triangulation of a tetrahedron (Bull. AMS 64, 1958), its 41 facets with
  // vertices a..n as the Macaulay2 SimplicialComplexes package lists them (rudinBallComplex).
  const char* facets =
      "klmn hlmn ikmn fjmn djmn fimn dhmn jkln bjln bhln cjkn eikn egkn cgkn cfjn bdjn efin bdhn gklm eilm cilm "
      "ehlm cglm aikm agkm efim acim dehm acgm fjkl fhkl dhkl dgkl bfjl bfhl dehl cdgl cfjk aeik aegk cdgk";
  std::string list;
  for (const char* p = facets; *p; ++p) {
    if (*p == ' ') {
      list += '\n';
    } else {
      list += std::to_string(*p - 'a' + 1);
      list += p[1] && p[1] != ' ' ? " " : "";
    }
  }
  const auto j = run_cmx({"info", write_temp_file(list + "\n", ".facets"), "--json"});
  INFO(j.out << j.err);
  CHECK(j.exit_code == 0);
  CHECK(j.out.find("\"vertices\": 14, \"edges\": 66, \"faces\": 94, \"tets\": 41") != std::string::npos);
  CHECK(j.out.find("\"is_ball\": true") != std::string::npos);
  CHECK(j.out.find("\"interior_vertices\": 0") != std::string::npos);
  CHECK(j.out.find("\"coherent\": true") != std::string::npos);
}
