#include "cli/map_input.hpp"

#include "generators/boundary_shapes.hpp"
#include "arith/rounding.hpp"
#include "io/boundary.hpp"
#include "io/io_error.hpp"
#include "io/read_facets.hpp"
#include "io/read_mesh.hpp"
#include "topology/coherent_orientation.hpp"
#include "topology/complex_queries.hpp"
#include "topology/ball_check.hpp"

namespace cmx::cli {

namespace {

// Generated boundary positions (doubles, exactly) for the domain's boundary vertices; from the
// combinatorics alone when `combinatorial`.
io::BoundaryPositions generated_boundary(const io::TetMeshData& mesh, const std::string& shape,
                                         std::uint64_t seed, bool combinatorial,
                                         generators::CornerChoice corners, unsigned threads) {
  auto spec = generators::parse_boundary_shape(shape);
  if (!spec)
    throw algorithm::MapError(algorithm::MapErrorKind::invalid_input,
                              "unknown shape '" + shape + "' (tet, stiff-tet, sphere, star[:SEED])");
  if (shape.find(':') == std::string::npos) spec->seed = seed;
  spec->corners = corners;
  spec->threads = threads;
  const topology::TetMesh tm(mesh.positions.size(), mesh.tets);
  if (const auto ball = topology::check_ball(tm); !ball.ok) throw algorithm::MapError(algorithm::MapErrorKind::not_ball, ball.message);
  std::vector<std::array<double, 3>> source;  // empty: no geometry
  if (!combinatorial) source.reserve(mesh.positions.size());
  for (std::size_t i = 0; !combinatorial && i < mesh.positions.size(); ++i) {
    const auto& p = mesh.positions[i];
    source.push_back({to_double(p[0]), to_double(p[1]), to_double(p[2])});
  }
  const generators::GeneratedBoundary g = generators::generate_boundary(tm, source, *spec);
  if (!g.ok)
    throw algorithm::MapError(algorithm::MapErrorKind::invalid_input, "no valid '" + shape + "' boundary: " + g.message);
  io::BoundaryPositions b;
  b.vertices = g.vertices;
  for (const auto& p : g.positions)
    b.positions.push_back({rational_from_double(p[0]), rational_from_double(p[1]), rational_from_double(p[2])});
  return b;
}

// The tets of a ball given by its tets alone, oriented alike; positions zeros.
io::TetMeshData combinatorial_domain(const std::string& path) {
  io::TetMeshData mesh;
  if (io::is_facet_list_path(path)) {
    io::FacetList list = io::read_facet_list_file(path);
    mesh.tets = std::move(list.tets);
    mesh.positions.assign(list.vertex_count, {});
  } else {
    io::ReadOptions keep;
    keep.orientation = io::Orientation::keep;  // the positions are not the problem's
    mesh = io::read_tet_mesh(path, keep);
    for (auto& p : mesh.positions) p = {};
  }
  topology::TetMesh tm(mesh.positions.size(), mesh.tets);
  if (const auto o = topology::orient_coherently(tm); !o.ok)
    throw algorithm::MapError(algorithm::MapErrorKind::not_ball, "its tets cannot be oriented alike: " + o.message);
  mesh.tets.clear();
  for (topology::TetId t : tm.live_tets()) mesh.tets.push_back(topology::indices_of(tm.tet(t)));
  return mesh;
}

// Six times the volume the prescribed boundary encloses with the tets' orientation (exact).
Rational enclosed_volume(const io::TetMeshData& mesh, const io::BoundaryPositions& b) {
  std::vector<const cmx::Point3*> at(mesh.positions.size(), nullptr);
  for (std::size_t i = 0; i < b.vertices.size(); ++i)
    if (b.vertices[i] < at.size()) at[b.vertices[i]] = &b.positions[i];
  Rational volume;
  for (const auto& f : topology::boundary_faces(topology::TetMesh(mesh.positions.size(), mesh.tets))) {
    const cmx::Point3 *p = at[f.face[0]], *q = at[f.face[1]], *r = at[f.face[2]];
    if (!p || !q || !r) return Rational(0);  // validation names the vertex without a position
    const Rational a = (*q)[1] * (*r)[2] - (*q)[2] * (*r)[1], c = (*q)[2] * (*r)[0] - (*q)[0] * (*r)[2],
                   d = (*q)[0] * (*r)[1] - (*q)[1] * (*r)[0];
    volume += (*p)[0] * a + (*p)[1] * c + (*p)[2] * d;
  }
  return volume;
}

}  // namespace

algorithm::MapProblem load_map_problem(const std::string& domain_path, const std::string& boundary_path,
                                       const std::string& codomain_path, const std::string& shape,
                                       std::uint64_t seed, bool combinatorial,
                                       generators::CornerChoice corners, unsigned threads) {
  io::TetMeshData mesh = combinatorial ? combinatorial_domain(domain_path) : io::read_tet_mesh(domain_path);
  io::BoundaryPositions b;
  if (!boundary_path.empty()) b = io::read_boundary_positions(boundary_path, mesh.positions.size());
  else if (!codomain_path.empty()) b = io::read_boundary_positions_from_codomain(mesh, codomain_path);
  else
    b = generated_boundary(mesh, shape, seed, combinatorial, corners, threads);
  // A facet list's orientation is a convention: the prescribed boundary decides which one.
  if (combinatorial && enclosed_volume(mesh, b) < 0)
    for (auto& t : mesh.tets) std::swap(t[2], t[3]);
  algorithm::MapProblem p;
  p.tets = topology::make_tets(mesh.tets);
  p.source = std::move(mesh.positions);
  p.boundary_vertices = std::move(b.vertices);
  p.boundary_positions = std::move(b.positions);
  return p;
}

void load_initial_map(algorithm::MapProblem& p, const std::string& init_file, const std::string& codomain_path) {
  const std::size_t n = p.source.size();
  if (init_file.empty()) {
    io::ReadOptions keep;
    keep.orientation = io::Orientation::keep;
    io::TetMeshData codomain = io::read_tet_mesh(codomain_path, keep);
    if (codomain.positions.size() != n)
      throw io::IoError(io::ErrorKind::mismatch, codomain_path, 0,
                        std::to_string(codomain.positions.size()) + " vertices, the domain has " + std::to_string(n));
    p.initial_target = std::move(codomain.positions);
    return;
  }
  io::BoundaryPositions b = io::read_boundary_positions(init_file, n);
  if (b.vertices.size() != n)
    throw io::IoError(io::ErrorKind::mismatch, init_file, 0,
                      "positions for " + std::to_string(b.vertices.size()) + " of " + std::to_string(n) +
                          " vertices; an initial map needs one per vertex");
  p.initial_target.assign(n, {});
  for (std::size_t i = 0; i < n; ++i) p.initial_target[b.vertices[i]] = std::move(b.positions[i]);
}

}  // namespace cmx::cli
