#pragma once
// Opening the crowds around the shrink point before rounding to doubles (paper Sec. 4.2.7).
//
// The last expansions leave crowds of interior vertices around p_c, too close together for
// doubles to separate (next to p_c doubles resolve ulp(p_c), about 1e-17 for a p_c near 0.1):
//   - nested crowds: tens of vertices within 1e-283 of p_c inside more within 1e-238, inside
//     more within 1e-194, and so on;
//   - funnels (thin inputs): a thousand or more vertices within 1e-6 of p_c, spread continuously
//     from 1e-42 up.
// The Gauss-Seidel repair (double_output.hpp) moves the vertices of offending tets and their
// neighbours in graph order and opens neither. Two steps here do, each keeping the exact map
// valid:
//   - a crowd separated from the next vertex by a large gap moves as a whole, by a homothety
//     about p_c: a positive scaling keeps every tet inside the crowd positive, so only the tets
//     joining it to the vertices outside need checking (exact);
//   - a funnel opens by sweeps that re-centre its vertices from the outermost inward, each in the
//     kernel of its star: the outer vertices move out first, which gives the next ones room.
#include <cstddef>
#include <vector>

#include "algorithm/embedding.hpp"
#include "algorithm/expansion/placement.hpp"

namespace cmx::algorithm {

// For every gap of at least a factor 8 in the sorted distances of the interior vertices from
// p_c, innermost first: scales the vertices inside the gap about p_c by the largest power of two
// below the gap (bisection on the exponent, each candidate checked exactly) that keeps every tet
// joining them to the vertices outside strictly positive. Returns the homotheties applied.
// Boundary vertices never move. Exact arithmetic only (a scaled position need not be
// representable otherwise): does nothing for another `arith`.
std::size_t scale_crowds(Embedding& e);

// The interior vertices within 2^-10 times the boundary's distance from p_c (the distances as
// in scale_crowds: log2 of the largest coordinate difference).
std::vector<VertexId> crowd_around_center(const Embedding& e);

// log2 of the distance from p_c of the innermost vertex of `crowd` (-infinity when one sits on
// p_c, +infinity for an empty crowd): a sweep that raises it opens the crowd even while the
// doubles' bad tets stay as many.
double innermost_log2_distance(const Embedding& e, const std::vector<VertexId>& crowd);

// One sweep: each vertex of `crowd`, in decreasing distance from p_c (then by id), moves to the
// precision-reduced Chebyshev centre of its star's kernel. Returns the vertices moved; adds the
// LPs solved to `lps`.
std::size_t sweep_crowd(Embedding& e, const std::vector<VertexId>& crowd, const PlacementOptions& options,
                        std::size_t& lps);

}  // namespace cmx::algorithm
