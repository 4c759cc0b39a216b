#pragma once
// The source side of the verifier for a ball given by its tets alone (MapOptions::combinatorial):
// with no source geometry, the output must still be a subdivision of the input complex. Every
// input tet is taken as the standard simplex of its four vertices; each output vertex gets exact
// barycentric coordinates over the input vertices, recomputed from the splits that made it (the
// midpoint of its two parents, or the barycentre of its three); then
//   * every output tet lies in one input tet (its vertices' supports span exactly that tet's
//     vertices) and is strictly positive in it (the 4 x 4 determinant of its vertices' coordinates,
//     in the input tet's vertex order), and
//   * the determinants of the output tets inside each input tet sum to exactly 1 (they tile it).
// Positive pieces that fill every input tet exactly, in an output that is a ball, make the output
// a subdivision of the input (the degree argument of verify_map.hpp, tet by tet).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "topology/tet_mesh.hpp"

namespace cmx::algorithm {

// input_tets: the input complex, positively oriented alike (their vertex ids below input_vertices);
// tets: the output; parents: one record per vertex ever made, by creation number (the first
// input_vertices are the input's, invalid_index three times; every other names two or three older
// creation numbers); origin: each output vertex's creation number. Returns "" or the first failure.
std::string verify_subdivision(const std::vector<topology::Tet>& input_tets, std::size_t input_vertices,
                               const std::vector<topology::Tet>& tets,
                               const std::vector<std::array<std::uint32_t, 3>>& parents,
                               const std::vector<std::uint32_t>& origin);

}  // namespace cmx::algorithm
