#pragma once
// A mapping problem made by cmx itself for the tests: a generated mesh and its boundary file in a
// fresh directory.
#include <doctest/doctest.h>

#include <string>

#include "run_cmx.hpp"

namespace cmx::test {

struct Case {
  std::string dir, mesh, boundary;  // mesh: dir/domain.vtk, boundary: dir/boundary.txt
};

// `cmx generate-mesh --shape SHAPE --perturb 3`, then `cmx boundary --shape BOUNDARY_SHAPE`.
inline Case make_case(const std::string& shape, const std::string& boundary_shape) {
  Case c;
  c.dir = fresh_directory();
  c.mesh = c.dir + "/domain.vtk";
  c.boundary = c.dir + "/boundary.txt";
  REQUIRE(run_cmx({"generate-mesh", "--shape", shape, "--perturb", "3", "-o", c.mesh, "-q"}).exit_code == 0);
  REQUIRE(run_cmx({"boundary", c.mesh, "--shape", boundary_shape, "-o", c.boundary, "-q"}).exit_code == 0);
  return c;
}

}  // namespace cmx::test
