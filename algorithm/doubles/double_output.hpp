#pragma once
// Double-precision output (paper Sec. 4.2.7; snap rounding).
//
// The exact map is always the result; these steps look for IEEE doubles that are a valid map too
// (every tet strictly positive with the target positions replaced by the doubles, decided with
// exact predicates on those doubles):
//   none            : no double work; display formats carry the nearest doubles, unchecked;
//   nearest         : the nearest doubles, checked;
//   chebyshev-pass  : first one Gauss-Seidel pass moving every interior vertex, in increasing id
//                     order, to the precision-reduced Chebyshev centre of its star's kernel (in
//                     the exact map: each move keeps every tet around it positive, so the exact
//                     map stays valid), then nearest;
//   repair          : the nearest doubles when they are valid already; else chebyshev-pass, then
//                     the crowds around p_c opened (decrowd.hpp), then
//                     rounds of exact Gauss-Seidel moves of the interior
//                     vertices of the tets the doubles invert or flatten and of their neighbours
//                     (vertices crowded closer than doubles resolve move apart), then rounds in
//                     which each such vertex is re-centred among its neighbours' *double*
//                     positions: the Chebyshev centre of that star's kernel, rounded to the nearest
//                     double, is taken when it is strictly inside (exact test). Last, outside
//                     this function, map_to_domain maps a map whose doubles are still not valid
//                     again from its own nearest doubles (algorithm/local/remap_doubles.hpp).
// Boundary vertices keep the nearest doubles of their prescribed positions (when a prescribed
// position is not a double the double map's boundary differs from it by that rounding; a tet of
// boundary vertices only that the rounding flattens cannot be repaired).
#include <array>
#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "algorithm/embedding.hpp"
#include "algorithm/expansion/placement.hpp"
#include "algorithm/verify/verify_map.hpp"

namespace cmx::algorithm {

class RunControl;  // run_control.hpp (which includes map.hpp, which includes this header)

enum class SnapPolicy : std::uint8_t { none, nearest, chebyshev_pass, repair };
std::optional<SnapPolicy> parse_snap_policy(std::string_view name);
std::string_view to_string(SnapPolicy p);

// The nearest doubles (round to nearest) of an exact position's three coordinates.
std::array<double, 3> nearest_double(const HPoint& p);

struct ChebyshevPassResult {
  std::size_t moved = 0;  // vertices whose exact position changed
  std::size_t lps = 0;
};

// The Gauss-Seidel pass on the exact map (no cluster vertex left). Vertices with boundary[v] set
// never move.
// Told to stop by `control` (when given), the pass stops: every move made kept the map valid.
ChebyshevPassResult chebyshev_pass(Embedding& e, const PlacementOptions& options, RunControl* control = nullptr);

struct DoubleMap {
  bool checked = false;                       // false for SnapPolicy::none
  std::vector<std::array<double, 3>> target;  // one per vertex
  DoubleCheck check;                          // of `target`, when checked
  std::size_t chebyshev_moves = 0;            // exact positions changed (pass and exact repair rounds)
  std::size_t exact_rounds = 0;               // repair rounds on the exact map
  std::size_t repaired = 0;                   // re-centrings among the doubles (a vertex may count twice)
  std::size_t rounds = 0;                     // repair rounds among the doubles
  std::size_t lps = 0;
  std::size_t crowd_scalings = 0;             // homotheties opening crowds around p_c (decrowd.hpp)
  std::size_t crowd_sweeps = 0;               // outside-in sweeps over the crowd around p_c
  std::size_t boundary_rerounded = 0;         // boundary vertices given a double other than the nearest
  bool stopped_at_deadline = false;           // the time limit cut the repair short (moves undone)
};

// Runs `policy` on the finished exact map `e` (no cluster vertex left) and returns the doubles.
// chebyshev-pass and repair move exact positions, each move inside the kernel of the vertex's
// star, so the exact map stays valid (it is verified after this, independently). Told to stop by
// `control` (the time limit, or the caller's stop hook; phase "doubles"), the pass and the repair
// stop; unless the doubles are valid by then, every move is undone and the result is the plain
// rounding of the exact map as it was (deterministic, unlike the point where the time ran out),
// with stopped_at_deadline set.
DoubleMap make_double_map(Embedding& e, SnapPolicy policy, const PlacementOptions& options,
                          RunControl* control = nullptr);

}  // namespace cmx::algorithm
