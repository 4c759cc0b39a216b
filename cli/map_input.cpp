#include "cli/map_input.hpp"

#include "algorithm/boundary_shapes.hpp"
#include "arith/rounding.hpp"
#include "io/boundary.hpp"
#include "io/read_mesh.hpp"
#include "topology/ball_check.hpp"

namespace cmx::cli {

namespace {

// Generated boundary positions (doubles, exactly) for the domain's boundary vertices.
io::BoundaryPositions generated_boundary(const io::TetMeshData& mesh, const std::string& shape, std::uint64_t seed) {
  auto spec = algorithm::parse_boundary_shape(shape);
  if (!spec)
    throw algorithm::MapError(algorithm::MapErrorKind::invalid_input,
                              "unknown shape '" + shape + "' (tet, stiff-tet, sphere, star[:SEED])");
  if (shape.find(':') == std::string::npos) spec->seed = seed;
  const topology::TetMesh tm(mesh.positions.size(), mesh.tets);
  if (const auto ball = topology::check_ball(tm); !ball.ok) throw algorithm::MapError(algorithm::MapErrorKind::not_ball, ball.message);
  std::vector<std::array<double, 3>> source;
  source.reserve(mesh.positions.size());
  for (const auto& p : mesh.positions) source.push_back({to_double(p[0]), to_double(p[1]), to_double(p[2])});
  const algorithm::GeneratedBoundary g = algorithm::generate_boundary(tm, source, *spec);
  if (!g.ok)
    throw algorithm::MapError(algorithm::MapErrorKind::invalid_input, "no valid '" + shape + "' boundary: " + g.message);
  io::BoundaryPositions b;
  b.vertices = g.vertices;
  for (const auto& p : g.positions)
    b.positions.push_back({rational_from_double(p[0]), rational_from_double(p[1]), rational_from_double(p[2])});
  return b;
}

}  // namespace

algorithm::MapProblem load_map_problem(const std::string& domain_path, const std::string& boundary_path,
                                       const std::string& codomain_path, const std::string& shape, std::uint64_t seed) {
  io::TetMeshData mesh = io::read_tet_mesh(domain_path);
  io::BoundaryPositions b;
  if (!boundary_path.empty()) b = io::read_boundary_positions(boundary_path, mesh.positions.size());
  else if (!codomain_path.empty()) b = io::read_boundary_positions_from_codomain(mesh, codomain_path);
  else b = generated_boundary(mesh, shape, seed);
  algorithm::MapProblem p;
  p.tets = std::move(mesh.tets);
  p.source = std::move(mesh.positions);
  p.boundary_vertices = std::move(b.vertices);
  p.boundary_positions = std::move(b.positions);
  return p;
}

}  // namespace cmx::cli
