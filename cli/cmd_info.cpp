// cmx info MESH [--json]: what a mesh file holds, whether it is a topological ball, and whether
// its geometry orients every tet alike.
//
// Reads any format of io/read_mesh.hpp with the file's vertex order kept (no orientation
// normalisation: the orientation signs are reported instead, so that folded codomain meshes and
// placeholder coordinates can be inspected). The ball verdict is topology::check_ball on the tets
// as listed: topology alone (combinatorial orientation across faces, manifold edges and vertices,
// vertex links, Euler characteristics, one boundary sphere), no coordinates. The geometric
// verdict is separate: the exact sign of every tet, `consistent` when all have one sign.
#include <algorithm>
#include <cstdio>
#include <map>
#include <numeric>
#include <string>
#include <vector>

#include "arith/rounding.hpp"
#include "cli/command.hpp"
#include "cli/command_line.hpp"
#include "cli/json.hpp"
#include "cli/mesh_input.hpp"
#include "cmx_version.hpp"
#include "io/boundary.hpp"
#include "io/orientation.hpp"
#include "io/read_facets.hpp"
#include "topology/ball_check.hpp"
#include "topology/coherent_orientation.hpp"
#include "topology/union_find.hpp"

namespace cmx::cli::info_command {
using topology::UnionFind;
namespace {

using io::TetMeshData;

const HelpText help = {
    "usage: cmx info MESH [--json] [--source | --facets]\n",
    "Prints counts (vertices, edges, faces, tets; boundary vertices, edges, faces), Euler\n"
    "characteristics, the ball verdict with its reason, the exact orientation signs with their\n"
    "verdict, valence histograms and the bounding box.\n"
    "The ball verdict is topology alone (topology::check_ball on the tets as listed: tets that share a\n"
    "face list it in opposite orders, every edge and vertex manifold, vertex links discs or spheres,\n"
    "Euler characteristic 1, the boundary one 2-sphere); coordinates play no part. The orientation\n"
    "verdict is the geometry: consistent (every tet of one sign), inverted tets (both signs; the\n"
    "minority counts as inverted) or flat tets (some of zero volume, whatever the others). A ball\n"
    "given with placeholder coordinates is a ball whose orientation is not consistent.\n"
    "A map (.tmap, as cmx map writes it) is described by its target geometry, or with --source by\n"
    "its source geometry; the tets are read as stored, so the verdicts check the map.\n"
    "A facet list (a .facets file, or any file with --facets: four vertex ids per tet, plain or\n"
    "[[a,b,c,d],...], docs/formats.md) has no coordinates: its tets are first oriented alike\n"
    "(topology::orient_coherently), then the counts and the ball verdict follow; the orientation line\n"
    "says whether they could be, and there is no bounding box.\n",
    "Exit status: 0 when the file was read (whatever the verdicts); 2 bad command line; 3 unreadable\n"
    "or malformed file (a directory, a missing file: the reason is given).\n"};

using Edge = std::array<std::uint32_t, 2>;
using Face = std::array<std::uint32_t, 3>;

// The geometric verdict: the exact sign of every tet as listed.
struct Orientation {
  io::OrientationCounts counts;
  std::string verdict;                    // consistent, inverted tets, flat tets
  std::size_t inverted = 0;               // tets of the minority sign (negative on a tie)
  std::size_t first_inverted = SIZE_MAX;  // SIZE_MAX: none
};

struct Summary {
  std::size_t vertices = 0, edges = 0, faces = 0, tets = 0;
  std::size_t boundary_vertices = 0, boundary_edges = 0, boundary_faces = 0, boundary_components = 0;
  std::size_t components = 0, isolated_vertices = 0;
  long euler = 0, boundary_euler = 0;
  bool face_in_three_tets = false;  // then there is no boundary surface to count
  Orientation orientation;
  bool is_ball = false;
  std::string reason;
  std::map<std::size_t, std::size_t> vertex_valence, edge_valence;  // edges per vertex, tets per edge
  std::array<double, 3> lo{}, hi{};
};

Edge edge(std::uint32_t a, std::uint32_t b) { return {std::min(a, b), std::max(a, b)}; }

// Edges, faces, valences, isolated vertices and the Euler characteristic.
void count_simplices(const TetMeshData& mesh, Summary& s) {
  std::vector<Edge> edges;
  std::vector<Face> faces;
  edges.reserve(6 * s.tets);
  faces.reserve(4 * s.tets);
  for (const auto& t : mesh.tets) {
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = i + 1; j < 4; ++j) edges.push_back(edge(t[i], t[j]));
    for (std::size_t skip = 0; skip < 4; ++skip) {
      Face f{};
      for (std::size_t j = 0, k = 0; j < 4; ++j)
        if (j != skip) f[k++] = t[j];
      std::sort(f.begin(), f.end());
      faces.push_back(f);
    }
  }
  std::sort(edges.begin(), edges.end());
  std::sort(faces.begin(), faces.end());
  std::vector<std::size_t> vertex_edges(s.vertices, 0);
  for (std::size_t i = 0, j = 0; i < edges.size(); i = j) {
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    ++s.edge_valence[j - i];
    ++vertex_edges[edges[i][0]];
    ++vertex_edges[edges[i][1]];
    ++s.edges;
  }
  for (std::size_t i = 0, j = 0; i < faces.size(); i = j) {
    while (j < faces.size() && faces[j] == faces[i]) ++j;
    s.face_in_three_tets |= j - i > 2;
    ++s.faces;
  }
  for (auto n : vertex_edges) ++s.vertex_valence[n];
  s.isolated_vertices = s.vertex_valence.count(0) ? s.vertex_valence[0] : 0;
  s.euler = long(s.vertices) - long(s.edges) + long(s.faces) - long(s.tets);
}

// Connected components of the used vertices (through tets).
std::size_t count_components(const TetMeshData& mesh) {
  UnionFind uf(mesh.positions.size());
  std::vector<bool> used(mesh.positions.size(), false);
  for (const auto& t : mesh.tets)
    for (std::size_t i = 0; i < 4; ++i) {
      uf.unite(t[0], t[i]);
      used[t[i]] = true;
    }
  std::size_t components = 0;
  for (std::uint32_t v = 0; v < used.size(); ++v) components += used[v] && uf.find(v) == v;
  return components;
}

// The boundary surface: faces in one tet, its edges, vertices, components and Euler characteristic.
void count_boundary(const TetMeshData& mesh, Summary& s) {
  if (s.face_in_three_tets) return;
  const io::MeshBoundary boundary = io::mesh_boundary(mesh);
  s.boundary_faces = boundary.faces.size();
  s.boundary_vertices = boundary.vertices.size();
  std::vector<Edge> edges;
  UnionFind uf(s.vertices);
  for (const auto& f : boundary.faces)
    for (std::size_t i = 0; i < 3; ++i) {
      edges.push_back(edge(f[i], f[(i + 1) % 3]));
      uf.unite(f[i], f[(i + 1) % 3]);
    }
  std::sort(edges.begin(), edges.end());
  s.boundary_edges = std::size_t(std::unique(edges.begin(), edges.end()) - edges.begin());
  for (auto v : boundary.vertices) s.boundary_components += uf.find(v) == v;
  s.boundary_euler = long(s.boundary_vertices) - long(s.boundary_edges) + long(s.boundary_faces);
}

void bounding_box(const TetMeshData& mesh, Summary& s) {
  if (mesh.positions.empty()) return;
  for (std::size_t k = 0; k < 3; ++k) {
    Rational lo = mesh.positions[0][k], hi = lo;
    for (const auto& p : mesh.positions) {
      if (p[k] < lo) lo = p[k];
      if (p[k] > hi) hi = p[k];
    }
    s.lo[k] = to_double(lo, Round::downward);
    s.hi[k] = to_double(hi, Round::upward);
  }
}

Orientation orientation_of(const TetMeshData& mesh) {
  Orientation o;
  o.counts = io::count_orientations(mesh);
  const auto& c = o.counts;
  const bool negative_minority = c.negative <= c.positive;
  o.inverted = std::min(c.positive, c.negative);
  if (o.inverted) o.first_inverted = negative_minority ? c.first_negative : c.first_positive;
  o.verdict = c.zero ? "flat tets" : o.inverted ? "inverted tets" : "consistent";
  return o;
}

const char* const ball_reason = "connected 3-manifold whose boundary is one 2-sphere, Euler characteristic 1";

// What depends on the tets alone: the counts, components and the boundary surface.
Summary count_complex(const TetMeshData& mesh) {
  Summary s;
  s.vertices = mesh.positions.size();
  s.tets = mesh.tets.size();
  count_simplices(mesh, s);
  s.components = count_components(mesh);
  count_boundary(mesh, s);
  return s;
}

Summary summarise(const TetMeshData& mesh) {
  Summary s = count_complex(mesh);
  bounding_box(mesh, s);
  s.orientation = orientation_of(mesh);
  const topology::BallVerdict ball = topology::check_ball(topology::TetMesh(s.vertices, mesh.tets));
  s.is_ball = ball.ok;
  s.reason = ball.ok ? ball_reason : ball.message;
  return s;
}

std::string histogram_json(const std::map<std::size_t, std::size_t>& h) {
  std::string out = "{";
  for (const auto& [k, n] : h) out += (out.size() > 1 ? ", " : "") + json_quote(std::to_string(k)) + ": " + std::to_string(n);
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

std::string orientation_json(const Orientation& o) {
  const auto& c = o.counts;
  std::string out = "{\"positive\": " + std::to_string(c.positive) + ", \"negative\": " + std::to_string(c.negative) +
                    ", \"zero\": " + std::to_string(c.zero) + ", \"verdict\": " + json_quote(o.verdict) +
                    ", \"inverted\": " + std::to_string(o.inverted) + ", \"flat\": " + std::to_string(c.zero);
  if (o.inverted) out += ", \"first_inverted\": " + std::to_string(o.first_inverted);
  if (c.zero) out += ", \"first_flat\": " + std::to_string(c.first_zero);
  return out + "}";
}

// A facet list's counts and ball verdict, on its tets oriented alike (no coordinates: the
// orientation reported is whether that was possible).
struct FacetSummary {
  Summary counts;
  io::FacetList list;
  topology::CoherentOrientation orientation;
};

FacetSummary summarise_facets(io::FacetList list) {
  FacetSummary f;
  topology::TetMesh mesh(list.vertex_count, std::span<const topology::TetIndices>(list.tets));
  f.orientation = topology::orient_coherently(mesh);
  TetMeshData data;  // the counts read the tets and the vertex count only
  data.positions.resize(list.vertex_count);
  for (topology::TetId t : mesh.live_tets()) data.tets.push_back(topology::indices_of(mesh.tet(t)));
  f.counts = count_complex(data);
  Summary& s = f.counts;
  const topology::BallVerdict ball = topology::check_ball(mesh);
  s.is_ball = f.orientation.ok && ball.ok;
  s.reason = !f.orientation.ok ? f.orientation.message : ball.ok ? ball_reason : ball.message;
  f.list = std::move(list);
  return f;
}

void print_facets_json(const std::string& path, const FacetSummary& f) {
  const Summary& s = f.counts;
  std::printf("{\"cmx_version\": %s, \"file\": %s, \"facet_list\": true, \"numbered_from\": %d, \"label\": %s,\n",
              json_quote(cmx_version).c_str(), json_quote(path).c_str(), f.list.one_based ? 1 : 0,
              json_quote(f.list.label).c_str());
  std::printf(" \"vertices\": %zu, \"edges\": %zu, \"faces\": %zu, \"tets\": %zu,\n", s.vertices, s.edges, s.faces, s.tets);
  std::printf(" \"boundary_vertices\": %zu, \"boundary_edges\": %zu, \"boundary_faces\": %zu, \"boundary_components\": %zu,\n",
              s.boundary_vertices, s.boundary_edges, s.boundary_faces, s.boundary_components);
  std::printf(" \"interior_vertices\": %zu, \"components\": %zu,\n", s.vertices - s.boundary_vertices - s.isolated_vertices,
              s.components);
  std::printf(" \"euler_characteristic\": %ld, \"boundary_euler_characteristic\": %ld,\n", s.euler, s.boundary_euler);
  std::printf(" \"is_ball\": %s, \"reason\": %s,\n", s.is_ball ? "true" : "false", json_quote(s.reason).c_str());
  std::printf(" \"orientation\": {\"coherent\": %s, \"turned\": %zu},\n", f.orientation.ok ? "true" : "false",
              f.orientation.flipped);
  std::printf(" \"vertex_valence_histogram\": %s,\n \"edge_valence_histogram\": %s}\n", histogram_json(s.vertex_valence).c_str(),
              histogram_json(s.edge_valence).c_str());
}

void print_facets_text(const std::string& path, const FacetSummary& f) {
  const Summary& s = f.counts;
  std::printf("file: %s\n", path.c_str());
  std::printf("facet list%s%s: ids numbered from %d%s, no coordinates\n", f.list.label.empty() ? "" : " ",
              f.list.label.c_str(), f.list.one_based ? 1 : 0,
              f.list.one_based ? " (named below from 0: the file's id minus 1)" : "");
  std::printf("vertices %zu, edges %zu, faces %zu, tets %zu\n", s.vertices, s.edges, s.faces, s.tets);
  std::printf("boundary: vertices %zu, edges %zu, faces %zu, components %zu; interior vertices %zu\n", s.boundary_vertices,
              s.boundary_edges, s.boundary_faces, s.boundary_components, s.vertices - s.boundary_vertices - s.isolated_vertices);
  std::printf("Euler characteristic %ld (boundary %ld), connected components %zu\n", s.euler, s.boundary_euler, s.components);
  std::printf("ball: %s (%s)\n", s.is_ball ? "yes" : "no", s.reason.c_str());
  if (f.orientation.ok)
    std::printf("orientation: the tets can be oriented alike (%zu of %zu turned)\n", f.orientation.flipped, s.tets);
  else
    std::printf("orientation: the tets cannot be oriented alike (%s)\n", f.orientation.message.c_str());
  std::printf("vertex valence (edges per vertex):%s\n", histogram_text(s.vertex_valence).c_str());
  std::printf("edge valence (tets per edge):%s\n", histogram_text(s.edge_valence).c_str());
}

void print_json(const std::string& path, const Summary& s) {
  std::printf("{\"cmx_version\": %s, \"file\": %s,\n", json_quote(cmx_version).c_str(), json_quote(path).c_str());
  std::printf(" \"vertices\": %zu, \"edges\": %zu, \"faces\": %zu, \"tets\": %zu,\n", s.vertices, s.edges, s.faces, s.tets);
  std::printf(" \"boundary_vertices\": %zu, \"boundary_edges\": %zu, \"boundary_faces\": %zu, \"boundary_components\": %zu,\n",
              s.boundary_vertices, s.boundary_edges, s.boundary_faces, s.boundary_components);
  std::printf(" \"interior_vertices\": %zu, \"isolated_vertices\": %zu, \"components\": %zu,\n",
              s.vertices - s.boundary_vertices - s.isolated_vertices, s.isolated_vertices, s.components);
  std::printf(" \"euler_characteristic\": %ld, \"boundary_euler_characteristic\": %ld,\n", s.euler, s.boundary_euler);
  std::printf(" \"is_ball\": %s, \"reason\": %s,\n", s.is_ball ? "true" : "false", json_quote(s.reason).c_str());
  std::printf(" \"orientation\": %s,\n", orientation_json(s.orientation).c_str());
  std::printf(" \"vertex_valence_histogram\": %s,\n \"edge_valence_histogram\": %s,\n", histogram_json(s.vertex_valence).c_str(),
              histogram_json(s.edge_valence).c_str());
  std::printf(" \"bounding_box\": {\"min\": [%s, %s, %s], \"max\": [%s, %s, %s]}}\n", json_number(s.lo[0]).c_str(),
              json_number(s.lo[1]).c_str(), json_number(s.lo[2]).c_str(), json_number(s.hi[0]).c_str(),
              json_number(s.hi[1]).c_str(), json_number(s.hi[2]).c_str());
}

std::string orientation_text(const Orientation& o) {
  const auto& c = o.counts;
  std::string text = o.verdict + " (" + std::to_string(c.positive) + " positive, " + std::to_string(c.negative) +
                     " negative, " + std::to_string(c.zero) + " zero";
  if (c.zero) text += "; first flat: tet " + std::to_string(c.first_zero);
  if (o.inverted) text += "; first of the " + std::to_string(o.inverted) + " inverted: tet " + std::to_string(o.first_inverted);
  return text + ")";
}

void print_text(const std::string& path, const Summary& s) {
  std::printf("file: %s\n", path.c_str());
  std::printf("vertices %zu, edges %zu, faces %zu, tets %zu\n", s.vertices, s.edges, s.faces, s.tets);
  std::printf("boundary: vertices %zu, edges %zu, faces %zu, components %zu; interior vertices %zu; isolated vertices %zu\n",
              s.boundary_vertices, s.boundary_edges, s.boundary_faces, s.boundary_components,
              s.vertices - s.boundary_vertices - s.isolated_vertices, s.isolated_vertices);
  std::printf("Euler characteristic %ld (boundary %ld), connected components %zu\n", s.euler, s.boundary_euler, s.components);
  std::printf("ball: %s (%s)\n", s.is_ball ? "yes" : "no", s.reason.c_str());
  std::printf("orientation det[b-a,c-a,d-a]: %s\n", orientation_text(s.orientation).c_str());
  std::printf("vertex valence (edges per vertex):%s\n", histogram_text(s.vertex_valence).c_str());
  std::printf("edge valence (tets per edge):%s\n", histogram_text(s.edge_valence).c_str());
  std::printf("bounding box: [%.17g, %.17g] x [%.17g, %.17g] x [%.17g, %.17g]\n", s.lo[0], s.hi[0], s.lo[1], s.hi[1], s.lo[2], s.hi[2]);
}

int run(const std::vector<std::string>& args) {
  std::string path;
  bool json = false, source = false, facets = false;
  CommandLine line("info", help);
  line.app()
      .add_option("MESH", path, "the mesh file: .ovm .vtk .vtu .mesh .msh .node/.ele, or a map .tmap")
      ->required()
      ->type_name("");
  line.app().add_flag("--json", json, "one JSON object on stdout (with cmx_version)");
  line.app().add_flag("--source", source, "of a .tmap: describe its source geometry (default: its target)");
  line.app().add_flag("--facets", facets, "read MESH as a facet list (as a .facets file is read anyway)");
  line.quiet_flag()->description("accepted for uniformity: info prints only its results");
  if (const auto done = line.parse(args)) return *done;
  io::ReadOptions keep;
  keep.orientation = io::Orientation::keep;
  if (source && !io::is_map_path(path)) usage_error("--source applies to a map (.tmap) only");
  if (facets || io::is_facet_list_path(path)) {
    const FacetSummary f = summarise_facets(io::read_facet_list_file(path));
    if (json) print_facets_json(path, f);
    else print_facets_text(path, f);
    return exit_ok;
  }
  const TetMeshData mesh = read_mesh_or_map(path, source ? io::MapGeometry::source : io::MapGeometry::target, keep);
  const Summary s = summarise(mesh);
  if (json) print_json(path, s);
  else print_text(path, s);
  return exit_ok;
}

[[maybe_unused]] const bool registered =
    register_command({"info", "counts, Euler characteristics, ball and orientation verdicts of a mesh file", &run});

}  // namespace
}  // namespace cmx::cli::info_command
