#pragma once
// Helpers shared by the public-API suites.
#include <doctest/doctest.h>

#include <string>

#include "cmx/types.hpp"

namespace cmx::test {

// The what() of the cmx::Error that f throws ("" and a failed check when it throws none).
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const cmx::Error& e) {
    return e.what();
  }
  FAIL_CHECK("no cmx::Error thrown");
  return "";
}

}  // namespace cmx::test
