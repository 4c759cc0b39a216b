#pragma once
// Backend `certified` (the default): float simplex on normalised rows, exact certificate of its
// basis, and only when that fails row generation (tall problems) or the exact simplex
// warm-started from the float basis. The answer is always exact; the float part only decides how
// fast it comes.
#include <cstddef>

#include "lp/lp_problem.hpp"

namespace cmx::lp {

// Row generation (row_generation.hpp) is tried when the float basis fails its certificate on a
// problem of at least this many rows; SIZE_MAX turns it off (the benchmark's comparison).
inline constexpr std::size_t row_generation_from = 24;
Solution certified_solve(const Problem& p);
Solution certified_solve(const Problem& p, std::size_t row_generation_from_rows);

}  // namespace cmx::lp
