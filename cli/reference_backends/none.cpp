// The MIT program `cmx`: no reference backend, so `--lp glpk` is refused with a pointer to cmx-glpk.
#include "cli/common_options.hpp"

namespace cmx::cli {

void register_reference_backends() {}

}  // namespace cmx::cli
