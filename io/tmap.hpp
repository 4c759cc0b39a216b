#pragma once
// The exact map format .tmap (docs/formats.md):
//   tmap 1
//   vertices N
//   sx sy sz tx ty tz      N lines: exact source then target coordinates (integer or p/q)
//   tets M
//   a b c d                M lines: 0-based; det[b-a, c-a, d-a] > 0 in source and target
// The reader also accepts decimals and hexfloats (any syntax of parse_rational), blank lines and
// '#' comments; the writer writes canonical integers or p/q only.
#include <string>
#include <string_view>
#include <vector>

#include "io/tet_mesh_data.hpp"

namespace cmx::io {

struct TetMap {
  std::vector<Point3> source, target;  // same size
  std::vector<Tet> tets;
};

// Reads and verifies a tmap: counts, indices, no repeated vertex within a tet, no duplicate tet,
// and every tet positively oriented in the source AND the target (exact); a violation is an
// IoError naming the line of the offending tet. With verify_orientation = false only the
// combinatorial checks are made.
TetMap parse_tmap(std::string_view bytes, const std::string& name, bool verify_orientation = true);
TetMap read_tmap(const std::string& path, bool verify_orientation = true);

// Writes atomically. Throws IoError (mismatch) when source and target sizes differ,
// (index_out_of_range) for a bad tet index. Orientation is the caller's invariant (not checked).
void write_tmap(const std::string& path, const TetMap& map);

// Which geometry of a map a mesh is made of.
enum class MapGeometry { source, target };

// The map as a mesh: its tets with the exact source or target positions (TetMeshData invariants
// hold for a map read by read_tmap: every tet is positive in both). Throws IoError(mismatch) when
// source and target sizes differ. Pass the map with std::move to avoid copying positions.
TetMeshData mesh_of_map(TetMap map, MapGeometry geometry);
// read_tmap (with its orientation checks), then mesh_of_map: how `.tmap` becomes an input of
// commands that take a mesh (read_tet_mesh refuses .tmap, since only the caller knows which
// geometry is wanted).
TetMeshData read_map_as_mesh(const std::string& path, MapGeometry geometry);
// True for a path ending in .tmap (any case).
bool is_map_path(const std::string& path);

}  // namespace cmx::io
