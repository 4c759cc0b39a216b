#pragma once
// Non-shellable triangulated 3-balls given by their facets alone, from their published
// definitions, for the tests of balls without a source geometry (cmx map --combinatorial).
//   Rudin's ball (Bull. AMS 64, 1958): a triangulation of a tetrahedron with 14 vertices and 41
//   tets, all vertices on the boundary; its facets with vertices a..n as 0..13, in the listing of
//   Macaulay2's SimplicialComplexes package (rudinBallComplex).
//   Ziegler's ball (Discrete Comput. Geom. 19, 1998, "Shelling polyhedral 3-balls and
//   4-polytopes"): 10 vertices and 21 tets, all on the boundary, as Hachimori's library lists it.
// Vertex order within a tet is as published, not oriented: topology::orient_coherently orients.
#include <array>
#include <cstdint>
#include <vector>

namespace cmx::test {

inline const std::vector<std::array<std::uint32_t, 4>>& rudin_ball() {
  static const std::vector<std::array<std::uint32_t, 4>> facets{
      {10, 11, 12, 13}, {7, 11, 12, 13}, {8, 10, 12, 13}, {5, 9, 12, 13}, {3, 9, 12, 13}, {5, 8, 12, 13},
      {3, 7, 12, 13},   {9, 10, 11, 13}, {1, 9, 11, 13},  {1, 7, 11, 13}, {2, 9, 10, 13}, {4, 8, 10, 13},
      {4, 6, 10, 13},   {2, 6, 10, 13},  {2, 5, 9, 13},   {1, 3, 9, 13},  {4, 5, 8, 13},  {1, 3, 7, 13},
      {6, 10, 11, 12},  {4, 8, 11, 12},  {2, 8, 11, 12},  {4, 7, 11, 12}, {2, 6, 11, 12}, {0, 8, 10, 12},
      {0, 6, 10, 12},   {4, 5, 8, 12},   {0, 2, 8, 12},   {3, 4, 7, 12},  {0, 2, 6, 12},  {5, 9, 10, 11},
      {5, 7, 10, 11},   {3, 7, 10, 11},  {3, 6, 10, 11},  {1, 5, 9, 11},  {1, 5, 7, 11},  {3, 4, 7, 11},
      {2, 3, 6, 11},    {2, 5, 9, 10},   {0, 4, 8, 10},   {0, 4, 6, 10},  {2, 3, 6, 10}};
  return facets;
}

inline const std::vector<std::array<std::uint32_t, 4>>& ziegler_ball() {
  static const std::vector<std::array<std::uint32_t, 4>> facets{
      {0, 1, 2, 3}, {0, 1, 3, 8}, {0, 1, 4, 5}, {0, 3, 7, 8}, {0, 4, 5, 8}, {0, 5, 1, 8}, {0, 7, 4, 8},
      {1, 0, 4, 9}, {1, 2, 0, 9}, {1, 2, 5, 6}, {1, 4, 5, 9}, {1, 5, 6, 9}, {1, 6, 2, 9}, {2, 1, 3, 7},
      {2, 1, 5, 7}, {2, 3, 6, 7}, {2, 5, 6, 7}, {3, 0, 2, 6}, {3, 0, 4, 6}, {3, 0, 7, 4}, {3, 4, 6, 7}};
  return facets;
}

}  // namespace cmx::test
