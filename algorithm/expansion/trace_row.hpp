#pragma once
// The whole-mesh figures of a `--trace` row (map.hpp, TraceRow): largest and mean bits over the
// live vertices' target positions, vertices added so far, tets still degenerate. One pass over
// vertices and tets: computed only when a trace is asked for.
#include <cstddef>

#include "algorithm/embedding.hpp"
#include "algorithm/map.hpp"

namespace cmx::algorithm {

TraceRow state_row(const Embedding& e, std::size_t input_vertices);

}  // namespace cmx::algorithm
