#pragma once
// cmx::map_to_domain: a bijective piecewise-linear map of a ball-topology tetrahedral mesh onto a
// star-shaped domain with prescribed boundary positions, by Cluster-Mesh Expansion (the method of
// docs/algorithm.md). The input is plain arrays (libigl style); the output is a refined mesh whose
// exact target has no inverted or flat tet, checked exactly on an independent code path, and its
// doubles, checked exactly too.
//
//   std::vector<cmx::Point3d> V = ...;  std::vector<cmx::Tet> T = ...;
//   std::vector<std::uint32_t> ids = cmx::boundary_vertices(T, V.size());
//   std::vector<cmx::Point3d> P = ...;  // one prescribed position per entry of ids
//   cmx::MapResult r = cmx::map_to_domain(V, T, ids, P);
//   if (!r.ok()) std::cerr << r.message << '\n';
//
// This header includes only the standard library and <cmx/types.hpp>.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cmx/types.hpp"

namespace cmx {

// Where the target starts. automatic (the default): a 3D Tutte map whose defects are repaired in
// small stars, falling back to shrink when the stars would cover too much of the mesh or their
// doubles are not valid (the report's local.fallback says why). shrink: every interior vertex at
// one point, the whole cluster expanded (the paper's Alg. 1). tutte: the Tutte map and its stars,
// no fallback. given: MapOptions::initial_target, one position per input vertex.
enum class InitialMap : std::uint8_t { automatic, shrink, tutte, given };

// What the progress callback gets, about five times a second. phase: "expansion", "collapse",
// "doubles", "verification" or "shelling search". In the expansion, expanded/remaining count
// cluster vertices; in the other phases done of total steps (total 0: unknown).
struct MapProgress {
  std::string_view phase;
  std::size_t done = 0, total = 0;
  std::size_t expanded = 0, remaining = 0;
  std::size_t added_vertices = 0;  // vertices added so far
  std::size_t max_bits = 0;        // largest coordinate bit size so far
  double seconds = 0;
};

// One row of the precision study (`cmx map --trace` writes these as CSV), after every expansion.
struct MapTraceRow {
  std::size_t step = 0;             // 1, 2, ... (expansions so far)
  std::string_view kind;            // simple, star-shapified, refinement, inflation, automatic
  std::uint32_t vertex = 0;         // the vertex expanded
  std::size_t cone_rows = 0;        // half-spaces of its expansion cone's LP (0: no LP)
  std::string_view lp;              // certified, exact-fallback, exact, float-centre, none
  std::size_t bits = 0;             // bits of the new position (largest homogeneous coordinate)
  std::size_t max_bits = 0;         // over every vertex's current target position
  double mean_bits = 0;
  std::size_t added_vertices = 0;   // vertices added so far (preprocessing included)
  std::size_t degenerate_left = 0;  // tets with two or more cluster vertices
  std::size_t cluster_left = 0;     // cluster vertices still to expand
  double seconds = 0;
  std::size_t star = 0;  // 0: the global method; k: the k-th star of a local repair
};

// Options; the defaults are those of `cmx map`. The text-valued fields take the values of the
// `cmx map` option of the same name (`cmx map --help` lists them); a value that does not parse
// makes map_to_domain return MapStatus::invalid_options naming the field.
struct MapOptions {
  InitialMap init = InitialMap::automatic;
  std::vector<ExactPoint3> initial_target;      // init = given: one position per input vertex
  std::vector<Point3d> initial_target_doubles;  // ... or in doubles (used when initial_target is empty)
  double time_limit_seconds = 0;                // 0 or infinite: none; a run over it returns time_limit
  std::size_t threads = 0;      // stars mapped at once (0: the machine's cores); output does not depend on it
  bool collapse = true;         // collapse added vertices where the map stays valid (smaller output)
  bool merge = true;            // ... also merging them into moving neighbours (cmx map --no-merge)
  bool flip_collapse = true;    // ... also after flips of their stars (cmx map --no-flip-collapse)
  bool collapse_refinement = true;  // collapse what each star-shapification added, at once
  // When the expansion loop star-shapifies by shelling the cone base (cmx map --shelled):
  // when-stuck (the fallback: once every candidate has failed everything else), after-pushes
  // (wherever bends and pushes failed), first (before bends and pushes). The last two are for
  // tests and comparisons: they change runs that the default leaves alone, not always for better.
  std::string shelled = "when-stuck";
  // Replay a shelling of the input from the start (paper Sec. 4.3, Alg. 2) instead of expanding
  // greedily (cmx map --replay-shelling): after-nobuenoss (when the greedy run ends in a
  // NOBUENOSS and a shelling is found, the run again with until-greedy); off (never: such a run
  // ends as stuck); until-greedy (until topological expansion of the cluster left completes in the
  // run's order and in that order without its deferral, then the greedy loop in the latter; of 8
  // shellings, the plan that gets there soonest); full (every step). The report's
  // expansion.replay says what was replayed.
  std::string replay_shelling = "after-nobuenoss";
  bool check = false;           // assert every invariant after every step (slow; for debugging)
  std::string snap = "repair";  // doubles written: repair, chebyshev, nearest
  std::string order = "priority";  // expansion order: priority, index, strict-index, random:SEED[,defer:A-B]
  std::string filter = "cascade";    // predicate arithmetic: cascade, interval, exact, mpfr:BITS
  std::string lp = "certified";      // LP backend of the placements: certified, exact
  std::string norm = "l2-upper";     // Chebyshev row weights: l2-upper, l1
  std::string precision = "dyadic";  // precision reduction of new positions (cmx map --precision)
  std::string arith = "rational";    // coordinate arithmetic: rational (exact), double, mpfr:BITS
  std::size_t subclusters = 4;       // largest subcluster expanded at once, 2..4 (0 or 1: off)
  std::size_t smooth = 0;            // Laplacian smoothing period in expansions (0: off)
  // A ball given by its tets alone (cmx map --combinatorial): the vertices' positions are ignored
  // (give any, one per vertex) and the tets need only be oriented alike. The result realises a
  // subdivision of the complex: every tet positive in the target, the boundary as prescribed, and
  // exact_valid includes an exact check that the output subdivides the input complex (barycentric
  // coordinates from the splits). MapResult::source and source_exact are then the target (there is
  // no source geometry). init, collapse, merge, flip_collapse and collapse_refinement are ignored:
  // only splits refine the mesh.
  bool combinatorial = false;
  // Called now and then during the run, on the calling thread.
  std::function<void(const MapProgress&)> progress;
  // Polled between steps; once it returns true the run stops at the next step and returns
  // MapStatus::cancelled (a signal handler's flag, a GUI's cancel button).
  std::function<bool()> stop;
  // Called after every expansion, on the calling thread (stars mapped in parallel report theirs
  // in star order once mapped); the views are valid during the call only.
  std::function<void(const MapTraceRow&)> trace;
};

// How a run ended. Bad input is a status, not an exception: exceptions are kept for programming
// errors (std::bad_alloc, a callback that throws).
enum class MapStatus : std::uint8_t {
  success,          // exact target verified (MapResult::exact_valid); the doubles may still be invalid
  invalid_input,    // not a ball, bad index, NaN, boundary not star-shaped, degenerate, ...: see message
  invalid_options,  // an option value that does not parse or is out of range: see message
  time_limit,       // MapOptions::time_limit_seconds reached
  cancelled,        // MapOptions::stop returned true
  stuck,            // no cluster vertex could be expanded (message says which case)
  precision_lost,   // a non-exact `arith` lost validity (message says where)
};
const char* to_string(MapStatus status);

// The headline figures of a run (`cmx map` prints these); report_json has every statistic.
struct MapStatistics {
  std::size_t input_vertices = 0, input_tets = 0;
  std::size_t output_vertices = 0, output_tets = 0;
  double growth_ratio = 0;                // output tets / input tets
  std::size_t rounded_coordinates = 0;    // input coordinates rounded (a non-exact `arith` only)
  std::size_t preprocess_splits = 0;      // tets split before the shrink (paper Sec. 4.1)
  std::size_t expansions_simple = 0;      // cluster vertices expanded by one LP (Sec. 4.2.1)
  std::size_t expansions_subcluster = 0;  // ... expanded together in subclusters
  std::size_t subclusters_expanded = 0;   // those subclusters
  std::size_t expansions_star_shapified = 0, pushes = 0;  // after star-shapification (Sec. 4.2.2)
  std::size_t expansions_inflated = 0;    // after an inflation (Sec. 4.2.3)
  std::size_t expansions_automatic = 0;   // with a forced position (a single candidate)
  std::size_t max_bits = 0;               // largest homogeneous coordinate of the exact target
  bool double_checked = false;            // the doubles were checked (snap is not none)
  bool double_repair_stopped = false;     // the double repair stopped at the time limit
  double seconds_total = 0;
};

// One top-level field of the report: its key and its value as JSON text.
struct ReportField {
  std::string key;
  std::string json;
};

struct MapResult {
  MapStatus status = MapStatus::invalid_input;
  std::string message;  // why, when status != success; "" on success
  // invalid_input only: which check failed, a stable name: invalid_input (sizes, indices, NaN,
  // text that is not a number), not_ball, boundary_mismatch (positions not for exactly the
  // boundary vertices), source_not_positive, degenerate_boundary, boundary_orientation (mirrored),
  // not_star_shaped. Otherwise to_string(status).
  std::string reason;
  // The output mesh (filled on success): the input's vertices first, in input order, then the
  // vertices the method added; tets positively oriented in both source and target.
  std::vector<Tet> tets;
  std::vector<ExactPoint3> source_exact;  // source positions (added vertices lie inside input tets)
  std::vector<ExactPoint3> target_exact;  // the exact map
  std::vector<std::array<std::string, 4>>
      target_homogeneous;       // the same as integers x y z w (point x/w, y/w, z/w), w > 0
  std::vector<Point3d> source;  // source positions rounded to nearest
  std::vector<Point3d> target;  // target doubles (MapOptions::snap), checked exactly
  std::size_t input_vertices = 0;
  // Verdicts of the independent checks: every target tet positive in exact arithmetic, the
  // boundary kept, the output a refinement of the input; and the same for `target` as doubles.
  bool exact_valid = false;
  bool double_valid = false;
  std::size_t double_inverted = 0, double_flat = 0;  // tets of `target` that are not positive
  // Statistics and timings as a JSON object (the `cmx map --report` fields but the options):
  // input, local, preprocess, expansion, double_output, output, bits, seconds, predicates,
  // verdict, precision_loss. Filled whenever the run got past input validation.
  std::string report_json;
  // The same fields but status, reason and message, in the same order, for callers that build a
  // report of their own around them (`cmx map --report` adds its inputs and options).
  std::vector<ReportField> report_fields;
  MapStatistics statistics;  // filled whenever report_fields are
  bool ok() const { return status == MapStatus::success; }
};

// Maps `vertices`/`tets` (a ball, every tet positively oriented, no unused vertex) onto the domain
// whose boundary puts boundary_ids[i] at boundary_positions[i]; boundary_ids must be exactly the
// boundary vertices (see boundary_vertices), in any order. The positions are taken exactly as
// given (doubles are exact rationals). Preconditions: boundary_ids.size() ==
// boundary_positions.size(). Errors of the input come back as MapStatus::invalid_input with a
// message naming the vertex, tet or face. Time: typically near-linear in the tets for Tutte-
// friendly targets; a whole-cluster expansion is super-linear (see bench/RESULTS.md).
MapResult map_to_domain(std::span<const Point3d> vertices, std::span<const Tet> tets,
                        std::span<const std::uint32_t> boundary_ids,
                        std::span<const Point3d> boundary_positions, const MapOptions& options = {});
// The same with exact input (each coordinate "p/q", "p" or a finite decimal; a coordinate that
// does not parse is invalid_input naming it).
MapResult map_to_domain(std::span<const ExactPoint3> vertices, std::span<const Tet> tets,
                        std::span<const std::uint32_t> boundary_ids,
                        std::span<const ExactPoint3> boundary_positions, const MapOptions& options = {});
// The same on raw arrays: vertices holds 3 * vertex_count doubles, tets 4 * tet_count indices,
// boundary_positions 3 * boundary_count doubles.
MapResult map_to_domain(const double* vertices, std::size_t vertex_count, const std::uint32_t* tets,
                        std::size_t tet_count, const std::uint32_t* boundary_ids,
                        const double* boundary_positions, std::size_t boundary_count,
                        const MapOptions& options = {});

// The boundary vertices of a tet mesh (vertices of faces in exactly one tet), ascending. Throws
// cmx::Error when a tet names a vertex >= vertex_count. O(tets log tets).
std::vector<std::uint32_t> boundary_vertices(std::span<const Tet> tets, std::size_t vertex_count);

// Prescribed boundary positions of a generated star-shaped domain (`cmx map --shape`): shape is
// tet, stiff-tet, sphere, star or star:SEED, as `cmx map --help` lists; corners is "random" (the
// tetrahedron's corners go to drawn boundary vertices) or "farthest" (to the ends of the longest
// protrusion or tunnel, as `cmx boundary --corners farthest`: a boundary for thin fingers and
// knotted tunnels where drawn corners find none). Throws cmx::Error when the shape or the corner
// choice does not parse, or no valid boundary could be generated for this mesh (the message says
// why).
struct ShapeBoundary {
  std::vector<std::uint32_t> ids;  // boundary vertices, ascending
  std::vector<Point3d> positions;  // one per id
};
ShapeBoundary boundary_for_shape(std::span<const Point3d> vertices, std::span<const Tet> tets,
                                 std::string_view shape, std::string_view corners = "random");

}  // namespace cmx
