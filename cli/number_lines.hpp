#pragma once
// Line-oriented numeric input shared by the commands that read one record per line (chebyshev:
// half-spaces, orient3d: quadruples of points): `count` exact numbers per line, in any syntax of
// cmx::parse_rational, blank-separated; blank lines and '#' comments are skipped.
#include <functional>
#include <istream>
#include <span>
#include <string_view>

#include "arith/rational.hpp"

namespace cmx::cli {

// Calls on_line(numbers) for every good line, in order. A malformed line is reported as
// "line N: reason" (`expected` names what a line holds, e.g. "12 numbers") and skipped; the
// remaining lines are still read. Returns false when some line was malformed or the stream failed
// ("read error" reported).
bool read_number_lines(std::istream& in, std::size_t count, std::string_view expected,
                       const std::function<void(std::span<const Rational>)>& on_line);

}  // namespace cmx::cli
