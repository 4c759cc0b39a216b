// OpenVolumeMesh ASCII reader. Layout (see docs/formats.md): "OVM ASCII"; "Vertices" n, x y z;
// "Edges" n, v0 v1; "Faces" n, k h0..h(k-1) with half-edge h = 2*edge (+1 reversed);
// "Polyhedra" n, k f0..f(k-1) with half-face f = 2*face (+1 reversed); property blocks.
// A cell's vertex order is the first half-face's vertex cycle, then the remaining vertex.
#include <algorithm>
#include <cstdint>

#include "io/orientation.hpp"
#include "io/read_mesh.hpp"
#include "io/scanner.hpp"

namespace cmx::io {
namespace {

void expect_keyword(Scanner& s, std::string_view keyword) {
  const auto t = s.token(keyword);
  if (t != keyword) s.fail(ErrorKind::syntax, "expected '" + std::string(keyword) + "', found " + quoted(t));
}

std::uint32_t index_below(Scanner& s, std::uint64_t bound, std::string_view what) {
  const auto v = s.unsigned_integer(what);
  if (v >= bound)
    s.fail(ErrorKind::index_out_of_range,
           std::string(what) + " " + std::to_string(v) + " out of range (" + std::to_string(bound) + " available)");
  return std::uint32_t(v);
}

// Parses "x;y;z" of exact numbers; false if malformed.
bool parse_exact_position(std::string_view text, Point3& out) {
  for (int k = 0; k < 3; ++k) {
    const auto semi = text.find(';');
    if ((k < 2) != (semi != std::string_view::npos)) return false;
    auto q = parse_rational(k < 2 ? text.substr(0, semi) : text);
    if (!q) return false;
    out[std::size_t(k)] = std::move(*q);
    if (k < 2) text.remove_prefix(semi + 1);
  }
  return true;
}

// Skips or reads one property block whose header line has been read.
void read_property_block(Scanner& s, std::string_view entity, std::size_t header_line, std::uint64_t count,
                         bool keep, TetMeshData& mesh) {
  // Header: <Entity>Prop <type> "<name>"
  const auto type = s.token("property type");
  s.more_on_line();
  std::string name(s.rest_of_line());
  while (!name.empty() && (name.back() == ' ' || name.back() == '\t')) name.pop_back();
  if (name.size() < 2 || name.front() != '"' || name.back() != '"')
    s.fail_at(header_line, ErrorKind::syntax, "expected a quoted property name after '" + std::string(entity) + "'");
  name = name.substr(1, name.size() - 2);
  const bool is_string = type == "string";
  StringProperty property{name, {}};
  if (keep && is_string) property.values.reserve(plausible_count(count, s.remaining(), 3));
  for (std::uint64_t i = 0; i < count; ++i) {
    if (is_string) {
      // "<length>:<text>": the text may hold blanks, so it is read by length.
      if (!s.skip_space()) s.fail(ErrorKind::truncated, "property \"" + name + "\" ends after " + std::to_string(i) + " of " + std::to_string(count) + " values");
      const auto rest = s.data().substr(s.position());
      const auto colon = rest.find(':');
      std::uint64_t len = 0;
      if (colon == std::string_view::npos || colon == 0 || colon > 12 ||
          !std::all_of(rest.begin(), rest.begin() + std::ptrdiff_t(colon), [](char c) { return c >= '0' && c <= '9'; }))
        s.fail(ErrorKind::syntax, "expected a string value '<length>:<text>' in property \"" + name + "\"");
      for (std::size_t k = 0; k < colon; ++k) len = len * 10 + std::uint64_t(rest[k] - '0');
      s.bytes(colon + 1, "string property");
      if (len > s.remaining())
        s.fail(ErrorKind::truncated, "string value of length " + std::to_string(len) + " in property \"" + name + "\" runs past the end of the file");
      const std::size_t start = s.position();
      s.seek(start + std::size_t(len));  // seek, not bytes(): keeps line numbers right if the text has line ends
      if (keep) property.values.emplace_back(s.data().substr(start, std::size_t(len)));
    } else {
      // Other types (int, bool, double, vec3d, ...) hold one entity per line.
      if (!s.skip_space()) s.fail(ErrorKind::truncated, "property \"" + name + "\" ends after " + std::to_string(i) + " of " + std::to_string(count) + " values");
      s.skip_line();
    }
  }
  if (keep && is_string) mesh.vertex_string_properties.push_back(std::move(property));
}

using Edge = std::array<std::uint32_t, 2>;
using FaceCycle = std::array<std::uint32_t, 3>;  // a face's vertex cycle (from-vertex of each half-edge)

void read_header(Scanner& s) {
  const auto magic = s.token("'OVM ASCII'");
  if (magic != "OVM") s.fail(ErrorKind::syntax, "not an OVM file: expected 'OVM ASCII', found " + quoted(magic));
  const auto mode = s.token("'ASCII'");
  if (mode == "BINARY") s.fail(ErrorKind::unsupported, "OVM BINARY files are not supported; write OVM ASCII");
  if (mode != "ASCII") s.fail(ErrorKind::syntax, "expected 'OVM ASCII', found 'OVM " + std::string(quoted(mode)) + "'");
}

void read_vertices(Scanner& s, TetMeshData& mesh) {
  expect_keyword(s, "Vertices");
  const auto nv = s.count("vertex count", max_vertices, 6);
  mesh.positions.reserve(std::size_t(nv));
  for (std::uint64_t i = 0; i < nv; ++i) {
    Point3 p;
    p[0] = s.rational("x coordinate");
    p[1] = s.rational("y coordinate");
    p[2] = s.rational("z coordinate");
    mesh.positions.push_back(std::move(p));
  }
}

std::vector<Edge> read_edges(Scanner& s, std::uint64_t nv) {
  expect_keyword(s, "Edges");
  const auto ne = s.count("edge count", max_vertices, 4);
  std::vector<Edge> edges;
  edges.reserve(std::size_t(ne));
  for (std::uint64_t i = 0; i < ne; ++i) {
    const auto a = index_below(s, nv, "edge vertex");
    const auto b = index_below(s, nv, "edge vertex");
    if (a == b) s.fail(ErrorKind::syntax, "edge " + std::to_string(i) + " is a loop at vertex " + std::to_string(a));
    edges.push_back({a, b});
  }
  return edges;
}

std::vector<FaceCycle> read_faces(Scanner& s, const std::vector<Edge>& edges) {
  expect_keyword(s, "Faces");
  const auto nf = s.count("face count", max_tets * 4, 8);
  std::vector<FaceCycle> faces;
  faces.reserve(std::size_t(nf));
  for (std::uint64_t i = 0; i < nf; ++i) {
    const auto k = s.unsigned_integer("face size");
    if (k != 3) s.fail(ErrorKind::non_tet_cell, "face " + std::to_string(i) + " has " + std::to_string(k) + " half-edges; only triangles are supported");
    FaceCycle from{}, to{};
    for (int j = 0; j < 3; ++j) {
      const auto h = index_below(s, 2 * edges.size(), "half-edge index");
      const auto& e = edges[h / 2];
      from[std::size_t(j)] = e[h % 2];
      to[std::size_t(j)] = e[1 - h % 2];
    }
    for (int j = 0; j < 3; ++j)
      if (to[std::size_t(j)] != from[std::size_t((j + 1) % 3)])
        s.fail(ErrorKind::syntax, "face " + std::to_string(i) + ": its half-edges do not form a cycle");
    if (from[0] == from[1] || from[1] == from[2] || from[0] == from[2])
      s.fail(ErrorKind::syntax, "face " + std::to_string(i) + " repeats a vertex");
    faces.push_back(from);
  }
  return faces;
}

// The tet bounded by four half-face cycles (polyhedron i, on `line`). They must bound one
// tetrahedron consistently: every directed edge of one half-face appears reversed in another
// one, and exactly four vertices are used.
Tet tet_of_half_faces(Scanner& s, const std::array<FaceCycle, 4>& cycles, std::uint64_t i, std::size_t line) {
  Tet t{cycles[0][0], cycles[0][1], cycles[0][2], 0};
  bool found = false;
  for (const auto& c : cycles)
    for (auto v : c)
      if (v != t[0] && v != t[1] && v != t[2]) {
        if (found && v != t[3]) s.fail_at(line, ErrorKind::non_tet_cell, "polyhedron " + std::to_string(i) + " has more than four vertices");
        t[3] = v;
        found = true;
      }
  if (!found) s.fail_at(line, ErrorKind::degenerate_tet, "polyhedron " + std::to_string(i) + " has fewer than four vertices");
  std::vector<std::pair<std::uint32_t, std::uint32_t>> directed;
  for (const auto& c : cycles)
    for (std::size_t j = 0; j < 3; ++j) directed.emplace_back(c[j], c[(j + 1) % 3]);
  std::sort(directed.begin(), directed.end());
  bool closed = std::adjacent_find(directed.begin(), directed.end()) == directed.end();
  for (const auto& [a, b] : directed)
    closed = closed && std::binary_search(directed.begin(), directed.end(), std::make_pair(b, a));
  if (!closed)
    s.fail_at(line, ErrorKind::syntax, "polyhedron " + std::to_string(i) + ": its half-faces do not bound a consistently oriented tetrahedron");
  return t;
}

// The tets, and the line of each (for messages of the later validation).
std::vector<std::size_t> read_polyhedra(Scanner& s, const std::vector<FaceCycle>& faces, TetMeshData& mesh) {
  expect_keyword(s, "Polyhedra");
  const auto nc = s.count("polyhedron count", max_tets, 8);
  mesh.tets.reserve(std::size_t(nc));
  std::vector<std::size_t> tet_lines;
  tet_lines.reserve(std::size_t(nc));
  for (std::uint64_t i = 0; i < nc; ++i) {
    const auto k = s.unsigned_integer("polyhedron size");
    const std::size_t line = s.line();
    if (k != 4) s.fail(ErrorKind::non_tet_cell, "polyhedron " + std::to_string(i) + " has " + std::to_string(k) + " half-faces; only tetrahedra are supported");
    std::array<FaceCycle, 4> cycles{};
    for (std::size_t j = 0; j < 4; ++j) {
      const auto hf = index_below(s, 2 * faces.size(), "half-face index");
      auto c = faces[hf / 2];
      if (hf % 2) std::swap(c[1], c[2]);  // the opposite half-face runs the cycle backwards
      cycles[j] = c;
    }
    mesh.tets.push_back(tet_of_half_faces(s, cycles, i, line));
    tet_lines.push_back(line);
  }
  return tet_lines;
}

// Property blocks until the end; vertex string properties are kept.
void read_properties(Scanner& s, std::uint64_t nv, std::uint64_t ne, std::uint64_t nf, std::uint64_t nc, TetMeshData& mesh) {
  while (s.skip_space()) {
    const std::size_t header_line = s.line();
    const auto kind = s.token("property block");
    std::uint64_t count = 0;
    if (kind == "VProp") count = nv;
    else if (kind == "EProp") count = ne;
    else if (kind == "HEProp") count = 2 * ne;
    else if (kind == "FProp") count = nf;
    else if (kind == "HFProp") count = 2 * nf;
    else if (kind == "CProp") count = nc;
    else if (kind == "MProp") count = 1;
    else s.fail(ErrorKind::syntax, "expected a property block (VProp, EProp, ...) or the end of the file, found " + quoted(kind));
    read_property_block(s, kind, header_line, count, kind == "VProp", mesh);
  }
}

// The exact positions cmx writes beside the doubles (`str_exact_position`), replacing them.
void apply_exact_positions(TetMeshData& mesh, const std::string& name) {
  for (const auto& prop : mesh.vertex_string_properties) {
    if (prop.name != "str_exact_position") continue;
    for (std::size_t v = 0; v < prop.values.size(); ++v)
      if (!parse_exact_position(prop.values[v], mesh.positions[v]))
        throw IoError(ErrorKind::syntax, name, 0, "str_exact_position of vertex " + std::to_string(v) + " is not 'x;y;z' of exact numbers: " + quoted(prop.values[v]));
  }
}

}  // namespace

TetMeshData read_ovm(std::string_view bytes, const std::string& name, const ReadOptions& options) {
  Scanner s(bytes, name);
  TetMeshData mesh;
  read_header(s);
  read_vertices(s, mesh);
  const std::uint64_t nv = mesh.positions.size();
  const std::vector<Edge> edges = read_edges(s, nv);
  const std::vector<FaceCycle> faces = read_faces(s, edges);
  const std::vector<std::size_t> tet_lines = read_polyhedra(s, faces, mesh);
  read_properties(s, nv, edges.size(), faces.size(), mesh.tets.size(), mesh);
  if (options.use_exact_position_property) apply_exact_positions(mesh, name);
  validate_and_orient(mesh, options, name, tet_lines);
  return mesh;
}

}  // namespace cmx::io
