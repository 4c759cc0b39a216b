// cmx chebyshev: output formats, statuses, backends and error handling, through the binary.
#include <doctest/doctest.h>

#include "run_cmx.hpp"
#include "skip.hpp"

using cmx::test::run_cmx;

namespace {
const char* cube =
    "# the unit cube\n"
    "1 0 0 1\n-1 0 0 0\n\n0 1 0 1.0\n0 -1 0 0\n0 0 1 0x1p0\n0 0 -1 0   # z >= 0\n";

// The JSON object's first key: the version `cmx --version` prints.
std::string version_key() {
  const std::string line = run_cmx({"--version"}).out;  // "cmx VERSION\n"
  return "{\"cmx_version\": \"" + line.substr(4, line.size() - 5) + "\", ";
}
}  // namespace

TEST_CASE("cmx chebyshev --json: the unit cube, every backend") {
  const std::string expected = version_key() +
      "\"status\": \"interior\", \"radius\": \"1/2\", \"center\": [\"1/2\", \"1/2\", \"1/2\"], "
      "\"center_double\": [0.5, 0.5, 0.5]}\n";
  for (const char* lp : {"certified", "exact"}) {
    CAPTURE(lp);
    const auto r = run_cmx({"chebyshev", "--lp", lp, "--json"}, cube);
    CHECK(r.exit_code == 0);
    CHECK(r.out == expected);
  }
  // The MIT program has no GLPK: a clear refusal that names the program which has it.
  const auto r = run_cmx({"chebyshev", "--lp", "glpk", "--json"}, cube);
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("built without GLPK") != std::string::npos);
  CHECK(r.err.find("cmx-glpk") != std::string::npos);
  CHECK(r.out.empty());
}

TEST_CASE("cmx-glpk chebyshev --json: GLPK's answer on the unit cube") {
#ifdef CMX_GLPK_EXE
  const auto r = cmx::test::run_program(CMX_GLPK_EXE, {"chebyshev", "--lp", "glpk", "--json"}, cube);
  CHECK(r.exit_code == 0);
  CHECK(r.out == version_key() +
        "\"status\": \"interior\", \"radius\": \"1/2\", \"center\": [\"1/2\", \"1/2\", \"1/2\"], "
        "\"center_double\": [0.5, 0.5, 0.5]}\n");
#else
  cmx::test::skip("configured without GLPK (CMX_WITH_GLPK=OFF): no cmx-glpk program");
#endif
}

TEST_CASE("cmx chebyshev: text output, file input, l1 norm, statuses") {
  const std::string path = cmx::test::write_temp_file("-1 0 0 0\n0 -1 0 0\n0 0 -1 0\n1 1 1 1\n");
  auto r = run_cmx({"chebyshev", "--norm", "l1", path});
  CHECK(r.exit_code == 0);
  CHECK(r.out ==
        "status: interior\nradius: 1/6\nradius_double: 0.16666666666666666\ncenter: 1/6 1/6 1/6\n"
        "center_double: 0.16666666666666666 0.16666666666666666 0.16666666666666666\n");
  r = run_cmx({"chebyshev", "--json"}, "1 0 0 0\n-1 0 0 -1\n");
  CHECK(r.exit_code == 0);
  CHECK(r.out == version_key() + "\"status\": \"infeasible\", \"radius\": null, \"center\": null, \"center_double\": null}\n");
  r = run_cmx({"chebyshev", "--json"}, "0 0 1 0\n");
  CHECK(r.out == version_key() + "\"status\": \"unbounded\", \"radius\": null, \"center\": null, \"center_double\": null}\n");
  // A single point: x, y, z >= 0 and x + y + z <= 0.
  r = run_cmx({"chebyshev", "--json", "--lp", "exact"}, "-1 0 0 0\n0 -1 0 0\n0 0 -1 0\n1 1 1 0\n");
  CHECK(r.out == version_key() +
        "\"status\": \"empty_interior\", \"radius\": \"0\", \"center\": [\"0\", \"0\", \"0\"], "
        "\"center_double\": [0, 0, 0]}\n");
}

TEST_CASE("cmx chebyshev: malformed input and bad options") {
  auto r = run_cmx({"chebyshev"}, "1 0 0 1\n1 2 3\n0 0 1 1/0\n");
  CHECK(r.exit_code == 3);
  CHECK(r.out.empty());
  CHECK(r.err.find("line 2: expected 4 numbers") != std::string::npos);
  CHECK(r.err.find("line 3: number 4:") != std::string::npos);
  CHECK(run_cmx({"chebyshev", "--lp", "simplex9"}, cube).exit_code == 2);
  CHECK(run_cmx({"chebyshev", "--norm", "linf"}, cube).exit_code == 2);
  CHECK(run_cmx({"chebyshev", "--weight-bits", "99"}, cube).exit_code == 2);
  CHECK(run_cmx({"chebyshev", "--frobnicate"}, cube).exit_code == 2);
  CHECK(run_cmx({"chebyshev", "/nonexistent/file"}).exit_code == 3);
}
