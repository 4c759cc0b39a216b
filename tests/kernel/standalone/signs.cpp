// cmx_standalone_signs: a consumer of the header-only kernel alone (kernel/orient_standalone.hpp),
// built with Boost's headers and nothing else, no GMP (tests/kernel/CMakeLists.txt). Prints, for
// every quadruple of the differential set of orient_quads.hpp (seed from argv[1]), the sign of
// orient3d and of orient2d on the first three points, as two characters of "+-0", one quadruple
// per line; ../test_orient_standalone.cpp compares them with the GMP build's.
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "kernel/orient_standalone.hpp"
#include "orient_quads.hpp"

namespace {
char symbol(cmx::Sign s) {
  return s == cmx::Sign::positive ? '+' : s == cmx::Sign::negative ? '-' : '0';
}
}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s SEED\n", argv[0]);
    return 2;
  }
  const std::uint64_t seed = std::strtoull(argv[1], nullptr, 10);
  cmx::test::for_each_differential_quad(seed, [](const cmx::test::Quad& q) {
    const char s3 = symbol(cmx::standalone::orient3d(q.a.data(), q.b.data(), q.c.data(), q.d.data()));
    const char s2 = symbol(cmx::standalone::orient2d(q.a.data(), q.b.data(), q.c.data()));
    std::printf("%c%c\n", s3, s2);
  });
  return 0;
}
