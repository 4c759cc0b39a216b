#pragma once
// The output part of MapStatistics, the same for the global method and a local repair.
#include <vector>

#include "algorithm/map.hpp"

namespace cmx::algorithm {

// Output vertex and tet counts, growth (input_vertices must be set) and the target's bit sizes.
void output_statistics(std::size_t tets, const std::vector<HPoint>& target, MapStatistics& s);

}  // namespace cmx::algorithm
