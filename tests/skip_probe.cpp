// Test cases for the run-time skips of tests/main.cpp, run by tests/check_skips.cmake with the
// environment's CMX_SHARED_DIR naming an absent folder. Never discovered as ctest entries: one
// of them fails on purpose.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>

#include "skip.hpp"

TEST_CASE("probe: skips") { cmx::test::skip("the probe's reason"); }

TEST_CASE("probe: the environment names the shared folder") {
  const char* set = std::getenv("CMX_SHARED_DIR");
  REQUIRE(set != nullptr);
  CHECK(cmx::test::shared_dir() == std::filesystem::path(set));
}

TEST_CASE("probe: skips then fails") {
  cmx::test::skip("the probe's reason");
  FAIL_CHECK("fails on purpose: a failure outweighs a skip");
}

TEST_CASE("probe: looks for shared data") {
  if (!cmx::test::have_shared("data")) return;
  FAIL_CHECK("found shared data in a folder check_skips.cmake made sure is absent");
}
