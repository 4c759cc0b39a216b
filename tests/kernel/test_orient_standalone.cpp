// The header-only kernel (kernel/orient_standalone.hpp) against the GMP build: the consumer
// cmx_standalone_signs (standalone/signs.cpp), built with Boost's headers only, must print the
// cascade's signs for every quadruple of the differential set, including those only an exact
// tier decides.
#include <doctest/doctest.h>

#include <cstdint>
#include <sstream>
#include <string>

#include "cli/run_cmx.hpp"
#include "kernel/orient.hpp"
#include "orient_quads.hpp"
#include "skip.hpp"

namespace {

char symbol(cmx::Sign s) {
  return s == cmx::Sign::positive ? '+' : s == cmx::Sign::negative ? '-' : '0';
}

constexpr std::uint64_t seed = 20261202;

}  // namespace

TEST_CASE("the header-only kernel, linked without GMP, gives the GMP build's signs on the differential set") {
  const cmx::test::RunResult r = cmx::test::run_program(CMX_STANDALONE_SIGNS, {std::to_string(seed)});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  std::istringstream lines(r.out);
  std::string line;
  cmx::FilterStats stats;
  long cases = 0, differ = 0;
  cmx::test::for_each_differential_quad(seed, [&](const cmx::test::Quad& q) {
    ++cases;
    const cmx::Sign s3 =
        cmx::orient3d(q.a.data(), q.b.data(), q.c.data(), q.d.data(), {cmx::FilterPolicy{}, &stats});
    const cmx::Sign s2 = cmx::orient2d(q.a.data(), q.b.data(), q.c.data(), cmx::PredicateContext::certain());
    if (!std::getline(lines, line) || line != std::string{symbol(s3), symbol(s2)}) ++differ;
  });
  MESSAGE(cases, " quadruples; the GMP build's tiers:\n", stats.report());
  CHECK(differ == 0);
  CHECK(!std::getline(lines, line));  // as many lines as quadruples
  CHECK(stats.exact > 0);             // the set reaches the tier that cpp_int replaces
  CHECK(stats.adaptive[3] > 0);       // and the adaptive stages' last one
}

TEST_CASE("the header-only kernel's consumer has no GMP among its shared libraries") {
  const cmx::test::RunResult r = cmx::test::run_program("/usr/bin/ldd", {CMX_STANDALONE_SIGNS});
  if (r.exit_code == 127) {
    cmx::test::skip("/usr/bin/ldd is absent");
    return;
  }
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("libgmp") == std::string::npos);
  CHECK(r.out.find("libmpfr") == std::string::npos);
}
