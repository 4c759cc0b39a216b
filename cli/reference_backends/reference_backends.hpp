#pragma once
// The one symbol that differs between the cmx programs, in a header of its own so that the
// backend files compile without CLI11 (cli/CMakeLists.txt).

namespace cmx::cli {

// Registers the reference LP backends this program is linked with: none in `cmx`
// (cli/reference_backends/none.cpp), GLPK in `cmx-glpk` (cli/reference_backends/glpk.cpp).
void register_reference_backends();

}  // namespace cmx::cli
