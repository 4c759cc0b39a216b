#pragma once
// Local repair of an initial map (MapOptions::init tutte, given, automatic).
//
// An initial map (initial_map.hpp) puts every vertex somewhere; its tets are classified exactly
// and the non-positive ones enclosed in stars (stars.hpp): balls of tets whose image boundary is
// star-shaped, every tet outside them positive. Each star is then a mapping problem of its own
// (its tets with their source positions; its boundary vertices prescribed where the initial map
// put them; its interior vertices free) and is solved by map_to_domain with the shrink method.
// Stars share no tet and no moving vertex, so they are mapped independently, several at once,
// and their refined tets replace theirs. The stitched map is verified exactly as a whole by the
// independent verifier: every tet positive and the boundary as prescribed make it bijective
// (docs/algorithm/local.md, "Local repair", gives the degree argument).
//
// Vertices outside the stars keep the initial map's positions, which are doubles for a Tutte map:
// the double output re-rounds only what the stars changed.
#include "algorithm/map.hpp"
#include "algorithm/run_control.hpp"
#include "algorithm/problem/validate_problem.hpp"

namespace cmx::algorithm {

// The local path of map_to_domain for a validated problem, into `r` (whose input statistics the
// caller has filled). false: with InitialMapKind automatic, the global method should run instead
// (r.stats.local.fallback says why). true: `r` is the result, whose outcome may be time_limit or
// stuck (the message names the star) like the global method's. Throws MapError: for an explicit
// initial map that cannot be made (invalid_input), and for a bug (internal).
bool map_locally(const MapProblem& problem, const ValidatedProblem& v, const MapOptions& options, RunControl& control,
                 MapResult& r);

}  // namespace cmx::algorithm
