#pragma once
// Reading a mapping problem for `cmx map`: the domain mesh and its boundary positions from a
// boundary file, a codomain mesh, or a generated shape.
#include <cstdint>
#include <string>

#include "algorithm/map.hpp"

namespace cmx::cli {

// Exactly one of boundary_path, codomain_path, shape is non-empty. Throws io::IoError for
// unreadable or malformed files, algorithm::MapError for a shape that cannot be generated.
algorithm::MapProblem load_map_problem(const std::string& domain_path, const std::string& boundary_path,
                                       const std::string& codomain_path, const std::string& shape, std::uint64_t seed);

}  // namespace cmx::cli
