// The option names of the method's enumerations parse back to the value that printed them.
#include <doctest/doctest.h>

#include "algorithm/doubles/double_output.hpp"
#include "algorithm/expansion/placement.hpp"
#include "algorithm/option_names.hpp"

using namespace cmx::algorithm;

TEST_CASE("snap and precision policy names round-trip and unknown names are refused") {
  for (SnapPolicy p :
       {SnapPolicy::none, SnapPolicy::nearest, SnapPolicy::chebyshev_pass, SnapPolicy::repair}) {
    CAPTURE(to_string(p));
    CHECK(to_string(p) != "?");
    CHECK(parse_snap_policy(to_string(p)) == p);
  }
  for (PrecisionPolicy p :
       {PrecisionPolicy::none, PrecisionPolicy::dyadic, PrecisionPolicy::shift, PrecisionPolicy::segment}) {
    CAPTURE(to_string(p));
    CHECK(to_string(p) != "?");
    CHECK(parse_precision_policy(to_string(p)) == p);
  }
  CHECK_FALSE(parse_snap_policy("Repair"));
  CHECK_FALSE(parse_snap_policy(""));
  CHECK_FALSE(parse_precision_policy("dyadic "));
}

TEST_CASE("an option-name table answers at compile time") {
  enum class Colour { red, green, blue };
  constexpr OptionNames<Colour, 2> names{{{{Colour::red, "red"}, {Colour::green, "green"}}}};
  static_assert(names.parse("green") == Colour::green);
  static_assert(!names.parse("blue"));
  static_assert(names.name(Colour::red) == "red");
  CHECK(names.name(Colour::blue) == "?");
}
