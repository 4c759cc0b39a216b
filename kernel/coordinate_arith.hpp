#pragma once
// The coordinate arithmetic of a run (`cmx map --arith`): the number system in which every coordinate the method holds must lie.
//
//   rational  (default) exact rationals: nothing is rounded.
//   double    IEEE 754 binary64: every new coordinate is rounded to the nearest double.
//   mpfr:BITS floats of BITS significant bits with an unbounded exponent (MPFR's model; 2..65536):
//             every new coordinate is rounded to nearest, ties to even, as mpfr_set_q does.
//
// Predicates stay exact on the rounded values (for doubles that is what robust predicates on
// doubles compute), so a non-exact run sees its own loss of validity exactly and can report it.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "kernel/homogeneous_point.hpp"

namespace cmx {

struct CoordinateArith {
  enum class Kind : std::uint8_t { rational, float64, mpfr };
  Kind kind = Kind::rational;
  unsigned bits = 0;  // significant bits (53 for float64, BITS for mpfr, 0 for rational)

  bool exact() const { return kind == Kind::rational; }
  // q rounded to the nearest representable value (q itself when exact()). Doubles beyond the
  // largest finite double round to +-DBL_MAX (coordinates inside a domain never get there).
  Rational round(const Rational& q) const;
  HPoint round(const HPoint& p) const;
  bool representable(const HPoint& p) const { return exact() || round(p) == p; }

  friend bool operator==(const CoordinateArith&, const CoordinateArith&) = default;
};

// Parses "rational", "double" or "mpfr:BITS". On failure returns nullopt and, if `why` is given,
// a one-line reason that lists the valid names.
std::optional<CoordinateArith> parse_coordinate_arith(std::string_view name, std::string* why = nullptr);
// The canonical name ("rational", "double", "mpfr:80"); parse_coordinate_arith reads it back.
std::string to_string(const CoordinateArith& arith);

}  // namespace cmx
