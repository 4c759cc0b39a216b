#pragma once
// The mapping method end to end (paper Alg. 1):
//   validate -> preprocess (parsimonious splits, shrink point p_c) -> shrink -> expand the cluster
//   mesh vertex by vertex -> verify exactly, on an independent code path.
// The CLI (`cmx map`) is a thin shell over map_to_domain.
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "algorithm/embedding.hpp"
#include "algorithm/doubles/double_output.hpp"
#include "algorithm/map_error.hpp"
#include "algorithm/expansion/placement.hpp"
#include "algorithm/precision_loss.hpp"
#include "algorithm/verify/verify_map.hpp"
#include "arith/rational.hpp"
#include "kernel/filter_policy.hpp"
#include "kernel/homogeneous_point.hpp"
#include "topology/tet_mesh.hpp"
#include "topology/topological_expansion.hpp"

namespace cmx::algorithm {

// A mapping problem: a ball-topology tet mesh with exact source positions (every tet positively
// oriented) and exact prescribed positions for exactly its boundary vertices.
struct MapProblem {
  std::vector<topology::Tet> tets;
  std::vector<Point3> source;                 // one per vertex
  std::vector<std::uint32_t> boundary_vertices;
  std::vector<Point3> boundary_positions;     // boundary_positions[i] for boundary_vertices[i]
  // For MapOptions::init = given: a target position per vertex (the interior positions of a
  // codomain mesh, or a user's file); empty otherwise.
  std::vector<Point3> initial_target;
};

// Where the target starts (cmx map --init). shrink: every interior vertex at the shrink point and
// the whole cluster expanded (paper Alg. 1). tutte, given: an initial map (a 3D Tutte map, or
// MapProblem::initial_target) whose non-positive tets are enclosed in stars, each star mapped by
// the method of `shrink` as a problem of its own (algorithm/local/local_repair.hpp). automatic:
// tutte, falling back to shrink when the stars would hold more than MapOptions::star_max_share of
// the tets or the initial map cannot be made; and shrink after tutte when the stars' stitched
// doubles are not a valid map (its result kept only if its doubles are valid).
enum class InitialMapKind : std::uint8_t { shrink, tutte, given, automatic };
std::optional<InitialMapKind> parse_initial_map_kind(std::string_view name);
const char* to_string(InitialMapKind kind);

// When the expansion loop star-shapifies by shelling the cone base
// (refinement/shelled_star_shapify.cpp): when_stuck, the fallback, only in a last round once every
// candidate has failed everything else; after_pushes wherever bends and pushes failed; first
// before bends and pushes. The names are those of cmx map --shelled.
enum class ShelledMode : std::uint8_t { when_stuck, after_pushes, first };
std::optional<ShelledMode> parse_shelled_mode(std::string_view name);
std::string_view to_string(ShelledMode m);

// Whether the expansion replays a shelling of the input from the start (paper Sec. 4.3, Alg. 2;
// expansion/shelling_replay.cpp): off, never (a NOBUENOSS ends the run as stuck);
// after_nobuenoss, when the greedy loop ended in a NOBUENOSS and the shelling search found a
// shelling, the run starts again from the shrunk state with until_greedy; until_greedy, from the
// start until topological expansion of the cluster left completes (in the run's order and in the
// same order without its deferral), then the greedy loop, replaying of 8 shellings the plan that
// gets there soonest; full, every step. The names are those of cmx map --replay-shelling.
enum class ReplayMode : std::uint8_t { off, after_nobuenoss, until_greedy, full };
std::optional<ReplayMode> parse_replay_mode(std::string_view name);
std::string_view to_string(ReplayMode m);

// What the progress callback gets. During the expansion: the cluster counts below. In later
// phases ("collapse", "doubles", "verification"): done of total steps (total 0: unknown).
struct MapProgress {
  const char* phase = "expansion";            // expansion, collapse, doubles, verification, shelling search, stars (a
                                              // local repair), replay attempts (after a NOBUENOSS, on threads)
  std::size_t done = 0, total = 0;            // phases other than expansion: steps done / all (0: unknown)
  std::size_t expanded = 0, remaining = 0;    // cluster vertices expanded so far / still left
  std::size_t splits = 0;                     // vertices added so far (preprocessing included)
  std::size_t max_bits = 0;                   // largest coordinate bit size so far
  double seconds = 0;
};

// One row of the precision study (`cmx map --trace`): written after every expansion.
struct TraceRow {
  std::size_t step = 0;              // 1, 2, ... (expansions so far)
  const char* kind = "";             // simple, star-shapified, refinement, inflation, automatic
  std::uint32_t vertex = 0;
  std::size_t cone_rows = 0;         // half-spaces of the cone's LP (0: no LP, automatic)
  const char* lp = "";               // certified, exact-fallback, exact, float-centre (no LP certified), none
  std::size_t bits = 0;              // bits of the new position (largest homogeneous coordinate)
  std::size_t max_bits = 0;          // over every vertex's current target position
  double mean_bits = 0;
  std::size_t added_vertices = 0;    // vertices added so far (preprocessing included)
  std::size_t degenerate_left = 0;   // tets with two or more cluster vertices
  std::size_t cluster_left = 0;
  double seconds = 0;
  std::size_t star = 0;              // 0: the global method; k: the k-th star of a local repair
};

struct MapOptions {
  FilterPolicy filter;                        // predicate arithmetic
  PlacementOptions placement;                 // LP backend, norm, precision reduction, coordinate arith
  topology::ExpansionOrder order;             // priority (default), index, random:SEED
  double time_limit_seconds = 0;              // 0 = none; huge or infinite = none (run_control.hpp)
  bool check = false;                         // assert every invariant after every step (slow)
  bool collapse = true;                       // collapse added vertices when the map stays valid
  bool merge = true;                          // ... and merge them, moving the vertex kept (merge_pass.hpp)
  bool flip_collapse = true;                  // ... and re-cut stars by flips first (flip_collapse.hpp)
  SnapPolicy snap = SnapPolicy::repair;       // double output (algorithm/doubles/double_output.hpp)
  // The repair's last stage: a map whose doubles are still not valid is mapped again from them
  // (algorithm/local/remap_doubles.hpp). Off inside that second pass and for a local repair's
  // stars (their doubles are judged stitched).
  bool remap_doubles = true;
  std::size_t smooth_every = 0;               // Laplacian smoothing period in expansions (0: off)
  bool collapse_refinement = true;            // collapse what each star-shapification added, at once (Sec. 4.2.2)
  ShelledMode shelled = ShelledMode::when_stuck;  // when the loop star-shapifies by shelling
  ReplayMode replay = ReplayMode::after_nobuenoss;  // replay a shelling from the start (Alg. 2)
  std::size_t subclusters = 4;                // largest subcluster expanded at once, 2..4 (Sec. 4.2.5); 0 or 1: off
  std::function<void(const MapProgress&)> progress;  // called now and then (about 5 Hz)
  // Polled between steps of every phase with the phase's name ("expansion", "collapse",
  // "doubles", "shelling search"); once it returns true the run stops exactly as at the time
  // limit (outcome time_limit, or the phase's work undone where the time limit undoes it). For
  // cancelling a run (a signal, a GUI) and for cutting it at a reproducible point.
  std::function<bool(std::string_view phase)> stop;
  // Called after every expansion when set (costs a pass over vertices and tets per row). A local
  // repair calls it after all stars are mapped, star by star, so the rows do not depend on threads.
  std::function<void(const TraceRow&)> trace;
  // Called with the state and the vertex just before the shelling star-shapification tries a
  // cluster vertex on which bends and pushes failed (`shelled`): how the project keeps such
  // states as test data (tests/algorithm/fallback_bases/). Not called in a local repair's stars
  // (they run on threads); a re-map from the doubles (remap_doubles.hpp) passes it on.
  std::function<void(const Embedding&, topology::VertexId)> before_fallback;
  InitialMapKind init = InitialMapKind::shrink;
  // Local repair only: the shares of the tets above which `automatic` gives the stars up for the
  // global method (stars holding more than star_max_share of them; an initial map with more than
  // star_max_defect_share of them inverted or flat, decided before any growth), and how many
  // stars are mapped at once (0: the machine's cores; the output is the same for every count).
  double star_max_share = 0.5;
  double star_max_defect_share = 0.05;        // automatic: defects above this share of the tets fall back at once
  // automatic: above this predicted factorisation cost (multiply-adds) the Tutte map is first
  // solved approximately and given up unfactorised when it folds more than twice
  // star_max_defect_share (algorithm/tuning.hpp, tutte_screen_multiply_adds: 1e10; 0 screens
  // every map). Changes only how soon a map that would be given up anyway is given up.
  double tutte_screen_multiply_adds = 1e10;
  std::size_t threads = 0;
  // A ball given by its tets alone (a facet list): MapProblem::source carries no geometry (any
  // values, one per vertex). The run is a realisation of the complex: no source check (validation,
  // invariants), none of the steps that rely on one (the collapses of added vertices, merges and
  // flips; the local repair, so init is shrink; the doubles re-map); only splits refine the mesh.
  // The verifier proves instead that the output is a subdivision of the input complex
  // (verify/verify_subdivision.hpp, from MapResult::parents).
  bool combinatorial = false;
};

// What a local repair did (InitialMapKind tutte, given, automatic).
struct LocalRepairStatistics {
  const char* init = "shrink";                // the initial map used: shrink, tutte or given
  std::string fallback;                       // automatic: why the global method ran instead ("" if it did not)
  std::size_t inverted = 0, flat = 0;         // tets of the initial map
  std::size_t stars = 0, star_tets_max = 0, tets_in_stars = 0;
  double star_tets_mean = 0, share = 0;       // tets per star; share of the input tets re-mapped
  std::size_t threads = 0;                    // stars mapped at once
  double seconds_init = 0, seconds_classify_grow = 0, seconds_map_stars = 0, seconds_stitch = 0;
};

struct MapStatistics {
  std::size_t input_vertices = 0, input_tets = 0, input_boundary_vertices = 0, input_interior_vertices = 0;
  std::size_t input_rounded = 0;              // input coordinates a non-exact --arith rounded (it maps those)
  bool combinatorial = false;                 // MapOptions::combinatorial: no source geometry
  // Preprocessing splits, by reason (algorithm/problem/preprocess.hpp).
  std::size_t split_topology = 0;             // chord faces/edges: the cluster mesh must be simply connected
  std::size_t split_all_boundary_tet = 0;     // all-boundary tet not positive
  std::size_t split_no_shrink_point = 0;      // one-interior-vertex tet no shrink point could make positive
  std::size_t split_fallback = 0;             // the predecessor's split-every-chord fallback
  std::size_t vertices_after_preprocess = 0, tets_after_preprocess = 0;
  std::size_t degenerate_after_shrink = 0;
  double shrink_radius = 0;                   // radius of the ball around p_c inside every shrink constraint
  double boundary_extent = 0;                 // largest side of the prescribed boundary's bounding box
  // Expansion.
  std::size_t expansions_simple = 0, expansions_star_shapified = 0, expansions_inflated = 0,
              expansions_automatic = 0;
  std::size_t expansions_subcluster = 0;      // vertices expanded as part of a subcluster
  std::size_t subcluster_expansions = 0;      // subclusters expanded (Sec. 4.2.5)
  std::size_t subcluster_candidates = 0;      // subclusters considered (float screen included)
  std::size_t k_manifold[4] = {0, 0, 0, 0};   // expansions of k-manifold-expandable vertices (k=1..3; [0]: other)
  std::size_t pushes = 0;                     // vertices pushed into the cluster (star-shapification)
  std::size_t bends = 0;                      // spoke splits of star-shapification (new expanded vertices)
  // The fallback star-shapification (refinement/shelled_star_shapify.cpp): expansions whose base
  // was shelled onto its witness, and the base edges it split at their midpoints on the way.
  std::size_t shelled_star_shapifications = 0, base_edge_splits = 0;
  std::size_t shelled_pushes = 0;             // the vertices it pushed (counted in pushes too)
  std::size_t shelled_pushes_left = 0;        // of those, not expanded right after v (queued)
  std::size_t relaxations = 0;                // expanded vertices re-centred in their star's kernel
  std::size_t smoothing_moves = 0;            // Laplacian moves kept (paper Sec. 4.2.4)
  std::size_t inflation_splits = 0;
  std::size_t isolated_inflations = 0;        // of those, at a base without edges (inflate_isolated)
  std::size_t collapsed = 0;                  // added vertices collapsed away at the end (merges included)
  std::size_t merged = 0;                     // of those, removed by merges and the collapses they enabled (merge_pass.hpp)
  std::size_t relocating_collapses = 0;       // of those, collapses that moved other added vertices (relocating_collapse.hpp)
  std::size_t flip_collapses = 0;             // of those, collapses made possible by flips (flip_collapse.hpp)
  bool merge_stopped_at_time_limit = false;   // the time limit cut the merges short (all undone)
  // A NOBUENOSS (stuck, no cluster vertex satisfies Eq. (1)) and the first stage of the
  // shelling-based fallback of paper Sec. 4.3 (shelling_fallback.hpp): a shelling of the input.
  bool nobuenoss = false;
  bool shelling_found = false;
  std::size_t shelling_attempts = 0, shelling_best_removed = 0;
  std::size_t shelling_tets = 0, shelling_split_chords = 0;  // the mesh searched: the input, chords split
  bool shelling_replay_completed = false;  // its topological replay by Alg. 2 (shelling_fallback.hpp)
  std::size_t shelling_replay_expansions = 0, shelling_replay_empty_cone_steps = 0;
  // The geometric replay of a shelling (MapOptions::replay, expansion/shelling_replay.cpp).
  struct Replay {
    bool ran = false;
    bool after_nobuenoss = false;  // run again with the replay because the greedy loop met one
    bool handed_over = false;      // until_greedy: the greedy loop took over
    // The last replay's --shelled mode: the run's own, or after_pushes on a retry below.
    ShelledMode shelled = ShelledMode::when_stuck;
    // After a NOBUENOSS, the replays made again with `shelled` raised to after_pushes, one per
    // plan that ended stuck in the run's own mode (ExpansionSettings::raise_shelled).
    std::size_t shelled_retries = 0;
    // The input vertices the plan expanded, in its order (the other planned expansions are of
    // the vertices of its splits).
    std::vector<std::uint32_t> input_vertices;
    std::size_t chord_splits = 0;  // chords split before the shelling
    std::size_t shelling_attempts = 0;
    std::size_t plans = 0;        // plans compared (one per shelling seed that found one)
    std::size_t plans_tried = 0;  // replayed geometrically, the last one reported (best first)
    std::size_t steps = 0;       // of Alg. 2's plan
    // The plan's topological replay: expansions before greedy expansion could take over (steps
    // + 1 when never; 0 when not asked, as for full). The geometric replay asks the same question.
    std::size_t plan_handover = 0;
    std::size_t splits = 0;      // of all-cluster simplices, at p_c (the others change nothing)
    std::size_t expansions = 0;  // planned vertices expanded
    std::size_t drained = 0;     // vertices of the refinement's own expanded after a step
    // drains that gave up with some of them left (tuning::replay_drain_patience)
    std::size_t drains_left = 0;
    // the plan planned again from where it met a step it could not make (tuning::replay_replans)
    std::size_t replans = 0;
  } replay;
  std::size_t refinement_collapses = 0;       // added vertices collapsed right after their refinement
  std::size_t expansion_restarts = 0;         // runaway restarts (expansion/cluster_expansion.hpp)
  // Double output.
  std::size_t chebyshev_moves = 0;            // exact positions changed by the Chebyshev pass
  std::size_t snap_exact_rounds = 0, snap_repaired = 0, snap_rounds = 0;
  std::size_t snap_crowd_scalings = 0, snap_crowd_sweeps = 0;  // decrowd.hpp
  std::size_t snap_boundary_rerounded = 0;    // boundary vertices given a double within 1 ulp, not the nearest
  std::size_t lps = 0, lps_certified = 0, lps_fell_back = 0;
  std::size_t lp_float_guesses = 0;           // cones classified simple by a float LP alone (placed when popped)
  std::size_t placements_float_centre = 0;    // of those, placed at the float centre (no exact LP; placement.hpp)
  std::size_t closed_by_support = 0;          // cones proved closed on their float basis's rows (certified_closed)
  // Output.
  std::size_t output_vertices = 0, output_tets = 0;
  double growth_ratio = 0;                    // output / input vertices (preprocessing included)
  std::size_t max_bits = 0;                   // largest homogeneous coordinate of any target position
  double mean_bits = 0;
  // Times (seconds).
  double seconds_validate = 0, seconds_preprocess = 0, seconds_expand = 0, seconds_collapse = 0, seconds_verify = 0,
         seconds_double = 0, seconds_total = 0;
  double seconds_subcluster_search = 0;       // part of seconds_expand spent looking for subclusters
  double seconds_shelling_search = 0;         // after a NOBUENOSS (shelling_fallback.hpp)
  FilterStats filter;
  LocalRepairStatistics local;
};

// precision_lost: a non-exact --arith (placement.arith) lost validity; MapResult::loss says where.
enum class MapOutcome { success, time_limit, stuck, precision_lost };
const char* to_string(MapOutcome o);

// The snap policy a run applies: MapOptions::snap, except that a non-exact `arith`'s doubles are
// the plain rounding of its coordinates (SnapPolicy::nearest).
SnapPolicy applied_snap_policy(const MapOptions& options);

struct MapResult {
  MapOutcome outcome = MapOutcome::stuck;
  std::string message;                        // why it stopped, for time_limit, stuck, precision_lost
  std::optional<PrecisionLoss> loss;          // filled for precision_lost
  std::vector<topology::Tet> tets;            // output tets (input order, then new ones)
  std::vector<HPoint> source, target;         // one per output vertex; the first input_vertices are the input's
  // MapOptions::combinatorial (empty otherwise): for every vertex ever made, by creation number,
  // the two or three vertices (creation numbers) whose edge or face its split divided
  // (invalid_index three times for an input vertex); and each output vertex's creation number.
  std::vector<std::array<std::uint32_t, 3>> parents;
  std::vector<std::uint32_t> origin;
  HPoint center;                              // the shrink point p_c
  MapStatistics stats;
  MapVerification verification;               // filled on success
  DoubleMap doubles;                          // filled on success: the target as doubles, and their check
};

// Throws MapError for invalid problems (not a ball, boundary mismatch, degenerate or mirrored or
// non-star-shaped boundary, ...); time limit, stuck and precision lost come back as outcomes with
// statistics. With a non-exact placement.arith the input is rounded to it first (the result maps
// and is verified against the rounded input; stats.input_rounded counts the coordinates that
// moved; a rounded input that is no longer a valid problem is a loss in phase "input"), every
// coordinate the method creates is rounded to it, and the double output is the plain rounding
// (--snap nearest) of those coordinates.
MapResult map_to_domain(const MapProblem& problem, const MapOptions& options = {});

}  // namespace cmx::algorithm
