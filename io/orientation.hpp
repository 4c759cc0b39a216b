#pragma once
// Combinatorial and geometric checks shared by all readers, applied after parsing.
#include <cstddef>
#include <string>
#include <vector>

#include "io/tet_mesh_data.hpp"

namespace cmx::io {

// Checks that no tet repeats a vertex and that no two tets share a vertex set, then (with
// Orientation::normalise) computes every tet's orientation sign exactly and normalises the mesh
// to det[b-a, c-a, d-a] > 0 (see ReadOptions). `tet_lines[i]` is the line of tet i in `file`
// (used in error messages; may be empty, then errors name the tet index with line 0).
// Throws IoError(degenerate_tet | duplicate | inconsistent_orientation).
void validate_and_orient(TetMeshData& mesh, const ReadOptions& options, const std::string& file,
                         const std::vector<std::size_t>& tet_lines);

// Counts of exact orientation signs, for reports (`cmx info`).
struct OrientationCounts {
  std::size_t positive = 0, negative = 0, zero = 0;
  std::size_t first_negative = SIZE_MAX, first_zero = SIZE_MAX, first_positive = SIZE_MAX;
};
OrientationCounts count_orientations(const TetMeshData& mesh);

}  // namespace cmx::io
