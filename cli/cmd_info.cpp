// cmx info MESH [--json]: what a mesh file holds and whether it is a topological ball.
//
// Reads any format of io/read_mesh.hpp with the file's vertex order kept (no orientation
// normalisation: the orientation signs are reported instead, so that folded codomain meshes can be
// inspected). Exit 0 whenever the file was read, whatever the verdict; 3 with "file:line: message"
// on a read error; 2 on a bad command line.
//
// The ball verdict checks, in this order, and names the first failure: at least one tet; every
// vertex used by a tet; connected; every face in one or two tets; every vertex link a disc (boundary
// vertex) or a sphere (interior vertex); the boundary surface connected with Euler characteristic
// 2 (one 2-sphere); Euler characteristic 1; tets consistently oriented (exact signs, all of one
// sign, none zero). It is computed here until topology/ offers its ball validation.
#include <algorithm>
#include <cstdio>
#include <map>
#include <numeric>
#include <string>
#include <vector>

#include "arith/rounding.hpp"
#include "cli/command.hpp"
#include "io/boundary.hpp"
#include "io/io_error.hpp"
#include "io/orientation.hpp"
#include "io/read_mesh.hpp"

namespace cmx::cli {
namespace {

using io::Tet;
using io::TetMeshData;

constexpr const char* usage =
    "usage: cmx info MESH [--json]\n"
    "Prints counts (vertices, edges, faces, tets; boundary vertices, edges, faces), Euler\n"
    "characteristics, exact orientation signs, the ball verdict with its reason, valence\n"
    "histograms and the bounding box. MESH: .ovm .vtk .vtu .mesh .msh .node/.ele\n"
    "Exit status: 0 when the file was read (whatever the verdict), 3 on a read error.\n";

struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

using Edge = std::array<std::uint32_t, 2>;
using Face = std::array<std::uint32_t, 3>;

struct Summary {
  std::size_t vertices = 0, edges = 0, faces = 0, tets = 0;
  std::size_t boundary_vertices = 0, boundary_edges = 0, boundary_faces = 0, boundary_components = 0;
  std::size_t components = 0, isolated_vertices = 0;
  long euler = 0, boundary_euler = 0;
  io::OrientationCounts orientation;
  bool is_ball = false;
  std::string reason;
  std::map<std::size_t, std::size_t> vertex_valence, edge_valence;  // edges per vertex, tets per edge
  std::array<double, 3> lo{}, hi{};
};

// The link of vertex v: the triangles opposite v in its tets. A disc or a sphere iff it is
// connected, every link edge is in one or two link triangles, and V - E + F is 1 (disc, with
// boundary edges) or 2 (sphere, without).
std::string check_link(std::uint32_t v, const std::vector<Face>& link, bool on_boundary) {
  std::vector<Edge> edges;
  std::vector<std::uint32_t> verts;
  for (const auto& f : link)
    for (int i = 0; i < 3; ++i) {
      Edge e{f[std::size_t(i)], f[std::size_t((i + 1) % 3)]};
      if (e[0] > e[1]) std::swap(e[0], e[1]);
      edges.push_back(e);
      verts.push_back(f[std::size_t(i)]);
    }
  std::sort(edges.begin(), edges.end());
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  std::size_t unique_edges = 0, border = 0;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i > 2) return "the link of vertex " + std::to_string(v) + " is not a surface (an edge in " + std::to_string(j - i) + " triangles)";
    border += j - i == 1;
    ++unique_edges;
    i = j;
  }
  UnionFind uf(verts.size());
  const auto id = [&](std::uint32_t x) { return std::uint32_t(std::lower_bound(verts.begin(), verts.end(), x) - verts.begin()); };
  for (const auto& f : link) {
    uf.unite(id(f[0]), id(f[1]));
    uf.unite(id(f[1]), id(f[2]));
  }
  for (std::uint32_t i = 0; i < verts.size(); ++i)
    if (uf.find(i) != uf.find(0)) return "the link of vertex " + std::to_string(v) + " is not connected";
  const long chi = long(verts.size()) - long(unique_edges) + long(link.size());
  if (on_boundary && (border == 0 || chi != 1))
    return "the link of boundary vertex " + std::to_string(v) + " is not a disc (Euler characteristic " + std::to_string(chi) + ")";
  if (!on_boundary && (border != 0 || chi != 2))
    return "the link of interior vertex " + std::to_string(v) + " is not a sphere (Euler characteristic " + std::to_string(chi) + ")";
  return "";
}

