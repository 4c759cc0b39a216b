// Facet lists (io/read_facets.hpp): a ball given only by its tets' vertex ids, in the plain and
// the bracketed spelling, numbered from 0 or 1; every malformation named with its line.
#include <doctest/doctest.h>

#include "io/read_facets.hpp"
#include "io_test_util.hpp"

using namespace cmx;
using namespace cmx::io;
using namespace cmx::io::test;

namespace {
const std::vector<std::array<std::uint32_t, 4>> listed_two{{0, 1, 2, 3}, {1, 2, 3, 4}};
}

TEST_CASE("a plain facet list numbered from 1, with comments, commas and CRLF line ends") {
  const FacetList f = read_facet_list("# two tets\r\n1 2 3 4\r\n\r\n2, 3, 4, 5  # the second\r\n", "two.facets");
  CHECK(f.vertex_count == 5);
  CHECK(f.one_based);
  CHECK(f.tets == listed_two);
  CHECK(f.label.empty());
}

TEST_CASE("a bracketed facet list with a label over several lines, numbered from 0") {
  const FacetList f = read_facet_list("manifold_lex_d3_n5_#1 = [[0,1,2,3],\n  [1,2,3,4]];\n", "two.facets");
  CHECK(f.vertex_count == 5);
  CHECK_FALSE(f.one_based);
  CHECK(f.tets == listed_two);
  CHECK(f.label == "manifold_lex_d3_n5_#1");
  CHECK(read_facet_list("[[1,2,3,4],[2,3,4,5]]", "bare").tets == listed_two);
}

TEST_CASE("malformed facet lists are refused with the kind and the line") {
  const auto read = [](const std::string& s) { return [s] { read_facet_list(s, "bad.facets"); }; };
  expect_io_error(read(""), ErrorKind::truncated);
  expect_io_error(read("1 2 3\n"), ErrorKind::syntax, 1);
  expect_io_error(read("1 2 3 4\n1 2 3 4 5\n"), ErrorKind::count_mismatch, 2);
  expect_io_error(read("1 2 3 x\n"), ErrorKind::syntax, 1);
  expect_io_error(read("1 2 3 -4\n"), ErrorKind::syntax, 1);
  expect_io_error(read("1 2 3 99999999999\n"), ErrorKind::too_large, 1);
  expect_io_error(read("2 3 4 5\n"), ErrorKind::index_out_of_range);           // neither 0 nor 1 first
  expect_io_error(read("0 1 2 3\n1 2 3 5\n"), ErrorKind::count_mismatch);      // 4 is in no tet
  expect_io_error(read("0 1 2 3\n1 2 3 3888888888\n"), ErrorKind::count_mismatch);  // refused unallocated
  expect_io_error(read("0 1 2 2\n"), ErrorKind::degenerate_tet, 1);
  expect_io_error(read("0 1 2 3\n4 1 2 3\n3 2 1 0\n"), ErrorKind::duplicate, 3);
  expect_io_error(read("[[0,1,2,3],\n[1,2,3]]"), ErrorKind::syntax, 2);
  expect_io_error(read("[[0,1,2,3] [1,2,3,4]]"), ErrorKind::syntax, 1);
  expect_io_error(read("[[0,1,2,3],[1,2,3,4]] extra"), ErrorKind::syntax, 1);
  expect_io_error(read("name = [[0,1,2,3],\n\n[1,2,3,4]"), ErrorKind::syntax, 3);
}

TEST_CASE("a bad vertex id is quoted as the token it is, without the line end") {
  const auto message = [](const std::string& s) {
    return std::string(expect_io_error([s] { read_facet_list(s, "bad.facets"); }, ErrorKind::syntax, 1).what());
  };
  CHECK(message("1 2 3 4.5\n").find("found '4.5'") != std::string::npos);  // not "more ids on the line"
  CHECK(message("1 2 3 4x 5\n").find("found '4x'") != std::string::npos);
  CHECK(message("[[0,1,2,3e0]]").find("found '3e0]]'") != std::string::npos);
  CHECK(message("1 2 3 x\n").find("found 'x'") != std::string::npos);
  CHECK(message("1 2 3 -4\r\n").find("found '-4'") != std::string::npos);
}

TEST_CASE("a facet list file that cannot be opened is an open failure naming it") {
  const IoError e = expect_io_error([] { read_facet_list_file("/nonexistent/x.facets"); }, ErrorKind::open_failed);
  CHECK(std::string(e.what()).find("/nonexistent/x.facets") != std::string::npos);
}
