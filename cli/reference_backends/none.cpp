// The MIT program `cmx`: no reference backend, so `--lp glpk` is refused with a pointer to cmx-glpk.
#include "cli/reference_backends/reference_backends.hpp"

namespace cmx::cli {

void register_reference_backends() {}

}  // namespace cmx::cli