Summary summarise(const TetMeshData& mesh) {
  Summary s;
  s.vertices = mesh.positions.size();
  s.tets = mesh.tets.size();
  std::vector<Edge> edges;
  std::vector<Face> faces;
  edges.reserve(6 * s.tets);
  faces.reserve(4 * s.tets);
  for (const auto& t : mesh.tets) {
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) edges.push_back({std::min(t[std::size_t(i)], t[std::size_t(j)]), std::max(t[std::size_t(i)], t[std::size_t(j)])});
    for (int i = 0; i < 4; ++i) {
      Face f{};
      std::size_t k = 0;
      for (int j = 0; j < 4; ++j)
        if (j != i) f[k++] = t[std::size_t(j)];
      std::sort(f.begin(), f.end());
      faces.push_back(f);
    }
  }
  std::sort(edges.begin(), edges.end());
  std::sort(faces.begin(), faces.end());
  std::vector<std::size_t> vertex_edges(s.vertices, 0);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    ++s.edge_valence[j - i];
    ++vertex_edges[edges[i][0]];
    ++vertex_edges[edges[i][1]];
    ++s.edges;
    i = j;
  }
  std::string face_problem;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i;
    while (j < faces.size() && faces[j] == faces[i]) ++j;
    if (j - i > 2 && face_problem.empty())
      face_problem = "face (" + std::to_string(faces[i][0]) + ", " + std::to_string(faces[i][1]) + ", " + std::to_string(faces[i][2]) +
                     ") is in " + std::to_string(j - i) + " tets";
    ++s.faces;
    i = j;
  }
  for (auto n : vertex_edges) ++s.vertex_valence[n];
  s.isolated_vertices = s.vertex_valence.count(0) ? s.vertex_valence[0] : 0;
  s.euler = long(s.vertices) - long(s.edges) + long(s.faces) - long(s.tets);

  UnionFind uf(s.vertices);
  for (const auto& t : mesh.tets)
    for (int i = 1; i < 4; ++i) uf.unite(t[0], t[std::size_t(i)]);
  std::vector<bool> used(s.vertices, false);
  for (const auto& t : mesh.tets)
    for (auto v : t) used[v] = true;
  for (std::uint32_t v = 0; v < s.vertices; ++v) s.components += used[v] && uf.find(v) == v;

  io::MeshBoundary boundary;
  if (face_problem.empty()) boundary = io::mesh_boundary(mesh);
  s.boundary_faces = boundary.faces.size();
  s.boundary_vertices = boundary.vertices.size();
  {
    std::vector<Edge> be;
    for (const auto& f : boundary.faces)
      for (int i = 0; i < 3; ++i) be.push_back({std::min(f[std::size_t(i)], f[std::size_t((i + 1) % 3)]), std::max(f[std::size_t(i)], f[std::size_t((i + 1) % 3)])});
    std::sort(be.begin(), be.end());
    s.boundary_edges = std::size_t(std::unique(be.begin(), be.end()) - be.begin());
    UnionFind buf(s.vertices);
    for (const auto& f : boundary.faces) {
      buf.unite(f[0], f[1]);
      buf.unite(f[1], f[2]);
    }
    for (auto v : boundary.vertices) s.boundary_components += buf.find(v) == v;
  }
  s.boundary_euler = long(s.boundary_vertices) - long(s.boundary_edges) + long(s.boundary_faces);
  s.orientation = io::count_orientations(mesh);

  if (!mesh.positions.empty()) {
    for (int k = 0; k < 3; ++k) {
      Rational lo = mesh.positions[0][std::size_t(k)], hi = lo;
      for (const auto& p : mesh.positions) {
        if (p[std::size_t(k)] < lo) lo = p[std::size_t(k)];
        if (p[std::size_t(k)] > hi) hi = p[std::size_t(k)];
      }
      s.lo[std::size_t(k)] = to_double(lo, Round::downward);
      s.hi[std::size_t(k)] = to_double(hi, Round::upward);
    }
  }

  // The ball verdict: the first failed condition is the reason.
  const auto verdict = [&]() -> std::string {
    if (s.tets == 0) return "the mesh has no tetrahedra";
    if (s.isolated_vertices) return std::to_string(s.isolated_vertices) + " vertices are in no tet";
    if (s.components != 1) return "the mesh has " + std::to_string(s.components) + " connected components";
    if (!face_problem.empty()) return "not a manifold: " + face_problem;
    std::vector<std::vector<Face>> links(s.vertices);
    for (const auto& t : mesh.tets)
      for (int i = 0; i < 4; ++i) {
        Face f{};
        std::size_t k = 0;
        for (int j = 0; j < 4; ++j)
          if (j != i) f[k++] = t[std::size_t(j)];
        links[t[std::size_t(i)]].push_back(f);
      }
    std::vector<bool> on_boundary(s.vertices, false);
    for (auto v : boundary.vertices) on_boundary[v] = true;
    for (std::uint32_t v = 0; v < s.vertices; ++v)
      if (auto why = check_link(v, links[v], on_boundary[v]); !why.empty()) return "not a manifold: " + why;
    if (s.boundary_components != 1) return "the boundary has " + std::to_string(s.boundary_components) + " components (a ball has one)";
    if (s.boundary_euler != 2) return "the boundary is not a sphere (Euler characteristic " + std::to_string(s.boundary_euler) + ")";
    if (s.euler != 1) return "Euler characteristic " + std::to_string(s.euler) + " (a ball has 1)";
    if (s.orientation.zero) return "tet " + std::to_string(s.orientation.first_zero) + " has zero volume";
    if (s.orientation.positive && s.orientation.negative) {
      const bool neg_minority = s.orientation.negative <= s.orientation.positive;
      return "inconsistent orientation: tet " + std::to_string(neg_minority ? s.orientation.first_negative : s.orientation.first_positive) +
             " is " + (neg_minority ? "negatively" : "positively") + " oriented, unlike most tets";
    }
    return "";
  }();
  s.is_ball = verdict.empty();
  s.reason = s.is_ball ? "connected 3-manifold with one sphere as boundary, Euler characteristic 1, consistently oriented" : verdict;
  return s;
}

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (unsigned char c : text) {
    if (c == '"' || c == '\\') out += '\\', out += char(c);
    else if (c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else out += char(c);
  }
  return out + "\"";
}

