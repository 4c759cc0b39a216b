#include "kernel/coordinate_arith.hpp"

#include <cfloat>
#include <cmath>

#include "arith/rounding.hpp"
#include "kernel/policy_name.hpp"

namespace cmx {

namespace {
constexpr long min_mpfr_bits = 2, max_mpfr_bits = 65536;
constexpr const char* valid_names = "rational, double or mpfr:BITS (BITS in 2..65536)";
}  // namespace

Rational CoordinateArith::round(const Rational& q) const {
  switch (kind) {
    case Kind::rational: return q;
    case Kind::float64: {
      double d = to_double(q);
      if (std::isinf(d)) d = std::copysign(DBL_MAX, d);
      return rational_from_double(d);
    }
    case Kind::mpfr: return round_to_dyadic(q, bits).value();
  }
  return q;
}

HPoint CoordinateArith::round(const HPoint& p) const {
  if (exact()) return p;
  if (kind == Kind::float64 && p.is_double()) return p;
  return HPoint(round(p.coordinate(0)), round(p.coordinate(1)), round(p.coordinate(2)));
}

std::optional<CoordinateArith> parse_coordinate_arith(std::string_view name, std::string* why) {
  using K = CoordinateArith::Kind;
  if (name == "rational") return CoordinateArith{K::rational, 0};
  if (name == "double") return CoordinateArith{K::float64, 53};
  if (name.substr(0, 5) == "mpfr:") {
    if (const auto bits = parse_bounded_integer(name.substr(5), min_mpfr_bits, max_mpfr_bits))
      return CoordinateArith{K::mpfr, unsigned(*bits)};
    if (why) *why = "bad precision in arithmetic '" + std::string(name) + "': expected " + valid_names;
    return std::nullopt;
  }
  if (why) *why = "unknown arithmetic '" + std::string(name) + "': expected " + valid_names;
  return std::nullopt;
}

std::string to_string(const CoordinateArith& arith) {
  switch (arith.kind) {
    case CoordinateArith::Kind::rational: return "rational";
    case CoordinateArith::Kind::float64: return "double";
    case CoordinateArith::Kind::mpfr: return "mpfr:" + std::to_string(arith.bits);
  }
  return "?";
}

}  // namespace cmx
