// A downstream project using the installed cmx: exact orientation of a tetrahedron with a
// rational vertex that no double can represent.
#include <cstdio>

#include "arith/rational.hpp"
#include "kernel/orient_exact.hpp"

int main() {
  cmx::HPoint a, b(1, 0, 0), c(0, 1, 0), d(cmx::Rational(1, 3), cmx::Rational(1, 3), cmx::Rational(1, 3));
  std::printf("orient3d = %c\n", cmx::sign_char(cmx::orient3d_exact(a, b, c, d)));
  return 0;
}
