// meshio (Debian python3-meshio) reads back what cmx writes: VTU, VTK, Medit, Gmsh. Skipped when
// python3 or meshio is missing.
#include <doctest/doctest.h>

#include <cstdlib>
#include <string>

#include "io/write_mesh.hpp"
#include "io_test_util.hpp"
#include "skip.hpp"

using namespace cmx::io;
using namespace cmx::io::test;

// The first Python that imports meshio: the one on PATH, else Debian's (a pyenv shim may shadow it).
static std::string meshio_python() {
  for (const char* python : {"python3", "/usr/bin/python3"})
    if (std::system((std::string(python) + " -c 'import meshio' > /dev/null 2>&1").c_str()) == 0) return python;
  return "";
}

TEST_CASE("meshio reads cmx's VTU, VTK, Medit and Gmsh output") {
  const std::string python = meshio_python();
  if (python.empty()) {
    cmx::test::skip("python3 -c 'import meshio' fails");
    return;
  }
  const auto dir = temp_dir();
  const auto mesh = grid_mesh(2);
  // The script checks counts, the tet connectivity and that every point equals the double written.
  const std::string script =
      "import sys, meshio\n"
      "m = meshio.read(sys.argv[1])\n"
      "tets = [c.data for c in m.cells if c.type == 'tetra']\n"
      "assert len(tets) == 1, [c.type for c in m.cells]\n"
      "assert m.points.shape == (27, 3), m.points.shape\n"
      "assert tets[0].shape == (48, 4), tets[0].shape\n"
      "exp = [l.split() for l in open(sys.argv[2])]\n"
      "for i in range(27):\n"
      "    assert all(float(exp[i][k]) == m.points[i][k] for k in range(3)), i\n"
      "for t in range(48):\n"
      "    assert [int(x) for x in exp[27 + t]] == list(tets[0][t]), t\n";
  write_text(dir / "check.py", script);
  std::string expected;
  const auto points = nearest_doubles(mesh.positions);
  for (const auto& p : points) expected += format_double(p[0]) + " " + format_double(p[1]) + " " + format_double(p[2]) + "\n";
  for (const auto& t : mesh.tets)
    expected += std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + " " + std::to_string(t[3]) + "\n";
  write_text(dir / "expected.txt", expected);
  for (const char* ext : {"vtu", "vtk", "mesh", "msh"}) {
    CAPTURE(ext);
    const auto path = dir / (std::string("grid.") + ext);
    write_tet_mesh(path.string(), mesh);
    const std::string command = python + " " + (dir / "check.py").string() + " " + path.string() + " " +
                                (dir / "expected.txt").string() + " > " + (dir / "log.txt").string() + " 2>&1";
    const int status = std::system(command.c_str());
    INFO(slurp(dir / "log.txt"));
    CHECK(status == 0);
  }
}
