#pragma once
// Helpers of the io tests: temporary files, small meshes, error expectations.
#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "io/io_error.hpp"
#include "io/tet_mesh_data.hpp"
#include "scratch.hpp"

namespace cmx::io::test {

// A fresh directory, unique per call, in the process's scratch directory (scratch.hpp: removed
// at exit).
inline std::filesystem::path temp_dir() {
  return cmx::test::make_unique_directory(cmx::test::scratch_directory(), "io_");
}

inline std::string write_text(const std::filesystem::path& path, const std::string& content) {
  std::ofstream(path, std::ios::binary) << content;
  return path.string();
}

inline std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs f, which must throw IoError of `kind` at `line` (0 = do not check the line); returns it.
inline IoError expect_io_error(const std::function<void()>& f, ErrorKind kind, std::size_t line = 0) {
  try {
    f();
  } catch (const IoError& e) {
    INFO("what(): " << std::string(e.what()));
    CHECK(std::string(kind_name(e.kind())) == std::string(kind_name(kind)));
    if (line) CHECK(e.line() == line);
    CHECK(!e.file().empty());
    return e;
  }
  FAIL("no IoError thrown (expected " << std::string(kind_name(kind)) << ")");
  return IoError(kind, "", 0, "");
}

// Two positive tets sharing the face (0, 1, 2): (0,1,2,3) and (0,2,1,4), with a non-double
// exact coordinate so that exactness is observable.
inline TetMeshData two_tets() {
  TetMeshData m;
  m.positions = {{Rational(0), Rational(0), Rational(0)},
                 {Rational(1), Rational(0), Rational(0)},
                 {Rational(0), Rational(1), Rational(0)},
                 {Rational(1, 3), Rational(1, 3), Rational(1)},
                 {Rational(1, 5), Rational(1, 7), Rational(-2)}};
  m.tets = {{0, 1, 2, 3}, {0, 2, 1, 4}};
  return m;
}

}  // namespace cmx::io::test

#include "kernel/homogeneous_point.hpp"
#include "kernel/orient.hpp"

namespace cmx::io::test {

// An n x n x n grid of cubes, each cut into 6 tets (Freudenthal), coordinates i/3 (not doubles),
// every tet positively oriented.
inline TetMeshData grid_mesh(int n) {
  TetMeshData m;
  const auto id = [n](int i, int j, int k) { return std::uint32_t((i * (n + 1) + j) * (n + 1) + k); };
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) {
        Point3 p{Rational(i, 3), Rational(j, 3), Rational(k, 3)};
        for (auto& c : p) c.canonicalize();  // mpq_class(num, den) does not reduce
        m.positions.push_back(p);
      }
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        for (const auto& p : perms) {
          int c[3] = {i, j, k};
          Tet t;
          t[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[p[s]];
            t[std::size_t(s + 1)] = id(c[0], c[1], c[2]);
          }
          m.tets.push_back(t);
        }
  for (auto& t : m.tets) {
    const auto& P = m.positions;
    const auto h = [&](std::uint32_t v) { return HPoint(P[v][0], P[v][1], P[v][2]); };
    if (orient3d(h(t[0]), h(t[1]), h(t[2]), h(t[3]), PredicateContext::certain()) == Sign::negative)
      std::swap(t[2], t[3]);
  }
  return m;
}

}  // namespace cmx::io::test
