// The reference program `cmx-glpk` (GPL through GLPK; tests and benchmarks, never installed):
// `--lp glpk` selects GLPK's exact simplex.
#include "cli/reference_backends/reference_backends.hpp"
#include "lp/glpk/glpk_backend.hpp"

namespace cmx::cli {

void register_reference_backends() { lp::register_glpk_backend(); }

}  // namespace cmx::cli
