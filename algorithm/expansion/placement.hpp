#pragma once
// Choosing a new position inside an expansion cone: the Chebyshev centre of the cone's kernel
// (lp/chebyshev_center.hpp), then the precision-reduction policy (paper
// Sec. 4.2.3) for a point with fewer bits that is still certified strictly inside.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "algorithm/expansion/expansion_cone.hpp"
#include "kernel/coordinate_arith.hpp"
#include "lp/chebyshev_center.hpp"

namespace cmx::algorithm {

// none    : the exact Chebyshev centre;
// dyadic  : the centre rounded to k-bit dyadics, k = 1, 2, 4, ... (lp::few_bits_by_dyadics);
// shift   : Shrink-and-Expand's right-shift bisection (lp::few_bits_by_shift);
// segment : dyadic points p_c + t (w - p_c), t = 1/2, 1/4, ..., toward a witness vertex w when
//           the expansion has one (star-shapified cones), else as dyadic (paper Sec. 4.2.3).
enum class PrecisionPolicy : std::uint8_t { none, dyadic, shift, segment };
std::optional<PrecisionPolicy> parse_precision_policy(std::string_view name);
std::string_view to_string(PrecisionPolicy p);

struct PlacementOptions {
  lp::ChebyshevOptions lp;
  PrecisionPolicy precision = PrecisionPolicy::dyadic;
  // Coordinates of a non-exact run (--arith): the chosen point is rounded to it; if the rounding
  // leaves the cone, the rounded Chebyshev centre is tried; if that leaves it too, the rounded
  // point is returned anyway, flagged: a float program would move there, and the caller reports
  // the validity it loses.
  CoordinateArith arith;
};

struct Placement {
  lp::ChebyshevStatus status = lp::ChebyshevStatus::infeasible;
  HPoint position;                        // valid when status == interior
  std::size_t centre_bits = 0, bits = 0;  // bits of the centre and of the position (max coordinate)
  std::size_t rows = 0;                   // half-spaces of the LP (the cone's constraints)
  std::size_t unrounded_bits = 0;         // bits of the position before rounding to a non-exact arith
  bool rounded_outside = false;           // that rounding left the cone (validity will be lost)
  bool at_float_centre = false;           // the float simplex's centre, checked exactly: no LP solved
  lp::SolveInfo info;                     // the LP behind it (empty when at_float_centre)
  bool ok() const { return status == lp::ChebyshevStatus::interior; }
};

// Whether the float shortcuts below may answer for the LP: only when the backend itself solves in
// floats and certifies (lp::BackendCapabilities); a reference backend answers every LP. Throws
// std::invalid_argument for an unknown backend.
bool takes_float_shortcuts(const PlacementOptions& options);

// What the float simplex alone says about the cone's kernel, for ordering (no certificate,
// cheap); only when takes_float_shortcuts (else `unsure`):
//   open   : radius above tuning::cone_open_radius of the rows' scale: almost surely simply expandable;
//   closed : at most tuning::cone_closed_radius of it: most likely no interior (certified_closed decides);
//   unsure : anything else, and float failures.
enum class ConeGuess : std::uint8_t { open, closed, unsure };
struct FloatConeVerdict {
  ConeGuess guess = ConeGuess::unsure;
  lp::FloatChebyshev lp;
};
FloatConeVerdict guess_cone(const FloatCone& cone, const PlacementOptions& options);

// Exact proof that v's cone has no interior, from a cone guessed closed: the rows of the float
// optimum's basis (at most four) alone already have no common point (proves_no_common_point, a
// Motzkin certificate, kernel/plane.hpp), and the cone has more constraints. False means "not
// proved" (the full cone must be solved).
// Why a proof from the float basis pays: on thick inputs nearly every cone that is not simple is
// closed, and each is re-evaluated several times while it waits in the queue.
bool certified_closed(const Embedding& e, VertexId v, const FloatCone& cone, const lp::FloatChebyshev& guess);

// The quick placement of a cone guessed open, for the dyadic and segment policies
// without witness in an exact run when takes_float_shortcuts: the float Chebyshev centre of the
// float cone, as doubles, when every float row keeps half the float radius from it (the margin
// the dyadic policy keeps from the exact centre) and moving v there leaves every tet of its cone
// positive (exact predicates). No exact LP runs. nullopt: use place_in_cone.
std::optional<Placement> place_at_float_centre(const Embedding& e, VertexId v, const FloatCone& cone,
                                               const PlacementOptions& options);
// Its two halves, for a caller that already has the cone's float LP (the expansion loop keeps the
// centre from classification until the vertex is popped): the float part (applicability, open
// radius, margin), and the exact check of the point.
std::optional<std::array<double, 3>> float_centre(const FloatCone& cone, const lp::FloatChebyshev& guess,
                                                  const PlacementOptions& options);
std::optional<Placement> place_at_point(const Embedding& e, VertexId v, const std::array<double, 3>& centre);

// Solves the cone's Chebyshev LP and reduces precision. `segment_from`/`segment_to` (optional)
// give the segment of the segment policy (p_c and the witness).
Placement place_in_cone(const ExpansionCone& cone, const PlacementOptions& options,
                        const HPoint* segment_from = nullptr, const HPoint* segment_to = nullptr);

// Moves vertex v to placement p, computed for v's own star, when p is usable: inside the kernel
// (p.ok()), not pushed outside it by a non-exact arith's rounding, and not where v already is.
// True when it moved. Every tet around v stays positive. The one rule for every re-centring.
bool move_to_placement(Embedding& e, VertexId v, const Placement& p);

// Moves expanded vertex v to the precision-reduced Chebyshev centre of its star's kernel; true
// when it moved. Its current position is inside the kernel, so the LP has interior; a failure (a
// degenerate face, which a valid map cannot have) leaves the vertex where it is.
bool recentre(Embedding& e, VertexId v, const PlacementOptions& options);

}  // namespace cmx::algorithm
