#pragma once
// Orienting a tet complex given only combinatorially (a facet list, io/read_facets.hpp): the
// vertex order of each tet is changed so that every interior face is listed in opposite cyclic
// orders by its two tets (topology/tet_mesh.hpp's tet_face), which is what "positively oriented
// in some embedding" asks of the combinatorics. The global sign is the first live tet's as given
// (a realisation may need the mirror image: swap two coordinates). Needs no coordinates.
#include <cstddef>
#include <string>

#include "topology/tet_mesh.hpp"

namespace cmx::topology {

struct CoherentOrientation {
  bool ok = false;
  std::size_t flipped = 0;  // tets whose vertex order was changed (two vertices swapped)
  std::string message;      // why not, when !ok: a face whose two tets cannot agree
};

// Flips tets of `m` (breadth-first over interior faces, from each face-connected piece's first
// live tet) until every interior face is coherent. Fails, leaving `m` partly flipped, when some
// face cannot be: the complex is not orientable, or a face lies in three or more tets.
CoherentOrientation orient_coherently(TetMesh& m);

}  // namespace cmx::topology
