// OVM ASCII writer. Builds the half-edge / half-face structure from the tets: edges and faces are
// numbered in order of first appearance and stored in the orientation of that appearance; a tet
// (a, b, c, d) with det[b-a, c-a, d-a] > 0 gets the half-faces (a, b, c), (a, c, d), (a, d, b),
// (b, d, c) — each normal (right-hand rule) pointing into the tet — so that the first half-face's
// cycle followed by the remaining vertex gives back (a, b, c, d), the convention OVM readers of
// cmx and Shrink-and-Expand use.
#include <algorithm>
#include <map>
#include <unordered_map>

#include "io/atomic_file.hpp"
#include "io/io_error.hpp"
#include "io/write_mesh.hpp"

namespace cmx::io {
namespace {

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t(a) << 32) | b;
}

// Exact coordinate as SaE writes it: always "p/q" (integers as "k/1"), which GMP reads back.
std::string exact_text(const Rational& q) {
  std::string s = to_string(q);
  if (s.find('/') == std::string::npos) s += "/1";
  return s;
}

void write_string_property(std::ostream& out, const std::string& name, const std::vector<std::string>& values) {
  out << "VProp string \"" << name << "\"\n";
  for (const auto& v : values) out << v.size() << ':' << v << '\n';
}

}  // namespace

void write_ovm(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets,
               const std::vector<Point3>* exact, const std::vector<StringProperty>& properties) {
  detail::check_writable(path, points, tets);
  if (exact && exact->size() != points.size())
    throw IoError(ErrorKind::mismatch, path, 0, "exact positions and points differ in number");
  for (const auto& prop : properties)
    if (prop.values.size() != points.size())
      throw IoError(ErrorKind::mismatch, path, 0, "property \"" + prop.name + "\" has " + std::to_string(prop.values.size()) + " values for " + std::to_string(points.size()) + " vertices");

  std::vector<std::array<std::uint32_t, 2>> edges;
  std::unordered_map<std::uint64_t, std::uint32_t> edge_index;
  edge_index.reserve(tets.size() * 2);
  const auto half_edge = [&](std::uint32_t a, std::uint32_t b) -> std::uint64_t {
    const auto [it, added] = edge_index.try_emplace(edge_key(a, b), std::uint32_t(edges.size()));
    if (added) edges.push_back({a, b});
    return 2 * std::uint64_t(it->second) + (edges[it->second][0] == a ? 0 : 1);
  };
  std::vector<std::array<std::uint64_t, 3>> faces;  // half-edges
  std::vector<std::array<std::uint32_t, 3>> face_cycle;
  std::map<std::array<std::uint32_t, 3>, std::uint32_t> face_index;
  const auto half_face = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) -> std::uint64_t {
    std::array<std::uint32_t, 3> key{a, b, c};
    std::sort(key.begin(), key.end());
    const auto [it, added] = face_index.try_emplace(key, std::uint32_t(faces.size()));
    if (added) {
      faces.push_back({half_edge(a, b), half_edge(b, c), half_edge(c, a)});
      face_cycle.push_back({a, b, c});
    }
    const auto& f = face_cycle[it->second];
    // Same orientation when (a, b, c) is a rotation of the stored cycle.
    const bool same = (f[0] == a && f[1] == b) || (f[0] == b && f[1] == c) || (f[0] == c && f[1] == a);
    return 2 * std::uint64_t(it->second) + (same ? 0 : 1);
  };
  std::vector<std::array<std::uint64_t, 4>> cells;
  cells.reserve(tets.size());
  for (const auto& t : tets) {
    const auto [a, b, c, d] = t;
    cells.push_back({half_face(a, b, c), half_face(a, c, d), half_face(a, d, b), half_face(b, d, c)});
  }

  write_file_atomically(path, [&](std::ostream& out) {
    out << "OVM ASCII\nVertices\n" << points.size() << '\n';
    for (const auto& p : points) out << format_double(p[0]) << ' ' << format_double(p[1]) << ' ' << format_double(p[2]) << '\n';
    out << "Edges\n" << edges.size() << '\n';
    for (const auto& e : edges) out << e[0] << ' ' << e[1] << '\n';
    out << "Faces\n" << faces.size() << '\n';
    for (const auto& f : faces) out << "3 " << f[0] << ' ' << f[1] << ' ' << f[2] << '\n';
    out << "Polyhedra\n" << cells.size() << '\n';
    for (const auto& c : cells) out << "4 " << c[0] << ' ' << c[1] << ' ' << c[2] << ' ' << c[3] << '\n';
    if (exact) {
      std::vector<std::string> values;
      values.reserve(exact->size());
      for (const auto& p : *exact) values.push_back(exact_text(p[0]) + ';' + exact_text(p[1]) + ';' + exact_text(p[2]));
      write_string_property(out, "str_exact_position", values);
    }
    for (const auto& prop : properties)
      if (!(exact && prop.name == "str_exact_position")) write_string_property(out, prop.name, prop.values);
  });
}

}  // namespace cmx::io
