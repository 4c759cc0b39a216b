#pragma once
// The kernel test of a growing star (algorithm/local/stars.hpp, condition (c)): does some point
// see every boundary triangle strictly from inside in the target? The float Chebyshev LP proposes
// the point (the centroid of the boundary when the float LP finds no kernel); exact orientations
// of the triangles against it decide. Only when they reject a point while the float LP found a
// kernel does the exact Chebyshev LP run.
#include <array>
#include <cstddef>
#include <vector>

#include "algorithm/local/stars_growth.hpp"
#include "kernel/homogeneous_point.hpp"
#include "lp/chebyshev_center.hpp"

namespace cmx::algorithm::stars {

struct KernelTest {
  bool star_shaped = false;
  bool exact_lp = false;       // the exact Chebyshev LP ran
  std::size_t violated = 0;    // boundary faces the point does not see strictly from inside, exactly
  // Where to grow when not star-shaped: the violated faces with a tet behind them (indices into
  // GrowingStar::boundary()), worst first: largest signed distance of the point to the wrong side,
  // from the nearest doubles (a triangle degenerate in doubles first of all), ties by tet and
  // face. When every violated face lies on the domain boundary: every face with a tet behind it,
  // in the same order. Empty only when no face of the star has a tet behind it.
  std::vector<std::size_t> grow_across;
};

// `approx`: the nearest doubles of `target`.
KernelTest test_kernel(const GrowingStar& star, const std::vector<HPoint>& target,
                       const std::vector<std::array<double, 3>>& approx, const lp::ChebyshevOptions& lp);

}  // namespace cmx::algorithm::stars
