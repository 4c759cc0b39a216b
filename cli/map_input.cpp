#include "cli/map_input.hpp"

#include "io/boundary.hpp"
#include "io/read_mesh.hpp"

namespace cmx::cli {

algorithm::MapProblem load_map_problem(const std::string& domain_path, const std::string& boundary_path,
                                       const std::string& codomain_path, const std::string& shape, std::uint64_t seed) {
  io::TetMeshData mesh = io::read_tet_mesh(domain_path);
  io::BoundaryPositions b;
  if (!boundary_path.empty()) b = io::read_boundary_positions(boundary_path, mesh.positions.size());
  else if (!codomain_path.empty()) b = io::read_boundary_positions_from_codomain(mesh, codomain_path);
  else {
    (void)seed;
    throw algorithm::MapError(algorithm::MapErrorKind::invalid_input, "--shape " + shape + " is not available yet");
  }
  algorithm::MapProblem p;
  p.tets = std::move(mesh.tets);
  p.source = std::move(mesh.positions);
  p.boundary_vertices = std::move(b.vertices);
  p.boundary_positions = std::move(b.positions);
  return p;
}

}  // namespace cmx::cli
