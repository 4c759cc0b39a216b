#pragma once
// Reading a mapping problem for `cmx map`: the domain mesh and its boundary positions from a
// boundary file, a codomain mesh, or a generated shape.
#include <cstdint>
#include <string>

#include "algorithm/map.hpp"
#include "generators/boundary_shapes.hpp"

namespace cmx::cli {

// Exactly one of boundary_path, codomain_path, shape is non-empty. Throws io::IoError for
// unreadable or malformed files, algorithm::MapError for a shape that cannot be generated.
// combinatorial (cmx map --combinatorial, implied by a .facets DOMAIN): DOMAIN is a facet list
// (io/read_facets.hpp) or a mesh whose positions are ignored; its tets are oriented alike
// (topology::orient_coherently; MapError not_ball when they cannot be) and, when the prescribed
// boundary encloses a negative volume with them, all turned over; a generated shape works from
// the combinatorics alone; the problem's source positions are zeros. `threads`: the generated
// shape's corner attempts made at once (generators::BoundaryShapeSpec::threads).
algorithm::MapProblem load_map_problem(const std::string& domain_path, const std::string& boundary_path,
                                       const std::string& codomain_path, const std::string& shape,
                                       std::uint64_t seed, bool combinatorial = false,
                                       generators::CornerChoice corners = generators::CornerChoice::random,
                                       unsigned threads = 1);

// The initial map of --init FILE (lines 'index x y z' for every vertex) or, when init_file is
// empty, --init codomain (every position of the codomain mesh) into p.initial_target. Throws
// io::IoError: malformed, or (mismatch) not one position per vertex.
void load_initial_map(algorithm::MapProblem& p, const std::string& init_file, const std::string& codomain_path);

}  // namespace cmx::cli
