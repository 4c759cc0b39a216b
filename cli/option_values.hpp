#pragma once
// Strict readers of option values, for add_parsed (cli/command_line.hpp): the whole text must
// be the value (no sign where none belongs, no trailing characters, no wrap-around), or they
// throw std::invalid_argument with what was expected.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace cmx::cli {

// A decimal integer in [min, max].
std::uint64_t parse_integer(std::string_view text, std::uint64_t min, std::uint64_t max);

// A seed: a decimal integer from 0 to 2^64 - 1.
std::uint64_t parse_seed(std::string_view text);

// Seconds of a time limit: a positive number, `inf` (or a number too large for a double) meaning
// no limit, returned as 0, what algorithm::MapOptions takes for none.
double parse_time_limit(std::string_view text);

// A finite number >= 0.
double parse_nonnegative(std::string_view text);

// "a,b,c" -> {"a", "b", "c"}, each one of `known` (empty items are skipped); `what` names an
// item in the message ("format").
std::vector<std::string> parse_list(std::string_view text, const std::vector<std::string>& known, const std::string& what);

}  // namespace cmx::cli
