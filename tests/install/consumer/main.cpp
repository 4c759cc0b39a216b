// A downstream project using the installed cmx through its public API: the version header, the
// exact orientation of a tetrahedron with a rational vertex no double can represent, then the
// checks of checks.hpp. Exit 0 when all hold.
#include <cmx/kernel.hpp>
#include <cmx/version.hpp>
#include <cstdio>
#include <cstring>
#include <exception>

#include "checks.hpp"
#include "contraction_probe.hpp"

int main() {
  std::printf("the consumer's own flags contract a*b - c: %s\n", consumer_flags_contract() ? "yes" : "no");
  const bool version_ok = std::strcmp(cmx::version_string, CMX_PACKAGE_VERSION) == 0 &&
                          cmx::version_major == 0 && cmx::version_minor == 3;
  std::printf("<cmx/version.hpp>: %s, package: %s\n", cmx::version_string, CMX_PACKAGE_VERSION);
  try {
    const cmx::ExactPoint3 a{"0", "0", "0"}, b{"1", "0", "0"}, c{"0", "1", "0"}, d{"1/3", "1/3", "1/3"};
    const int s = cmx::orient3d(a, b, c, d);
    std::printf("orient3d = %c\n", s > 0 ? '+' : s < 0 ? '-' : '0');
    const int failures = (version_ok ? 0 : 1) + check_orient() + check_map();
    std::printf("%s\n", failures == 0 ? "all checks passed" : "CHECKS FAILED");
    return failures == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::printf("exception: %s\n", e.what());
    return 1;
  }
}
