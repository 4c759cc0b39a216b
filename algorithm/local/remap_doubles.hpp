#pragma once
// The last stage of `--snap repair` (algorithm/doubles/double_output.hpp): a finished exact map
// whose doubles are still not a valid map is mapped again from its own nearest doubles. They are
// an initial map of its refined mesh whose defects (a crowd of vertices near p_c, closer together
// than doubles resolve there) the local repair (local_repair.hpp) encloses in stars, each mapped
// afresh with a shrink point of its own and well-spread neighbours (docs/algorithm/local.md,
// "Initial maps"; measured in bench/results/map-local-repair.md, "gargoyle_star's doubles").
#include "algorithm/map.hpp"
#include "algorithm/verify/verify_map.hpp"

namespace cmx::algorithm {

// Whether `r` calls for that second pass: an exact run under the repair policy with
// MapOptions::remap_doubles that ended in a map whose doubles were checked and are not valid,
// with the double output not cut by the time limit.
bool wants_remap_from_doubles(const MapOptions& options, const MapResult& r);

// The problem of the second pass: r's output mesh with its source positions, the boundary at r's
// exact target (the prescribed positions, refined), and every vertex starting at the nearest
// double of r's target.
MapProblem problem_from_doubles(const MapResult& r);

// After the re-map's pass number `passes` (1 for the first) gave `again`: adopt it (its doubles
// are valid), go on from its doubles (fewer inverted or flat tets than `fewest_bad`, the fewest
// so far, and fewer than tuning::doubles_remap_passes passes run), or stop (no map, doubles cut
// by the time limit or unchecked, no progress, no pass left).
enum class RemapStep { adopt, go_on, stop };
// Whether the pass `again` is a map whose doubles, checked to the end, leave fewer inverted or
// flat tets than `fewest_bad`: the pass kept when no pass gives valid doubles.
bool improves_on(std::size_t fewest_bad, const MapResult& again);
RemapStep after_remap_pass(std::size_t passes, std::size_t fewest_bad, const MapResult& again);

// Runs the second pass with `options` (init given, no re-map inside it, the time limit replaced
// by what is left of `time_left` seconds, 0 for none), from the doubles of the last pass while
// after_remap_pass says go on, and keeps the pass whose doubles have the fewest inverted or flat
// tets (valid doubles when a pass gives them) when that is fewer than r's, verified against the
// original problem `in`; else `r` stands. Either way r.stats.local.fallback says what
// was done. Throws MapError(internal) when a kept map fails verification.
void remap_from_doubles(const MapOptions& options, const VerificationInput& in, double time_left, MapResult& r);

}  // namespace cmx::algorithm
