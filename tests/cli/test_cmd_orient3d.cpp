// cmx orient3d end to end: known answers from a file and from stdin, a malformed line, policies,
// the demo, and usage errors.
#include <doctest/doctest.h>

#include "run_cmx.hpp"

using cmx::test::run_cmx;

namespace {
// Known answers: unit tet (+), its mirror (-), coplanar (0), exact decimals and fractions that no
// double represents (0.1 + 0.2 = 0.3 exactly in this syntax), a hexfloat, and a Kettner witness.
const char* known =
    "# a b c d, one quadruple per line\n"
    "0 0 0  1 0 0  0 1 0  0 0 1\n"
    "0 0 0  0 1 0  1 0 0  0 0 1\n"
    "\n"
    "0 0 0  1 0 0  0 1 0  3 -2 0   # in the plane z = 0\n"
    "0.1 0.2 0.3  1 0 0  0 1 0  0.1 0.2 0.3000000000000000000001\n"
    "1/3 1/3 1/3  1 0 0  0 1 0  0 0 1\n"
    "0x1p-1 0 0  1 0 0  0 1 0  0 0 0x1.8p0\n"
    "-233.33333333333334 50.93333333333333 0 200 49.200000000000003 0 166.66666666666669 49.333333333333336 0 0 0 1\n";
const char* known_answers = "+\n-\n0\n+\n0\n+\n+\n";
}  // namespace

TEST_CASE("cmx orient3d answers a file of known cases under every exact policy") {
  const std::string file = cmx::test::write_temp_file(known);
  for (const char* filter : {"cascade", "interval", "exact", "mpfr:64"}) {
    const auto r = run_cmx({"orient3d", "--filter", filter, file});
    CHECK_MESSAGE(r.exit_code == 0, filter, " ", r.err);
    CHECK_MESSAGE(r.out == known_answers, filter);
    CHECK(r.err.empty());
  }
  const auto r = run_cmx({"orient3d"}, known);  // stdin
  CHECK(r.exit_code == 0);
  CHECK(r.out == known_answers);
}

TEST_CASE("a malformed line gets an error naming it, no output, and exit status 3 at the end") {
  const std::string input =
      "0 0 0 1 0 0 0 1 0 0 0 1\n"
      "0 0 0 1 0 0 0 1 0\n"           // line 2: 9 numbers
      "0 0 0 1 0 0 0 1 0 0 0 abc\n"   // line 3: bad number
      "0 0 0 1 0 0 0 1 0 0 0 1/0\n"   // line 4: zero denominator
      "0 0 0 0 1 0 1 0 0 0 0 1\n";    // still answered
  const auto r = run_cmx({"orient3d"}, input);
  CHECK(r.exit_code == 3);
  CHECK(r.out == "+\n-\n");
  CHECK(r.err.find("line 2: expected 12 numbers, got 9") != std::string::npos);
  CHECK(r.err.find("line 3: number 12:") != std::string::npos);
  CHECK(r.err.find("line 4: number 12:") != std::string::npos);
}

TEST_CASE("naive doubles are wrong on the demo case and --demo shows it") {
  const std::string witness =
      "-233.33333333333334 50.93333333333333 0 200 49.200000000000003 0 166.66666666666669 49.333333333333336 0 0 0 1\n";
  // As exact decimals the cascade answers for the decimals; the demo uses the nearest doubles.
  const auto d = run_cmx({"orient3d", "--demo"});
  CHECK(d.exit_code == 0);
  CHECK(d.out.find("naive double : -   <- wrong") != std::string::npos);
  CHECK(d.out.find("exact cascade: +") != std::string::npos);
  CHECK(run_cmx({"orient3d", "--filter", "naive"}, witness).exit_code == 0);
}

TEST_CASE("--stats reports the deciding tiers and usage errors exit 2") {
  const auto r = run_cmx({"orient3d", "--stats"}, known);
  CHECK(r.exit_code == 0);
  CHECK(r.err.find("semi-static") != std::string::npos);
  CHECK(r.err.find("exact") != std::string::npos);
  CHECK(run_cmx({"orient3d", "--filter", "fast"}).exit_code == 2);
  CHECK(run_cmx({"orient3d", "--filter"}).exit_code == 2);
  CHECK(run_cmx({"orient3d", "--bogus"}).exit_code == 2);
  CHECK(run_cmx({"orient3d", "/nonexistent/file"}).exit_code == 3);
  const auto h = run_cmx({"orient3d", "--help"});
  CHECK(h.exit_code == 0);
  CHECK(h.out.find("usage: cmx orient3d") != std::string::npos);
}
