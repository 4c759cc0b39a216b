#include "io/write_facets.hpp"

#include <ostream>

#include "io/atomic_file.hpp"

namespace cmx::io {

void write_facet_list(const std::string& path, const std::vector<Tet>& tets) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "# facet list written by cmx: one tet per line, 0-based vertex ids\n";
    for (const Tet& t : tets) out << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << t[3] << '\n';
  });
}

}  // namespace cmx::io
