// Medit .mesh reader (ASCII; MeshVersionFormatted 1 or 2, which differ only in binary files).
// Lenient on what trips other readers: keyword case, a keyword's value on the same or the next
// line, CRLF, '#' comments, unknown sections (skipped by their count), a missing `End`.
// Indices are 1-based in the file; every item ends with an integer reference (ignored).
// TetrahedraP2 (10-node tets) contribute their corners (io/second_order.hpp).
#include <cctype>
#include <cstdint>

#include "io/orientation.hpp"
#include "io/read_mesh.hpp"
#include "io/scanner.hpp"
#include "io/second_order.hpp"

namespace cmx::io {
namespace {

std::string lower(std::string_view t) {
  std::string s(t);
  for (auto& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Numbers per item of the sections cmx skips; 0 = unknown (then skipped line by line).
int fields_per_item(const std::string& keyword) {
  static const std::pair<const char*, int> table[] = {
      {"edges", 3}, {"triangles", 4}, {"quadrilaterals", 5}, {"hexahedra", 9}, {"prisms", 7},
      {"pyramids", 6}, {"corners", 1}, {"ridges", 1}, {"requiredvertices", 1}, {"requirededges", 1},
      {"requiredtriangles", 1}, {"requiredquadrilaterals", 1}, {"normals", 3}, {"tangents", 3},
      {"normalatvertices", 2}, {"tangentatvertices", 2}, {"tangentatedges", 3}, {"normalattrianglevertices", 3},
      {"edgesp2", 4}, {"trianglesp2", 7}, {"tetrahedrap2", 11}, {"subdomainfromgeom", 4},
      {"subdomainfrommesh", 4}, {"vertexongeometricvertex", 2}, {"vertexongeometricedge", 3},
      {"edgeongeometricedge", 2}, {"identifications", 0}, {"crackedges", 2}};
  for (const auto& [k, n] : table)
    if (keyword == k) return n;
  return 0;
}

// The 3D cell sections other than tetrahedra, with what they hold; nullptr for other keywords.
const char* refused_3d_cells(const std::string& keyword) {
  if (keyword == "hexahedra" || keyword == "hexaedra" || keyword == "prisms" || keyword == "pyramids") return "linear 3D cells";
  if (keyword == "hexahedraq2" || keyword == "prismsp2" || keyword == "pyramidsp2" || keyword == "tetrahedrap3")
    return "second-order or higher-order 3D cells";
  return nullptr;
}

// Reads a Tetrahedra (4 nodes) or TetrahedraP2 (10 nodes: corners, then mid-edge nodes) section:
// a count, then per item the 1-based node indices and a reference.
void read_tets(Scanner& s, int nodes, bool have_vertices, TetMeshData& mesh, std::vector<std::size_t>& tet_lines,
               HigherOrderNodes& higher_order) {
  const auto n = s.count("tetrahedron count", max_tets, std::size_t(2 * nodes + 2));
  mesh.tets.reserve(mesh.tets.size() + std::size_t(n));
  tet_lines.reserve(tet_lines.size() + std::size_t(n));
  for (std::uint64_t i = 0; i < n; ++i) {
    s.skip_space();
    tet_lines.push_back(s.line());
    Tet t;
    for (int k = 0; k < nodes; ++k) {
      const auto index = s.unsigned_integer("vertex index");
      if (index == 0 || index > mesh.positions.size() + (have_vertices ? 0 : max_vertices))
        s.fail(ErrorKind::index_out_of_range,
               "vertex index " + std::to_string(index) + " out of range (Medit indices are 1-based; " +
                   std::to_string(mesh.positions.size()) + " vertices)");
      if (k < 4) t[std::size_t(k)] = std::uint32_t(index - 1);
      else higher_order.add(std::uint32_t(index - 1));
    }
    s.integer("tetrahedron reference");
    mesh.tets.push_back(t);
  }
}

}  // namespace

TetMeshData read_medit(std::string_view bytes, const std::string& name, const ReadOptions& options) {
  Scanner s(bytes, name);
  s.set_comment_char('#');
  TetMeshData mesh;
  std::vector<std::size_t> tet_lines;
  bool have_version = false, have_vertices = false, have_tets = false, have_p2 = false;
  HigherOrderNodes higher_order;
  int dimension = 3;
  while (s.skip_space()) {
    const auto raw = s.token("keyword");
    const auto keyword = lower(raw);
    if (keyword == "meshversionformatted") {
      const auto v = s.unsigned_integer("mesh version");
      if (v < 1 || v > 4) s.fail(ErrorKind::unsupported, "MeshVersionFormatted " + std::to_string(v) + " is not supported");
      have_version = true;
    } else if (keyword == "dimension") {
      const auto d = s.unsigned_integer("dimension");
      if (d != 3) s.fail(ErrorKind::unsupported, "Dimension " + std::to_string(d) + ": only 3D meshes are supported");
      dimension = int(d);
    } else if (keyword == "vertices") {
      if (have_vertices) s.fail(ErrorKind::syntax, "a second Vertices section");
      const auto n = s.count("vertex count", max_vertices, 8);
      mesh.positions.reserve(std::size_t(n));
      for (std::uint64_t i = 0; i < n; ++i) {
        Point3 p;
        for (int k = 0; k < dimension; ++k) p[std::size_t(k)] = s.rational("vertex coordinate");
        s.integer("vertex reference");
        mesh.positions.push_back(std::move(p));
      }
      have_vertices = true;
    } else if (keyword == "tetrahedra" || keyword == "tetrahedrap2") {
      const bool p2 = keyword == "tetrahedrap2";
      if (p2 ? have_p2 : have_tets) s.fail(ErrorKind::syntax, "a second " + std::string(raw) + " section");
      (p2 ? have_p2 : have_tets) = true;
      read_tets(s, p2 ? 10 : 4, have_vertices, mesh, tet_lines, higher_order);
    } else if (keyword == "end") {
      break;
    } else {
      // Unknown or uninteresting section: "<Keyword> <count>" then count items.
      const int fields = fields_per_item(keyword);
      if (const char* what = refused_3d_cells(keyword)) {
        s.skip_space();
        const std::size_t at = s.line();
        if (s.unsigned_integer("item count") > 0)
          s.fail_at(at, ErrorKind::non_tet_cell,
                    "section " + quoted(raw) + " (" + what +
                        "): among 3D cells only Tetrahedra and TetrahedraP2 (read as their corners) are supported");
        continue;
      }
      const auto n = s.count("item count of section " + std::string(quoted(raw)), UINT64_MAX / 4, 2);
      if (fields > 0) {
        for (std::uint64_t i = 0; i < n; ++i)
          for (int k = 0; k < fields; ++k) s.token("item of section " + quoted(raw));
      } else {
        // Not in the table: one item per line (the Medit ASCII convention).
        s.rest_of_line();
        for (std::uint64_t i = 0; i < n; ++i) {
          if (!s.skip_space()) s.fail(ErrorKind::truncated, "section " + quoted(raw) + " ends early");
          s.rest_of_line();
        }
      }
    }
  }
  if (!have_version) s.fail_at(1, ErrorKind::syntax, "not a Medit file: no MeshVersionFormatted");
  if (!have_vertices) s.fail(ErrorKind::truncated, "no Vertices section");
  for (std::size_t i = 0; i < mesh.tets.size(); ++i)
    for (auto v : mesh.tets[i])
      if (v >= mesh.positions.size())
        s.fail_at(tet_lines[i], ErrorKind::index_out_of_range, "vertex index " + std::to_string(v + 1) + " out of range (" + std::to_string(mesh.positions.size()) + " vertices)");
  if (!higher_order.all_below(mesh.positions.size()))
    s.fail(ErrorKind::index_out_of_range, "a TetrahedraP2 mid-edge vertex index is out of range (" + std::to_string(mesh.positions.size()) + " vertices)");
  higher_order.drop_unused(mesh);
  validate_and_orient(mesh, options, name, tet_lines);
  return mesh;
}

}  // namespace cmx::io
