// A downstream project using the installed cmx: exact orientation of a tetrahedron with a
// rational vertex no double can represent, then the checks of checks.hpp. Exit 0 when all hold.
#include <cstdio>
#include <exception>

#include "arith/rational.hpp"
#include "checks.hpp"
#include "contraction_probe.hpp"
#include "kernel/orient_exact.hpp"

int main() {
  std::printf("the consumer's own flags contract a*b - c: %s\n", consumer_flags_contract() ? "yes" : "no");
  cmx::HPoint a, b(1, 0, 0), c(0, 1, 0), d(cmx::Rational(1, 3), cmx::Rational(1, 3), cmx::Rational(1, 3));
  std::printf("orient3d = %c\n", cmx::sign_char(cmx::orient3d_exact(a, b, c, d)));
  try {
    const int failures = check_two_product() + check_orient3d() + check_map();
    std::printf("%s\n", failures == 0 ? "all checks passed" : "CHECKS FAILED");
    return failures == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::printf("exception: %s\n", e.what());
    return 1;
  }
}
