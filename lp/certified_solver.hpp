#pragma once
// Backend `certified` (the default): float simplex on normalised rows, exact certificate of its
// basis, and only when that fails the exact simplex warm-started from the float basis. The answer
// is always exact; the float part only decides how fast it comes.
#include "lp/lp_problem.hpp"

namespace cmx::lp {

Solution certified_solve(const Problem& p);

}  // namespace cmx::lp
