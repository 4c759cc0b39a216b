#pragma once
// Vertex-disjoint paths of least total length from one vertex of a graph to several others.
//
// The boundary construction (generators/boundary_corners.cpp) needs three paths from one corner
// to the other three that share no vertex but that corner. Found one after another, the first
// two can wall off the third (two shortest paths down a narrow tunnel leave no free vertex
// between them); found together as a min-cost flow they exist whenever the graph allows them,
// which by Menger's theorem is always on a 3-connected graph, such as the edge graph of every
// triangulated sphere that is a simplicial complex.

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace cmx::generators {

// Paths from `from` to each of `to` (in that order; each path starts at `from` and ends at its
// target) that share no vertex but `from`, pass through no vertex of `to` but their own end and
// through no vertex with `blocked[v]` set, with the least total `length` (called once per
// directed edge; it must be positive). Empty when no such set of paths exists. `neighbors[v]`
// lists v's neighbours (each edge in both lists); the result depends only on the graph, the
// lengths and the order of the lists.
std::vector<std::vector<std::uint32_t>> disjoint_paths(
    const std::vector<std::vector<std::uint32_t>>& neighbors,
    const std::function<double(std::uint32_t, std::uint32_t)>& length, std::uint32_t from,
    std::span<const std::uint32_t> to, const std::vector<char>& blocked);

}  // namespace cmx::generators
