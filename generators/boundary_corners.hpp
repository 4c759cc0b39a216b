#pragma once
// The tetrahedron's corners on the boundary surface and the paths between them (steps 1 and 2 of
// generate_boundary, generators/boundary_shapes.hpp): drawn corners, or the ends of the surface's
// longest stretch (CornerChoice::farthest), and the paths that go to the tetrahedron's edges.
// Internal to the generators layer; not installed.
#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "generators/boundary_shapes.hpp"
#include "generators/boundary_surface.hpp"

namespace cmx::generators::detail {

// Four distinct corners (local ids) for attempt `rng`.
// CornerChoice::farthest alternates: farthest corners on even attempts (from different drawn
// starts, which often lead to the same corners; every other time with the ends swapped), drawn
// ones on odd attempts.
std::array<std::uint32_t, 4> choose_corners(const Surface& s, const std::vector<Vec3>& src,
                                            const BoundaryShapeSpec& spec, int attempt,
                                            std::mt19937_64& rng);

// Steps 1 and 2 of the construction: the corners go to the tetrahedron's corners, the paths
// between them to its edges; marks them fixed. "" or why it failed. Drawn corners: the paths
// one after another, 1-0, 2-0, 2-1, 3-0, 3-1, 3-2. Farthest corners (keep_apart): the three
// into the hub corner first (fix_paths_from_hub: corner 0, or 3 for stiff-tet), then the other
// three, each of which cuts a face off the disc that remains.
std::string fix_corner_paths(const Surface& s, const std::vector<Vec3>& src, const std::array<std::uint32_t, 4>& corners,
                             bool keep_apart, bool stiff, std::vector<char>& fixed, std::vector<Vec3>& pos);

}  // namespace cmx::generators::detail
