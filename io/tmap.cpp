#include "io/tmap.hpp"

#include "io/atomic_file.hpp"
#include "io/orientation.hpp"
#include "io/scanner.hpp"
#include "kernel/homogeneous_point.hpp"
#include "kernel/orient.hpp"

namespace cmx::io {
namespace {

void expect(Scanner& s, std::string_view word) {
  const auto t = s.token(word);
  if (t != word) s.fail(ErrorKind::syntax, "expected '" + std::string(word) + "', found " + quoted(t));
}

void check_positive(const std::vector<Point3>& positions, const std::vector<Tet>& tets,
                    const std::vector<std::size_t>& lines, const std::string& name, const char* side) {
  std::vector<HPoint> p;
  p.reserve(positions.size());
  for (const auto& x : positions) p.emplace_back(x[0], x[1], x[2]);
  for (std::size_t i = 0; i < tets.size(); ++i) {
    const auto& t = tets[i];
    const Sign s =
        orient3d(p[t[0]], p[t[1]], p[t[2]], p[t[3]], PredicateContext::certain());  // reading a map checks it
    if (s != Sign::positive)
      throw IoError(s == Sign::zero ? ErrorKind::degenerate_tet : ErrorKind::inconsistent_orientation, name, lines[i],
                    "tet " + std::to_string(i) + " is " + (s == Sign::zero ? "degenerate" : "negatively oriented") +
                        " in the " + side + " (a tmap requires det[b-a, c-a, d-a] > 0)");
  }
}

}  // namespace

TetMap parse_tmap(std::string_view bytes, const std::string& name, bool verify_orientation) {
  Scanner s(bytes, name);
  s.set_comment_char('#');
  expect(s, "tmap");
  if (const auto v = s.unsigned_integer("tmap version"); v != 1)
    s.fail(ErrorKind::unsupported, "tmap version " + std::to_string(v) + " is not supported (only 1)");
  expect(s, "vertices");
  const auto n = s.count("vertex count", max_vertices, 12);
  TetMap map;
  map.source.reserve(std::size_t(n));
  map.target.reserve(std::size_t(n));
  for (std::uint64_t i = 0; i < n; ++i) {
    s.skip_space();
    const std::size_t line = s.line();
    Point3 a, b;
    for (auto& c : a) c = s.rational("source coordinate");
    for (auto& c : b) c = s.rational("target coordinate");
    if (s.more_on_line()) s.fail_at(line, ErrorKind::count_mismatch, "a vertex line has more than 6 coordinates");
    map.source.push_back(std::move(a));
    map.target.push_back(std::move(b));
  }
  expect(s, "tets");
  const auto m = s.count("tet count", max_tets, 8);
  map.tets.reserve(std::size_t(m));
  std::vector<std::size_t> lines;
  lines.reserve(std::size_t(m));
  for (std::uint64_t i = 0; i < m; ++i) {
    s.skip_space();
    lines.push_back(s.line());
    Tet t;
    for (auto& v : t) {
      const auto x = s.unsigned_integer("vertex index");
      if (x >= n) s.fail(ErrorKind::index_out_of_range, "vertex index " + std::to_string(x) + " out of range (" + std::to_string(n) + " vertices)");
      v = std::uint32_t(x);
    }
    if (s.more_on_line()) s.fail(ErrorKind::count_mismatch, "a tet line has more than 4 indices");
    map.tets.push_back(t);
  }
  if (s.skip_space()) s.fail(ErrorKind::count_mismatch, "unexpected data after the " + std::to_string(m) + " tets: " + quoted(s.try_token()));
  // Combinatorial checks (repeated vertex, duplicate tet) through the shared validation.
  TetMeshData view;
  view.positions.resize(map.source.size());
  view.tets = map.tets;
  validate_and_orient(view, ReadOptions{Orientation::keep, false, false}, name, lines);
  if (verify_orientation) {
    check_positive(map.source, map.tets, lines, name, "source");
    check_positive(map.target, map.tets, lines, name, "target");
  }
  return map;
}

TetMap read_tmap(const std::string& path, bool verify_orientation) {
  return parse_tmap(read_file_bytes(path), path, verify_orientation);
}

TetMeshData mesh_of_map(TetMap map, MapGeometry geometry) {
  if (map.source.size() != map.target.size())
    throw IoError(ErrorKind::mismatch, "tmap", 0, "source and target vertex counts differ");
  TetMeshData mesh;
  mesh.positions = std::move(geometry == MapGeometry::source ? map.source : map.target);
  mesh.tets = std::move(map.tets);
  return mesh;
}

TetMeshData read_map_as_mesh(const std::string& path, MapGeometry geometry) { return mesh_of_map(read_tmap(path), geometry); }

bool is_map_path(const std::string& path) { return extension_of(path) == "tmap"; }

void write_tmap(const std::string& path, const TetMap& map) {
  if (map.source.size() != map.target.size())
    throw IoError(ErrorKind::mismatch, path, 0, "source and target vertex counts differ");
  for (std::size_t i = 0; i < map.tets.size(); ++i)
    for (auto v : map.tets[i])
      if (v >= map.source.size())
        throw IoError(ErrorKind::index_out_of_range, path, 0, "tet " + std::to_string(i) + " uses vertex " + std::to_string(v));
  write_file_atomically(path, [&](std::ostream& out) {
    out << "tmap 1\nvertices " << map.source.size() << '\n';
    for (std::size_t i = 0; i < map.source.size(); ++i) {
      const auto& a = map.source[i];
      const auto& b = map.target[i];
      out << to_string(a[0]) << ' ' << to_string(a[1]) << ' ' << to_string(a[2]) << ' ' << to_string(b[0]) << ' '
          << to_string(b[1]) << ' ' << to_string(b[2]) << '\n';
    }
    out << "tets " << map.tets.size() << '\n';
    for (const auto& t : map.tets) out << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << t[3] << '\n';
  });
}

}  // namespace cmx::io
