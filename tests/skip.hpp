#pragma once
// Run-time skips for the doctest suites (implemented in tests/main.cpp).
//
// A test case that cannot do what it checks (its data under ../shared, a checker, python3 or a
// build option is absent) calls skip() and returns, or goes on with the part it can do. It is
// then reported as skipped, never as passed: a run of that one test case, as every ctest entry
// is, exits with CMX_TEST_SKIP_CODE, which tests/CMakeLists.txt gives ctest as SKIP_RETURN_CODE;
// a run of several prints each skip and exits 0 when nothing failed. A failure outweighs a skip.
#include <filesystem>
#include <string>

namespace cmx::test {

// Marks the running test case as skipped and says why (printed `SKIPPED: <test case>: <why>`).
void skip(const std::string& why);

// The folder of shared example data and checkers: the environment's CMX_SHARED_DIR when set,
// else the CMX_SHARED_DIR configured in tests/CMakeLists.txt (../shared next to the checkout).
std::filesystem::path shared_dir();

// True when shared_dir() / relative exists; otherwise skips the test case, naming the path.
bool have_shared(const std::filesystem::path& relative);

}  // namespace cmx::test
