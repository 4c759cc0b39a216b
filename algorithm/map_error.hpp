#pragma once
// The typed error of the mapping method: what went wrong, where, in
// words a user can act on. The library never exits; the CLI maps each kind to an exit code.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace cmx::algorithm {

enum class MapErrorKind {
  invalid_input,         // sizes, indices, NaN: the data cannot describe a mapping problem
  not_ball,              // the mesh is not a ball (topology::check_ball failed)
  boundary_mismatch,     // positions not given for exactly the boundary vertices
  source_not_positive,   // a source tet is not positively oriented
  degenerate_boundary,   // a prescribed boundary triangle is degenerate (collinear corners)
  boundary_orientation,  // the prescribed boundary is mirrored (inside out)
  not_star_shaped,       // the prescribed boundary has no kernel of positive volume
  time_limit,            // --time-limit reached
  stuck,                 // no expansion sequence found
  internal,              // an invariant or the final verification failed: a bug
};

// Short stable name ("not_star_shaped", ...), for JSON reports and tests.
const char* kind_name(MapErrorKind kind);

class MapError : public std::runtime_error {
 public:
  // `where` names the offending element, e.g. "boundary triangle (3, 7, 9)" or "vertex 12".
  MapError(MapErrorKind kind, std::string message, std::string where = {});
  MapErrorKind kind() const { return kind_; }
  const std::string& where() const { return where_; }

 private:
  MapErrorKind kind_;
  std::string where_;
};

}  // namespace cmx::algorithm
