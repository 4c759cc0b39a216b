#pragma once
// What a viewer needs beside a map's display mesh (whose points are the target doubles): the
// fields `cmx map` writes into VTU, VTK and Gmsh outputs (io/write_mesh.hpp, write_display_mesh).
//   point vector  source            the source position of each vertex
//   cell uint8    added             1 when the tet has a vertex added by refinement (an index
//                                   >= the input's vertex count), else 0
//   cell double   source_volume     signed volume det[b-a, c-a, d-a] / 6 in the source
//   cell double   target_volume     the same in the target
//   cell double   min_dihedral_deg  the tet's smallest interior dihedral angle in the target,
//                                   in degrees (0 for a flat tet)
// Volumes and angles are computed in doubles from the doubles given: they are for looking at, not
// for deciding validity (a nearly flat tet's rounded volume may have the wrong sign; the exact
// verdict is the map's verification).
#include <cstddef>
#include <vector>

#include "io/write_mesh.hpp"

namespace cmx::io {

// The fields above, in that order. Throws IoError(mismatch) when source and target sizes differ
// and IoError(index_out_of_range) for a tet index beyond them.
DisplayFields map_display_fields(const std::vector<DoublePoint>& source, const std::vector<DoublePoint>& target,
                                 const std::vector<Tet>& tets, std::size_t input_vertex_count);

// det[b-a, c-a, d-a] / 6: positive for the cmx orientation.
double signed_volume(const DoublePoint& a, const DoublePoint& b, const DoublePoint& c, const DoublePoint& d);
// The smallest of the six interior dihedral angles, in degrees; the same for either orientation.
double min_dihedral_angle_deg(const DoublePoint& a, const DoublePoint& b, const DoublePoint& c, const DoublePoint& d);

}  // namespace cmx::io
