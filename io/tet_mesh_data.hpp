#pragma once
// What every mesh reader returns: exact vertex positions and 0-based tetrahedra, plus the
// per-vertex string properties of OVM files (kept verbatim so exact data survives conversion).
//
// Invariants after a successful read (with the default ReadOptions):
//  * every index in `tets` is < positions.size(); no tet repeats a vertex; no two tets have the
//    same vertex set;
//  * det[b-a, c-a, d-a] > 0 for every tet (a, b, c, d) — cmx's orientation convention — the
//    file's own convention having been detected and normalised (see docs/formats.md).
// Vertex indices keep the file's order (1-based formats are shifted down by one; Gmsh and TetGen
// node tags are mapped to positions in the file's node list), except that the mid-edge nodes of
// second-order tets are dropped (io/second_order.hpp).
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "arith/rational.hpp"

namespace cmx::io {

using Tet = std::array<std::uint32_t, 4>;

// A per-vertex string property (OVM `VProp string "name"`), one value per vertex.
struct StringProperty {
  std::string name;
  std::vector<std::string> values;
};

struct TetMeshData {
  std::vector<Point3> positions;
  std::vector<Tet> tets;
  std::vector<StringProperty> vertex_string_properties;
  // True when the reader swapped two vertices of every tet because the file listed all tets
  // negatively oriented.
  bool orientation_flipped = false;
  // Mid-edge nodes of second-order tets that the reader dropped (io/second_order.hpp); the
  // remaining vertices were renumbered consecutively in file order. 0 for linear meshes.
  std::size_t dropped_higher_order_nodes = 0;
};

// What readers do with orientation.
enum class Orientation {
  // Default. Compute every tet's sign exactly; all negative -> swap the last two vertices of every
  // tet; mixed signs -> IoError(inconsistent_orientation) naming the first tet of the minority
  // sign; a zero-volume tet -> IoError(degenerate_tet) unless allow_degenerate.
  normalise,
  // Keep the file's vertex order and do no geometric check (for codomain meshes whose interior is
  // allowed to be folded, and for `cmx info`, which reports the signs itself).
  keep,
};

struct ReadOptions {
  Orientation orientation = Orientation::normalise;
  // With normalise: zero-volume tets are accepted and ignored when deciding the convention (for
  // meshes whose positions carry no geometry). If every tet is degenerate nothing is flipped.
  bool allow_degenerate = false;
  // OVM: replace the double positions by the exact `str_exact_position` property when present.
  bool use_exact_position_property = true;
};

// Hard limits that protect against absurd headers: counts beyond these are IoError(too_large)
// before anything is allocated. Counts are additionally bounded by the file size.
inline constexpr std::uint64_t max_vertices = 0xFFFFFFFEull;  // indices are uint32
inline constexpr std::uint64_t max_tets = 0xFFFFFFFEull;

}  // namespace cmx::io
