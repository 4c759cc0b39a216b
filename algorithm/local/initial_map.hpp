#pragma once
// Initial maps for the local repair: a target position for every vertex, from which the repair
// finds the non-positive tets and re-maps only stars around them (docs/algorithm/local.md, "Initial
// maps"). Eigen solves the Tutte system; it is included only in initial_map.cpp, never here.
#include <array>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "algorithm/map.hpp"  // MapProblem, Point3

namespace cmx::algorithm {

// An initial map: a target position for every vertex of a MapProblem, exact (doubles taken as the
// rationals they are), boundary vertices at their prescribed positions. Tets may be inverted or flat.
struct InitialMap {
  bool ok = false;
  std::vector<Point3> target;  // one per vertex of the problem (empty when not asked for exactly)
  // The same map in doubles (tutte_map only): the solution for interior vertices, the prescribed
  // positions rounded to nearest for boundary vertices. Exactly the doubles nearest to `target`.
  std::vector<std::array<double, 3>> doubles;
  // Why not ok (singular system, non-finite solution, ...). When ok: empty, or a note that
  // given_map set boundary vertices to their prescribed positions.
  std::string message;
  // Not ok because TutteScreen::reject gave a reason (in `message`).
  bool screened_out = false;
  double seconds = 0;        // time to build and solve
  std::size_t interior = 0;  // interior vertices solved for
};

// Uniform-weight 3D Tutte map: every interior vertex at the average of its neighbours (vertices
// sharing an edge), boundary vertices at problem.boundary_positions. Solved in doubles with a
// sparse Cholesky (Eigen); the prescribed positions enter the right-hand side rounded to nearest
// doubles, and the solution doubles are taken exactly. Deterministic.
//
// The system deg(i) x_i - sum_{j interior nbr} x_j = sum_{j boundary nbr} p_j on the interior
// vertices is symmetric positive definite when every interior vertex has a path to a boundary
// vertex; a vertex without one (or in no tet) is named in `message` (ok = false) before any solve.
// Also not ok: boundary lists of different sizes, an index out of range or repeated, a tet
// vertex out of range, a prescribed coordinate beyond the doubles, a failed factorisation or a
// non-finite solution. Interior vertices are numbered in vertex order, edges in sorted order.
// With exact = false only `doubles` is filled: a caller that may reject the map from its doubles
// (cmx map --init auto) then pays for no rational until it keeps the map (exact_target).
// The factorisation cannot be interrupted (no time limit reaches into it), and its cost grows
// much faster than the mesh (fill-in of a 3D Laplacian): when the symbolic analysis predicts more
// than `max_flops` multiply-adds, nothing is factorised and the map is not ok, with the estimate
// in `message`.
//
// `screen` (optional): when the predicted cost is above screen->above_flops, the system is first
// solved approximately by conjugate gradients (relative residual 1e-10, at most
// screen->max_iterations; a solve that does not get there screens nothing), and screen->reject
// is asked about that approximate map (every vertex, boundary at its prescribed doubles). A
// non-empty answer is the reason the map is given up before the factorisation: not ok, with the
// reason in `message`. Otherwise the map is factorised as without the screen, so a screen that
// rejects nothing changes no output.
struct TutteScreen {
  double above_flops = 0;
  int max_iterations = 5000;
  std::function<std::string(const std::vector<std::array<double, 3>>& approximate)> reject;
};
InitialMap tutte_map(const MapProblem& problem, bool exact = true,
                     double max_flops = std::numeric_limits<double>::infinity(),
                     const TutteScreen* screen = nullptr);

// Fills m.target from m.doubles: interior vertices at their doubles taken exactly, boundary
// vertices at their prescribed positions. Pre: m from tutte_map(problem, false), m.ok.
void exact_target(const MapProblem& problem, InitialMap& m);

// A user-given initial map (cmx map --init FILE, or --init codomain: the codomain mesh's interior
// positions): checks that `positions` has one entry per vertex (problem.source.size()), and that
// the boundary lists are well formed. Every coordinate is finite already: it is an exact rational.
// A boundary vertex not exactly at its prescribed position is set to it, and ok stays true:
// `message` then notes how many were set and the first of them in the boundary list. Reason: the
// prescribed boundary is the problem's, an initial map only proposes interior positions, and a
// file's boundary often differs by its printing (6 digits, or doubles of a rational boundary).
// ok = false with a clear message for a wrong count or malformed boundary lists.
InitialMap given_map(const MapProblem& problem, std::vector<Point3> positions);

}  // namespace cmx::algorithm
