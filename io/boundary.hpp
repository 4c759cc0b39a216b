#pragma once
// Prescribed boundary positions: the `index x y z` text files of the Shrink-and-Expand convention
// (a strict superset: every coordinate may be an integer, a decimal, p/q or a hexfloat, all read
// exactly), or a codomain mesh with the domain's connectivity (the Galaxy Maps / FoF convention).
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "io/tet_mesh_data.hpp"

namespace cmx::io {

// Positions for some vertices, in file order.
struct BoundaryPositions {
  std::vector<std::uint32_t> vertices;
  std::vector<Point3> positions;  // positions[i] belongs to vertices[i]
};

// Reads `index x y z` lines. Blank lines and '#' comments are skipped. Errors (IoError with
// file:line): wrong field count, a non-integer or negative index, index >= vertex_count, an index
// given twice, a coordinate that is not an exact number (NaN, inf: not_finite).
BoundaryPositions parse_boundary_positions(std::string_view bytes, const std::string& name, std::size_t vertex_count);
BoundaryPositions read_boundary_positions(const std::string& path, std::size_t vertex_count);

// The boundary of a tet mesh: faces in exactly one tet, oriented so that the tet lies on the
// negative side (outward normals for positively oriented tets), sorted; and their vertices,
// sorted. Throws IoError(mismatch, `name`) when a face belongs to more than two tets.
struct MeshBoundary {
  std::vector<std::array<std::uint32_t, 3>> faces;
  std::vector<std::uint32_t> vertices;
};
MeshBoundary mesh_boundary(const TetMeshData& mesh, const std::string& name = "mesh");

// Takes the positions of the domain's boundary vertices from `codomain`, which must have the same
// vertex count and, tet by tet, the same vertex sets (vertex order within a tet may differ, so a
// flip during orientation normalisation does not matter). Interior codomain positions are
// ignored (they may fold). Throws IoError(mismatch) naming `codomain_name` otherwise.
BoundaryPositions read_boundary_positions_from_codomain(const TetMeshData& domain, const TetMeshData& codomain,
                                                        const std::string& codomain_name);
// Reads the codomain from `codomain_path` (with Orientation::keep) and calls the above.
BoundaryPositions read_boundary_positions_from_codomain(const TetMeshData& domain, const std::string& codomain_path);

// Checks that `positions` prescribes exactly the boundary vertices of `domain`; throws
// IoError(mismatch, `name`) naming the first missing or extra vertex.
void check_boundary_coverage(const TetMeshData& domain, const BoundaryPositions& positions, const std::string& name);

}  // namespace cmx::io
