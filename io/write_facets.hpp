#pragma once
// Writing a ball as a facet list (the plain form io/read_facets.hpp reads): a comment line, then
// one tet per line, four 0-based vertex ids separated by blanks, in the vertex order given (which
// a reader of facet lists does not take as an orientation). Committed atomically
// (io/atomic_file.hpp). Errors: IoError write_failed.
#include <string>
#include <vector>

#include "io/tet_mesh_data.hpp"

namespace cmx::io {

void write_facet_list(const std::string& path, const std::vector<Tet>& tets);

}  // namespace cmx::io
