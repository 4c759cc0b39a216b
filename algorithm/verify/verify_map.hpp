#pragma once
// Exact verification of a computed map, on a code path independent of the one that built it:
// plain exact determinants (kernel/orient_exact.hpp, no filter), combinatorics recomputed from the
// output tets alone, and exact rational areas for the boundary.
//
// A map passes when
//   * every output tet is strictly positive in the target and in the source (for a ball given by
//     its tets alone: a subdivision of the input complex, verify_subdivision.hpp);
//   * the first input_vertices output vertices keep their input source positions, and every input
//     boundary vertex sits exactly at its prescribed target position;
//   * the output mesh is a ball (topology::check_ball);
//   * the output boundary refines the input boundary: every output boundary face lies inside one
//     input boundary triangle, with the same orientation, in the target (prescribed positions) and
//     in the source, and the faces inside each input triangle have exactly its area (exact
//     projected areas), so they tile it.
// With all tets positive and the boundary mapped onto the prescribed boundary this way, the map is
// a bijection onto the prescribed domain (degree argument).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "kernel/homogeneous_point.hpp"
#include "topology/tet_mesh.hpp"

namespace cmx::algorithm {

struct MapVerification {
  bool target_positive = false;      // every tet strictly positive in the target
  bool source_positive = false;      // every tet strictly positive in the source
  bool input_kept = false;           // input vertices keep their source positions, boundary its prescribed ones
  bool ball = false;                 // the output is a ball
  bool boundary_refines = false;     // the output boundary tiles the input boundary (source and target)
  std::size_t inverted = 0, degenerate = 0;  // target tets with negative / zero volume
  std::string first_failure;         // empty when everything holds
  bool ok() const { return target_positive && source_positive && input_kept && ball && boundary_refines; }
};

// The input side of the check: the input tets and source positions, and the prescribed positions.
struct VerificationInput {
  const std::vector<topology::Tet>* tets = nullptr;
  const std::vector<HPoint>* source = nullptr;             // input source positions
  const std::vector<std::uint32_t>* boundary_vertices = nullptr;
  const std::vector<HPoint>* boundary_positions = nullptr;  // prescribed, one per boundary vertex
  // A ball given by its tets alone (MapOptions::combinatorial): the source positions carry no
  // geometry. Then the source side of the check is verify_subdivision.hpp on these records
  // (MapResult::parents and origin; source_positive says whether it holds), input source positions are not
  // compared, and the boundary tiling is checked in the target only.
  const std::vector<std::array<std::uint32_t, 3>>* parents = nullptr;
  const std::vector<std::uint32_t>* origin = nullptr;
};

// The orientation the verifier uses (sign of det[b-a, c-a, d-a]): a static double filter of its
// own when every coordinate is a double, else the exact homogeneous determinant. Exact.
Sign verification_orient(const HPoint& a, const HPoint& b, const HPoint& c, const HPoint& d);

MapVerification verify_map(const VerificationInput& input, const std::vector<topology::Tet>& tets,
                           const std::vector<HPoint>& source, const std::vector<HPoint>& target);

// Target-only check of double coordinates: how many tets are inverted / degenerate when the target
// positions are replaced by `doubles` (exact predicates on those doubles).
struct DoubleCheck {
  std::size_t inverted = 0, degenerate = 0;
  bool valid() const { return inverted == 0 && degenerate == 0; }
};
DoubleCheck check_doubles(const std::vector<topology::Tet>& tets, const std::vector<std::array<double, 3>>& doubles);

}  // namespace cmx::algorithm
