#include <algorithm>

#include "io/boundary.hpp"
#include "io/read_mesh.hpp"
#include "io/scanner.hpp"

namespace cmx::io {

BoundaryPositions parse_boundary_positions(std::string_view bytes, const std::string& name, std::size_t vertex_count) {
  Scanner s(bytes, name);
  s.set_comment_char('#');
  BoundaryPositions out;
  std::vector<std::size_t> line_of_vertex;  // 0 = not seen; bounded by vertex_count (the mesh's)
  line_of_vertex.resize(vertex_count, 0);
  while (s.skip_space()) {
    const std::size_t line = s.line();
    const auto first = s.token("vertex index");
    std::string_view fields[4] = {first, {}, {}, {}};
    int n = 1;
    while (s.more_on_line()) {
      const auto t = s.token("coordinate");
      if (n < 4) fields[n] = t;
      ++n;
    }
    if (n != 4)
      s.fail_at(line, ErrorKind::count_mismatch, "expected 4 fields 'index x y z', found " + std::to_string(n));
    Scanner field(fields[0], name);
    std::uint64_t index = 0;
    try {
      index = field.unsigned_integer("vertex index");
    } catch (const IoError& e) {
      throw IoError(e.kind(), name, line, e.message());
    }
    if (index >= vertex_count)
      s.fail_at(line, ErrorKind::index_out_of_range,
                "vertex index " + std::to_string(index) + " out of range (the mesh has " + std::to_string(vertex_count) + " vertices)");
    if (line_of_vertex[index])
      s.fail_at(line, ErrorKind::duplicate,
                "vertex " + std::to_string(index) + " given twice (first on line " + std::to_string(line_of_vertex[index]) + ")");
    line_of_vertex[index] = line;
    Point3 p;
    for (int k = 0; k < 3; ++k) {
      Scanner coordinate(fields[k + 1], name);
      try {
        p[std::size_t(k)] = coordinate.rational(k == 0 ? "x coordinate" : k == 1 ? "y coordinate" : "z coordinate");
      } catch (const IoError& e) {
        throw IoError(e.kind(), name, line, e.message());
      }
    }
    out.vertices.push_back(std::uint32_t(index));
    out.positions.push_back(std::move(p));
  }
  return out;
}

BoundaryPositions read_boundary_positions(const std::string& path, std::size_t vertex_count) {
  return parse_boundary_positions(read_file_bytes(path), path, vertex_count);
}

MeshBoundary mesh_boundary(const TetMeshData& mesh, const std::string& name) {
  // Each tet contributes its four faces oriented outward for a positive tet (a, b, c, d):
  // (b, c, d), (a, d, c), (a, b, d), (a, c, b). A face in one tet is a boundary face.
  struct Entry {
    std::array<std::uint32_t, 3> key, face;
  };
  std::vector<Entry> entries;
  entries.reserve(mesh.tets.size() * 4);
  for (const auto& t : mesh.tets) {
    const std::array<std::array<std::uint32_t, 3>, 4> faces{{{t[1], t[2], t[3]}, {t[0], t[3], t[2]}, {t[0], t[1], t[3]}, {t[0], t[2], t[1]}}};
    for (const auto& f : faces) {
      auto key = f;
      std::sort(key.begin(), key.end());
      entries.push_back({key, f});
    }
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.key < b.key; });
  MeshBoundary b;
  for (std::size_t i = 0; i < entries.size();) {
    std::size_t j = i;
    while (j < entries.size() && entries[j].key == entries[i].key) ++j;
    if (j - i > 2)
      throw IoError(ErrorKind::mismatch, name, 0,
                    "face (" + std::to_string(entries[i].key[0]) + ", " + std::to_string(entries[i].key[1]) + ", " +
                        std::to_string(entries[i].key[2]) + ") belongs to " + std::to_string(j - i) + " tets");
    if (j - i == 1) {
      b.faces.push_back(entries[i].face);
      b.vertices.insert(b.vertices.end(), entries[i].face.begin(), entries[i].face.end());
    }
    i = j;
  }
  std::sort(b.faces.begin(), b.faces.end());
  std::sort(b.vertices.begin(), b.vertices.end());
  b.vertices.erase(std::unique(b.vertices.begin(), b.vertices.end()), b.vertices.end());
  return b;
}

BoundaryPositions read_boundary_positions_from_codomain(const TetMeshData& domain, const TetMeshData& codomain,
                                                        const std::string& codomain_name) {
  if (domain.positions.size() != codomain.positions.size())
    throw IoError(ErrorKind::mismatch, codomain_name, 0,
                  "the codomain has " + std::to_string(codomain.positions.size()) + " vertices, the domain " +
                      std::to_string(domain.positions.size()));
  if (domain.tets.size() != codomain.tets.size())
    throw IoError(ErrorKind::mismatch, codomain_name, 0,
                  "the codomain has " + std::to_string(codomain.tets.size()) + " tets, the domain " + std::to_string(domain.tets.size()));
  for (std::size_t i = 0; i < domain.tets.size(); ++i) {
    auto a = domain.tets[i], b = codomain.tets[i];
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    if (a != b)
      throw IoError(ErrorKind::mismatch, codomain_name, 0,
                    "tet " + std::to_string(i) + " has other vertices than in the domain: the connectivity must be identical");
  }
  BoundaryPositions out;
  out.vertices = mesh_boundary(domain).vertices;
  out.positions.reserve(out.vertices.size());
  for (auto v : out.vertices) out.positions.push_back(codomain.positions[v]);
  return out;
}

BoundaryPositions read_boundary_positions_from_codomain(const TetMeshData& domain, const std::string& codomain_path) {
  ReadOptions keep;
  keep.orientation = Orientation::keep;
  return read_boundary_positions_from_codomain(domain, read_tet_mesh(codomain_path, keep), codomain_path);
}

void check_boundary_coverage(const TetMeshData& domain, const BoundaryPositions& positions, const std::string& name) {
  const auto boundary = mesh_boundary(domain).vertices;
  auto given = positions.vertices;
  std::sort(given.begin(), given.end());
  std::vector<std::uint32_t> missing, extra;
  std::set_difference(boundary.begin(), boundary.end(), given.begin(), given.end(), std::back_inserter(missing));
  std::set_difference(given.begin(), given.end(), boundary.begin(), boundary.end(), std::back_inserter(extra));
  if (!missing.empty())
    throw IoError(ErrorKind::mismatch, name, 0,
                  std::to_string(missing.size()) + " boundary vertices have no position, the first is vertex " + std::to_string(missing[0]));
  if (!extra.empty())
    throw IoError(ErrorKind::mismatch, name, 0,
                  std::to_string(extra.size()) + " prescribed vertices are not on the boundary, the first is vertex " + std::to_string(extra[0]));
}

}  // namespace cmx::io
