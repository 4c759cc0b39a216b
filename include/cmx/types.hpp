#pragma once
// Vocabulary of cmx's public API (<cmx/...>): plain value types, so that a public header needs
// nothing but the standard library. Exact numbers cross the API as text: a rational "p/q" or an
// integer "p" in base 10 (what GMP, Python's fractions.Fraction and a .tmap file all read and
// write); a reader accepts the same forms and finite decimals such as "-0.25" or "1e-3".
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace cmx {

using Point3d = std::array<double, 3>;           // a point in doubles
using ExactPoint3 = std::array<std::string, 3>;  // a point with exact rational coordinates, as text
using Tet = std::array<std::uint32_t, 4>;        // vertex indices; positive orientation = right-handed

// Thrown for errors of a caller's input that have no result type to carry them (a file that
// cannot be read, an exact number that does not parse): `what()` names the item and the place.
// Functions that return a status (cmx::map_to_domain) report bad input there instead.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace cmx
