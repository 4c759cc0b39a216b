#pragma once
// Mapping problems built from the project's own generators (no data written by others): domains
// from generators/domain_generators.hpp or TetGen balls, boundaries from the four generated shapes.
#include <doctest/doctest.h>

#include <array>
#include <string>
#include <vector>

#include "generators/boundary_shapes.hpp"
#include "generators/domain_generators.hpp"
#include "algorithm/embedding.hpp"
#include "algorithm/map.hpp"
#include "arith/rational.hpp"
#include "arith/rounding.hpp"
#include "topology/complex_queries.hpp"

namespace cmx::test {

inline algorithm::MapProblem problem_from(const topology::TetMesh& mesh,
                                          const std::vector<cmx::Point3>& source,
                                          const std::vector<std::array<double, 3>>& source_doubles,
                                          const std::string& shape) {
  const auto spec = generators::parse_boundary_shape(shape);
  REQUIRE(spec);
  const generators::GeneratedBoundary b = generators::generate_boundary(mesh, source_doubles, *spec);
  REQUIRE_MESSAGE(b.ok, b.message);
  algorithm::MapProblem p;
  for (topology::TetId t : mesh.live_tets()) p.tets.push_back(mesh.tet(t));
  p.source = source;
  p.boundary_vertices = b.vertices;
  for (const auto& q : b.positions)
    p.boundary_positions.push_back(
        {rational_from_double(q[0]), rational_from_double(q[1]), rational_from_double(q[2])});
  return p;
}

inline algorithm::MapProblem problem_from(const generators::GeneratedDomain& d, const std::string& shape) {
  return problem_from(d.mesh, d.positions, d.double_positions(), shape);
}

inline algorithm::MapProblem problem_from(const topology::TetMesh& mesh,
                                          const std::vector<std::array<double, 3>>& pos,
                                          const std::string& shape) {
  std::vector<cmx::Point3> exact;
  for (const auto& q : pos)
    exact.push_back({rational_from_double(q[0]), rational_from_double(q[1]), rational_from_double(q[2])});
  return problem_from(mesh, exact, pos, shape);
}

// The live tets' vertex tuples, in handle order (a refused edit must leave exactly these).
inline std::vector<topology::Tet> live_tet_tuples(const algorithm::Embedding& e) {
  std::vector<topology::Tet> out;
  for (topology::TetId t : e.mesh.live_tets()) out.push_back(e.mesh.tet(t));
  return out;
}

// The mesh's own boundary positions as the prescribed boundary (a trivially valid problem when
// the domain is star-shaped around its kernel).
inline algorithm::MapProblem identity_problem(const generators::GeneratedDomain& d) {
  algorithm::MapProblem p;
  for (topology::TetId t : d.mesh.live_tets()) p.tets.push_back(d.mesh.tet(t));
  p.source = d.positions;
  const std::vector<char> on_boundary = topology::boundary_vertex_flags(d.mesh);
  for (std::uint32_t v = 0; v < on_boundary.size(); ++v)
    if (on_boundary[v]) {
      p.boundary_vertices.push_back(v);
      p.boundary_positions.push_back(d.positions[v]);
    }
  return p;
}

// Maps with every invariant asserted after every step and checks the verdict.
inline algorithm::MapResult map_checked(const algorithm::MapProblem& p, algorithm::MapOptions options = {}) {
  options.check = true;
  algorithm::MapResult r = algorithm::map_to_domain(p, options);
  REQUIRE_MESSAGE(r.outcome == algorithm::MapOutcome::success, r.message);
  CHECK_MESSAGE(r.verification.ok(), r.verification.first_failure);
  CHECK(r.verification.target_positive);
  CHECK(r.verification.source_positive);
  CHECK(r.verification.boundary_refines);
  return r;
}

// A finished map as an embedding again (no cluster vertex; boundary = the mesh's boundary), for
// tests that run one step of the method on it.
inline algorithm::Embedding embedding_of(const algorithm::MapResult& r) {
  algorithm::Embedding e;
  e.mesh = topology::TetMesh(r.target.size(), r.tets);
  e.source = r.source;
  e.target = r.target;
  e.center = r.center;
  e.unexpanded.assign(r.target.size(), 0);
  e.boundary = topology::boundary_vertex_flags(e.mesh);
  return e;
}

// Every live tet strictly positive in the source and in the target.
inline bool every_tet_positive(const algorithm::Embedding& e) {
  for (topology::TetId t : e.mesh.live_tets())
    if (e.orient_source(e.mesh.tet(t)) != Sign::positive || e.orient_target(e.mesh.tet(t)) != Sign::positive)
      return false;
  return true;
}

// The four boundary shapes the collapse tests run on.
inline constexpr const char* collapse_test_shapes[] = {"tet", "stiff-tet", "sphere", "star:3"};

}  // namespace cmx::test
