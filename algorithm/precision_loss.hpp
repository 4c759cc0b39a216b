#pragma once
// Where a run with non-exact coordinates (`--arith double|mpfr:BITS`, kernel/coordinate_arith.hpp)
// first lost validity: the rounded coordinates made a tet inverted or degenerate, or the input
// itself is not representable. The run stops there (outcome precision_lost) rather than go on from
// a state whose invariants no longer hold; it never claims a success it has not verified.
#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include "arith/sign.hpp"
#include "kernel/homogeneous_point.hpp"
#include "topology/tet_mesh.hpp"

namespace cmx::algorithm {

struct PrecisionLoss {
  std::size_t step = 0;       // expansions completed before the operation that lost validity
  std::string phase;          // input, shrink, simple, star-shapified, refinement, inflation,
                              // relaxation, bend, smoothing, verification
  std::uint32_t vertex = 0;   // the vertex whose rounded coordinates lost validity
  std::string what;           // one line: what was rounded and what it broke
  std::optional<topology::Tet> tet;  // the first tet that lost validity, when one did
  bool in_source = false;            // that tet is flat or inverted in the source (else target)
  Sign orientation = Sign::zero;     // its orientation after rounding (negative or zero)
  std::array<HPoint, 4> corners;     // its corners' positions (source or target) after rounding
  std::size_t exact_bits = 0;        // bits of the exact position the rounding replaced (0: n/a)

  std::string message() const;
};

// Thrown inside the method, caught by map_to_domain, which returns the loss as an outcome.
class PrecisionLost : public std::runtime_error {
 public:
  explicit PrecisionLost(PrecisionLoss loss);
  const PrecisionLoss& loss() const { return loss_; }
  PrecisionLoss& loss() { return loss_; }

 private:
  PrecisionLoss loss_;
};

}  // namespace cmx::algorithm
