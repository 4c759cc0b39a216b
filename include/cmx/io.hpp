#pragma once
// Reading and writing tetrahedral meshes, the format chosen by the file's extension (any case):
//
//   .ovm        OpenVolumeMesh ASCII; written with doubles and the exact positions (the string
//               property str_exact_position, read back in preference to the doubles)
//   .vtu        VTK XML (read: ascii, base64, appended raw, zlib; written: ascii)
//   .vtk        legacy VTK (read: ASCII or BINARY, 4.2 and 5.1; written: 4.2 ASCII)
//   .mesh       Medit ASCII
//   .msh        Gmsh (read: 2.2 and 4.1, ASCII or binary; written: 4.1 ASCII)
//   .node/.ele  TetGen (both files, either name)
//   .tmap       cmx's exact map: exact source and target positions (docs/formats.md)
//
// Every coordinate is read as the exact rational its text or binary double denotes ("0.1" is
// 1/10), so Mesh::points_exact is always filled by read. Doubles are written with 17 significant
// digits (they read back as the same doubles). Writes are atomic: the file is written to a
// temporary beside it and renamed into place, so on failure nothing is written and an existing
// file is kept (TetGen: both files or neither).
//
//   cmx::Mesh m = cmx::read("in.vtu");
//   cmx::write("out.ovm", m);
//
// This header includes only the standard library and <cmx/types.hpp>.
#include <string>
#include <vector>

#include "cmx/types.hpp"

namespace cmx {

struct Mesh {
  std::vector<Point3d> points;            // vertex positions in doubles
  std::vector<ExactPoint3> points_exact;  // the same exactly ("p/q" or "p"); may be empty for write
  std::vector<Tet> tets;                  // 0-based vertex indices, positively oriented
  // A map (.tmap) only, one per vertex: the exact target and its nearest doubles; the tets are
  // positive in both geometries. Empty for every other format.
  std::vector<ExactPoint3> target_exact;
  std::vector<Point3d> target;
};

// Reads the mesh at `path`; a .tmap gives its source as points/points_exact and its target as
// target/target_exact. Vertices keep the file's order (1-based formats shifted to 0-based; the
// mid-edge nodes of 10-node tets dropped); cells of dimension < 3 are skipped. Every tet is checked
// exactly: when all tets are negatively oriented the last two vertices of every tet are swapped
// (each format's convention is normalised to cmx's, det[b-a, c-a, d-a] > 0).
// points are the nearest doubles of points_exact (the file's doubles, for binary formats).
// Errors: throws cmx::Error for a file that cannot be read, an unknown extension, malformed
// content, a tet with a repeated vertex or zero volume, tets of both signs, a duplicate tet, or
// an index out of range; what() names the file and, for text formats, the line
// ("in.mesh:12: ...").
// Time and memory: linear in the file size.
Mesh read(const std::string& path);

// Writes `mesh` to `path` in the format of its extension (the table above; .msh is Gmsh 4.1
// ASCII, .node or .ele writes both TetGen files). Positions: points_exact when not empty (then
// `points` may be empty, or must have the same size), else the doubles of points taken exactly.
// Doubles written in display formats are `points`, or the nearest doubles of points_exact when
// `points` is empty; .ovm adds points_exact as its exact property when given. A .tmap needs a
// target (target_exact, or else target, one per vertex) and writes exact source and target;
// orientation is not checked on writing (read checks it). Tets are written as given.
// Errors: throws cmx::Error, naming the file, for an unknown extension, a tet index >= the number
// of points, a NaN or infinite coordinate, sizes that disagree, exact text that does not parse
// (naming the point and coordinate), or a file that cannot be written.
// Time: linear in the mesh size.
void write(const std::string& path, const Mesh& mesh);

}  // namespace cmx