std::string histogram_json(const std::map<std::size_t, std::size_t>& h) {
  std::string out = "{";
  for (const auto& [k, n] : h) out += (out.size() > 1 ? ", " : "") + json_string(std::to_string(k)) + ": " + std::to_string(n);
  return out + "}";
}

std::string histogram_text(const std::map<std::size_t, std::size_t>& h) {
  std::string out;
  for (const auto& [k, n] : h) {
    out += ' ';  // appended piecewise: g++ 12 warns (-Wrestrict, a false positive) on " " + std::string
    out += std::to_string(k);
    out += ':';
    out += std::to_string(n);
  }
  return out;
}

int run(const std::vector<std::string>& args) {
  std::string path;
  bool json = false;
  for (const auto& a : args) {
    if (a == "--help" || a == "-h") {
      std::fputs(usage, stdout);
      return exit_ok;
    }
    if (a == "--json") json = true;
    else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "cmx info: unknown option '%s'\n%s", a.c_str(), usage);
      return exit_usage;
    } else if (path.empty()) path = a;
    else {
      std::fprintf(stderr, "cmx info: more than one MESH given\n%s", usage);
      return exit_usage;
    }
  }
  if (path.empty()) {
    std::fputs(usage, stderr);
    return exit_usage;
  }
  TetMeshData mesh;
  try {
    io::ReadOptions keep;
    keep.orientation = io::Orientation::keep;
    mesh = io::read_tet_mesh(path, keep);
  } catch (const io::IoError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return exit_bad_input;
  }
  const Summary s = summarise(mesh);
  const auto& o = s.orientation;
  if (json) {
    std::printf("{\"file\": %s, \"vertices\": %zu, \"edges\": %zu, \"faces\": %zu, \"tets\": %zu,\n", json_string(path).c_str(), s.vertices,
                s.edges, s.faces, s.tets);
    std::printf(" \"boundary_vertices\": %zu, \"boundary_edges\": %zu, \"boundary_faces\": %zu, \"boundary_components\": %zu,\n",
                s.boundary_vertices, s.boundary_edges, s.boundary_faces, s.boundary_components);
    std::printf(" \"interior_vertices\": %zu, \"isolated_vertices\": %zu, \"components\": %zu,\n", s.vertices - s.boundary_vertices - s.isolated_vertices,
                s.isolated_vertices, s.components);
    std::printf(" \"euler_characteristic\": %ld, \"boundary_euler_characteristic\": %ld,\n", s.euler, s.boundary_euler);
    std::printf(" \"orientation\": {\"positive\": %zu, \"negative\": %zu, \"zero\": %zu},\n", o.positive, o.negative, o.zero);
    std::printf(" \"is_ball\": %s, \"reason\": %s,\n", s.is_ball ? "true" : "false", json_string(s.reason).c_str());
    std::printf(" \"vertex_valence_histogram\": %s,\n \"edge_valence_histogram\": %s,\n", histogram_json(s.vertex_valence).c_str(),
                histogram_json(s.edge_valence).c_str());
    std::printf(" \"bounding_box\": {\"min\": [%.17g, %.17g, %.17g], \"max\": [%.17g, %.17g, %.17g]}}\n", s.lo[0], s.lo[1], s.lo[2], s.hi[0],
                s.hi[1], s.hi[2]);
  } else {
    std::printf("file: %s\n", path.c_str());
    std::printf("vertices %zu, edges %zu, faces %zu, tets %zu\n", s.vertices, s.edges, s.faces, s.tets);
    std::printf("boundary: vertices %zu, edges %zu, faces %zu, components %zu; interior vertices %zu; isolated vertices %zu\n",
                s.boundary_vertices, s.boundary_edges, s.boundary_faces, s.boundary_components,
                s.vertices - s.boundary_vertices - s.isolated_vertices, s.isolated_vertices);
    std::printf("Euler characteristic %ld (boundary %ld), connected components %zu\n", s.euler, s.boundary_euler, s.components);
    std::printf("orientation det[b-a,c-a,d-a]: %zu positive, %zu negative, %zu zero\n", o.positive, o.negative, o.zero);
    std::printf("ball: %s (%s)\n", s.is_ball ? "yes" : "no", s.reason.c_str());
    std::printf("vertex valence (edges per vertex):%s\n", histogram_text(s.vertex_valence).c_str());
    std::printf("edge valence (tets per edge):%s\n", histogram_text(s.edge_valence).c_str());
    std::printf("bounding box: [%.17g, %.17g] x [%.17g, %.17g] x [%.17g, %.17g]\n", s.lo[0], s.hi[0], s.lo[1], s.hi[1], s.lo[2], s.hi[2]);
  }
  return exit_ok;
}

[[maybe_unused]] const bool registered = register_command({"info", "counts, Euler characteristics and ball verdict of a mesh file", &run});

}  // namespace
}  // namespace cmx::cli
