// The rounding scope: sets upward rounding, restores the caller's mode (also when nested or when
// the caller was not in round-to-nearest), and the opposite trick survives the optimiser.
#include <doctest/doctest.h>

#include <cfenv>
#include <cmath>

#include "arith/interval.hpp"

using namespace cmx;

namespace {
volatile double one = 1.0, tiny = 0x1p-80, three = 3.0, ten = 10.0;
}

namespace {
// The rounding direction double arithmetic actually uses, observed (fegetround may read the x87
// control word, which the scope leaves alone on x86-64).
int observed_mode() {
  const double up = one + tiny, neg = -one - tiny;  // opaque volatile operands
  if (up > 1.0) return FE_UPWARD;
  if (neg < -1.0) return FE_DOWNWARD;
  const double x = one / ten;  // 1/10: to nearest rounds up (to 0.1), toward zero down
  return x == 0.1 ? FE_TONEAREST : FE_TOWARDZERO;
}
}  // namespace

TEST_CASE("UpwardRoundingScope rounds upward inside and restores the previous mode") {
  REQUIRE(std::fegetround() == FE_TONEAREST);
  REQUIRE(observed_mode() == FE_TONEAREST);
  {
    UpwardRoundingScope s;
    CHECK(observed_mode() == FE_UPWARD);
    {
      UpwardRoundingScope nested;
      CHECK(observed_mode() == FE_UPWARD);
    }
    CHECK(observed_mode() == FE_UPWARD);
  }
  CHECK(observed_mode() == FE_TONEAREST);
  CHECK(std::fegetround() == FE_TONEAREST);
  for (int mode : {FE_DOWNWARD, FE_TOWARDZERO, FE_UPWARD}) {
    std::fesetround(mode);
    REQUIRE(observed_mode() == mode);
    {
      UpwardRoundingScope s;
      CHECK(observed_mode() == FE_UPWARD);
    }
    CHECK(observed_mode() == mode);
    CHECK(std::fegetround() == mode);
  }
  std::fesetround(FE_TONEAREST);
  CHECK(observed_mode() == FE_TONEAREST);
}

TEST_CASE("the opposite trick is not folded: lower bounds really round down") {
  // 1 + 2^-80 is not a double: a correct interval is [1, 1 + 2^-52]. If the compiler folded
  // -((-a) - b) into a + b, the lower bound would be rounded up to 1 + 2^-52 and this fails.
  UpwardRoundingScope s;
  const Interval a = opaque(Interval(one)), b = opaque(Interval(tiny));
  const Interval sum = opaque(a + b);
  CHECK(sum.lo == 1.0);
  CHECK(sum.hi == std::nextafter(1.0, 2.0));
  const Interval diff = opaque(a - b);  // 1 - 2^-80: [1 - 2^-53, 1]
  CHECK(diff.lo == std::nextafter(1.0, 0.0));
  CHECK(diff.hi == 1.0);
  const Interval third = opaque(Interval(one) * Interval(1.0 / three));  // 1/3 rounded up then times 1
  CHECK(third.lo == third.hi);
  const Interval prod = opaque(Interval(one + tiny, one + tiny) * Interval(three));
  CHECK(prod.lo < prod.hi);  // 3 (1 + 2^-52) = 3 + 3 * 2^-52 is not a double
  CHECK(prod.lo == 3.0 + 0x1p-51);
  CHECK(prod.hi == 3.0 + 0x1p-50);
}
