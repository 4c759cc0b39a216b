#pragma once
// LP backends by name, each with what it can do. Built in: "certified" (default) and "exact".
// Optional backends register themselves through an explicit call from their own target (e.g.
// register_glpk_backend() in cmx_lp_glpk), so the core never links them and static linking never
// drops a registration. Callers branch on a backend's capabilities, never on its name.
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "lp/lp_problem.hpp"

namespace cmx::lp {

using SolveFunction = Solution (*)(const Problem&);

// What a backend can do, beyond solving exactly.
struct BackendCapabilities {
  // It solves in floats and certifies the float basis exactly. The method's float shortcuts
  // (guessing a cone's kernel from the float simplex, placing at a float centre checked exactly)
  // are the same idea and are taken only with such a backend; a reference backend (exact, glpk)
  // must answer every LP itself so that runs compare it.
  bool certifies_float_basis = false;
};

inline constexpr std::string_view default_backend = "certified";

// Adds or replaces a backend. Thread-unsafe: register before solving from several threads.
void register_backend(std::string_view name, SolveFunction solve, BackendCapabilities capabilities = {});
// The backend called `name`, or nullptr.
SolveFunction find_backend(std::string_view name);
// The capabilities of the backend called `name`; throws std::invalid_argument for an unknown name.
BackendCapabilities backend_capabilities(std::string_view name);
std::vector<std::string> backend_names();

// Solves p with the named backend; throws std::invalid_argument for an unknown name.
Solution solve(const Problem& p, std::string_view backend = default_backend);

// Thrown by a backend that cannot represent a problem exactly (e.g. GLPK with integers >= 2^53).
struct UnsupportedProblem : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace cmx::lp
