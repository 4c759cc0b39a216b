#pragma once
// The command line of `cmx map`: what the run reads, writes and how it maps.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "algorithm/map.hpp"
#include "generators/boundary_shapes.hpp"

namespace cmx::cli {

struct MapArgs {
  std::string domain, boundary, codomain, shape, out, report, trace;
  std::string init_file;             // --init FILE (options.init is then given)
  std::vector<std::string> formats;  // from --format (OUT's extension is added by the output plan)
  bool report_on_failure = false;    // a failed run may replace an existing report or trace
  std::uint64_t seed = 1234;
  generators::CornerChoice corners = generators::CornerChoice::random;  // --corners, with --shape
  algorithm::MapOptions options = program_defaults();  // time limit, check and the method's choices

  // The library's defaults, except the initial map: the program starts from `auto` (a Tutte map
  // repaired locally where it folds, else the global method), the library from the paper's shrink.
  static algorithm::MapOptions program_defaults() {
    algorithm::MapOptions o;
    o.init = algorithm::InitialMapKind::automatic;
    return o;
  }
};

// The formats cmx map writes.
const std::vector<std::string>& map_formats();

// nullopt: run; otherwise the exit code to return (help, version or a bad command line).
std::optional<int> parse_map_args(const std::vector<std::string>& args, MapArgs& a);

}  // namespace cmx::cli
