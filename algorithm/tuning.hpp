#pragma once
// The method's tuning constants, in one place, each with the reason for its value. None of them
// decides correctness: every geometric decision they steer is certified exactly afterwards, so a
// different value changes speed, refinement or how soon a heuristic gives up, never validity.
// Changing one changes outputs: compare with scripts/compare-cli-outputs.sh.
#include <cstddef>

namespace cmx::algorithm::tuning {

// The Tutte map of --init auto (local/initial_map.hpp) is factorised only when the symbolic
// analysis predicts at most this many multiply-adds per second of half the time limit: the
// factorisation cannot be interrupted, so a time limit of T seconds must not be spent in it past
// T/2. 1e9 per second is below what Eigen's simplicial LDLT reached here (Furch's knotted hole
// at S = 2: 1.17e11 in 55 s), so slower machines still keep to the limit. Without a time limit the
// factorisation always runs. The shared cases need at most 5.2e7 (moai): far below any budget.
inline constexpr double tutte_multiply_adds_per_second = 1e9;

// Above this predicted cost (about 10 s at that rate) --init auto first solves the Tutte system
// approximately by conjugate gradients and gives the map up, without factorising, when that
// approximate map folds more than `tutte_screen_fold_factor` times the share that gives a map up
// (MapOptions::star_max_defect_share) in doubles. The margin keeps the decision the factorised
// map's wherever the two could differ: folds come from the boundary's shape, not from the last
// digits of the solve. Furch's knotted hole at S = 2 (1.17e11, 55 s to factorise) folds 24 % to
// 37 % onto the four generated shapes; the shared cases (at most 5.2e7) are never screened.
// The cost is MapOptions::tutte_screen_multiply_adds (its default is this constant).
inline constexpr double tutte_screen_multiply_adds = 1e10;
inline constexpr double tutte_screen_fold_factor = 2;

// Passes of the re-map from doubles (local/remap_doubles.hpp): each maps again from the last
// pass's doubles while the count of inverted or flat tets falls. Most maps need none, the
// shared cases at most one; the third is a margin, each pass costs about one star map.
inline constexpr std::size_t doubles_remap_passes = 3;

// Refinement budget of one run: beyond max(floor, per_input_vertex x input vertices) vertices the
// loop stops as stuck: a run that refines a mesh fifty-fold has gone astray (growth on real
// meshes is a few percent, bench/RESULTS.md); the floor keeps tiny inputs from stopping early.
inline constexpr std::size_t vertex_budget_floor = 200000;
inline constexpr std::size_t vertex_budget_per_input_vertex = 50;

// The replay of a shelling (expansion/shelling_replay.cpp) stops as run away once the mesh has
// grown by more than per_step x the plan's steps + floor vertices: its refinement can add cluster
// vertices faster than it expands them (before the drain's patience below, a full replay of the
// dunce-hat ball; with the plan's splits made in plan order, 6x6x6 grids and the ball with 6 or
// more collars), and after a NOBUENOSS it runs on its own, possibly without a time limit. Replays
// that complete stay far below (the dunce-hat ball with 32 collars: at most 619 output vertices
// for a bound of about 14,600).
inline constexpr std::size_t replay_growth_per_step = 16;
inline constexpr std::size_t replay_growth_floor = 1024;
// Rounds of the replay's drain without fewer of the refinement's own cluster vertices left before
// it gives up and the plan goes on: on the compact house in a box (replay forced from the start)
// expanding one such vertex left exactly one more, round after round, until the time limit.
inline constexpr std::size_t replay_drain_patience = 8;
// Shelling seeds whose plans until_greedy compares topologically (the one that lets greedy
// expansion take over soonest is replayed): on the dunce-hat ball with 4 collars, seeds 1 to 8
// taken alone mapped 0, 1, 1, 0, 2, 1, 2, 0 of two shapes.
inline constexpr std::size_t replay_plan_seeds = 8;
// Plans replayed geometrically, best first, when the one before failed (each from the state the
// replay started in): with the plan's splits made only when needed, the best plan of the
// dunce-hat ball with 32 collars meets a split vertex it cannot expand and the second maps.
inline constexpr std::size_t replay_plan_attempts = 4;
// Times one replayed plan is planned again from where it met a step it could not make
// (shelling_replay.cpp, replay_shelling): each costs the shelling searches and topological
// replays of replay_plan_seeds plans on the mesh as it then is.
inline constexpr std::size_t replay_replans = 4;

// Smoothing period (expansions) turned on for the attempts after a runaway restart, when the run
// did not ask for smoothing itself: random orders on Freudenthal grids of 4,807 and 6,859
// interior vertices churn until the time limit without it and map with --smooth 10
// (bench/results/issue21-thin-combinatorial.md).
inline constexpr std::size_t restart_smooth_every = 10;

// The float Chebyshev LP of a cone, relative to the rows' scale (expansion/placement.hpp): a
// radius above `cone_open_radius` is a clearly open kernel (then a float centre is worth trying
// before the certified LP); at most `cone_closed_radius` is most likely empty (an exact proof of
// emptiness is tried first). Between the two the cone is `unsure` and the exact LP decides.
inline constexpr double cone_open_radius = 1e-6;
inline constexpr double cone_closed_radius = 1e-11;

// Subcluster screen (expansion/subcluster.cpp): a set of movers is tried exactly only when the
// float LP of the union of their cones sees a kernel this open; lower than cone_open_radius
// because a union that passes saves a star-shapification, so more candidates pay off.
inline constexpr double subcluster_open_radius = 1e-9;

// Rounds of the doubles repair (doubles/double_output.cpp): moves in the exact map first (every
// move is safe there; a crowd that has not opened in 32 rounds does not open with more, the
// crowd passes of doubles/decrowd.hpp do), then among the doubles themselves, where each round
// re-reads every cone.
inline constexpr std::size_t exact_repair_rounds = 32;
inline constexpr std::size_t double_repair_rounds = 16;

// Preprocessing (problem/preprocess.cpp) alternates topological and geometric passes; after this
// many rounds it splits every chord at once (the predecessor's configuration, which ends surely).
inline constexpr int preprocess_rounds_before_split_all = 8;

// Bends of one star-shapification (refinement/local_refinement.cpp, bend_and_expand): each
// blocker is bent at most twice, so two per base vertex, and a few more for blockers of the side
// constraints that are not base vertices; beyond that the bends are undone and pushes are tried.
inline constexpr std::size_t bends_per_base_vertex = 2;
inline constexpr std::size_t bends_beyond_base = 8;

}  // namespace cmx::algorithm::tuning
