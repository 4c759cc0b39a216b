// Problem validation: each failure a distinct error kind naming the first offending element.
#include <doctest/doctest.h>

#include <string>

#include "algorithm/map.hpp"
#include "map_test_util.hpp"
#include "topology/generators.hpp"

using namespace cmx;
using namespace cmx::algorithm;
using namespace cmx::generators;

namespace {

MapErrorKind error_of(const MapProblem& p, std::string* what = nullptr) {
  try {
    (void)map_to_domain(p);
  } catch (const MapError& e) {
    if (what) *what = e.what();
    return e.kind();
  }
  FAIL("no error");
  return MapErrorKind::internal;
}

// A 2x2x2 grid (one interior vertex) with its own boundary: a valid problem to break.
MapProblem grid_problem() { return cmx::test::identity_problem(perturbed_grid(2, 2, 2, 0, 0)); }

std::size_t index_of(const MapProblem& p, std::uint32_t v) {
  for (std::size_t i = 0; i < p.boundary_vertices.size(); ++i)
    if (p.boundary_vertices[i] == v) return i;
  FAIL("not a boundary vertex");
  return 0;
}

}  // namespace

TEST_CASE("the unbroken problem maps") { cmx::test::map_checked(grid_problem()); }

TEST_CASE("a vertex index out of range is invalid input naming the tet") {
  MapProblem p = grid_problem();
  p.tets[3][2] = topology::VertexId{999};
  std::string what;
  CHECK(error_of(p, &what) == MapErrorKind::invalid_input);
  CHECK(what.find("tet 3") != std::string::npos);
}

TEST_CASE("a mesh that is not a ball is refused with the ball check's reason") {
  MapProblem p = grid_problem();
  // Two tets touching only at a vertex: not a manifold.
  p.source.push_back({Rational(10), Rational(10), Rational(10)});
  p.source.push_back({Rational(11), Rational(10), Rational(10)});
  p.source.push_back({Rational(10), Rational(11), Rational(10)});
  const std::uint32_t n = std::uint32_t(p.source.size());
  p.tets.push_back(topology::make_tet({p.tets[0][0], n - 3, n - 2, n - 1}));
  std::string what;
  CHECK(error_of(p, &what) == MapErrorKind::not_ball);
  CHECK_FALSE(what.empty());
}

TEST_CASE("positions for a wrong vertex set are a boundary mismatch naming the vertex") {
  MapProblem p = grid_problem();
  const std::uint32_t missing = p.boundary_vertices.back();
  p.boundary_vertices.pop_back();
  p.boundary_positions.pop_back();
  std::string what;
  CHECK(error_of(p, &what) == MapErrorKind::boundary_mismatch);
  CHECK(what.find("vertex " + std::to_string(missing)) != std::string::npos);

  MapProblem q = grid_problem();
  q.boundary_vertices.push_back(13);  // the centre of the 3x3x3 vertex grid: interior
  q.boundary_positions.push_back({Rational(1), Rational(1), Rational(1)});
  CHECK(error_of(q) == MapErrorKind::boundary_mismatch);

  MapProblem r = grid_problem();
  r.boundary_vertices.push_back(r.boundary_vertices[0]);
  r.boundary_positions.push_back(r.boundary_positions[0]);
  CHECK(error_of(r) == MapErrorKind::boundary_mismatch);
}

TEST_CASE("a negatively oriented source tet is refused") {
  MapProblem p = grid_problem();
  std::swap(p.tets[0][0], p.tets[0][1]);
  CHECK(error_of(p) == MapErrorKind::not_ball);  // orientation is inconsistent across faces first
}

TEST_CASE("a degenerate prescribed boundary triangle is named") {
  MapProblem p = grid_problem();
  // Vertex 1 (grid point (1,0,0), middle of a bottom edge) moved onto the corner (0,0,0):
  // its triangles with that corner have collinear corners.
  p.boundary_positions[index_of(p, 1)] = p.boundary_positions[index_of(p, 0)];
  std::string what;
  CHECK(error_of(p, &what) == MapErrorKind::degenerate_boundary);
  CHECK(what.find("boundary triangle") != std::string::npos);
}

TEST_CASE("a mirrored boundary is refused as inside out") {
  MapProblem p = grid_problem();
  for (auto& q : p.boundary_positions) q[0] = -q[0];
  CHECK(error_of(p) == MapErrorKind::boundary_orientation);
}

TEST_CASE("a boundary without a kernel is refused as not star-shaped, naming a triangle") {
  MapProblem p = grid_problem();
  // The centre of the top face (grid point (1,1,2), vertex 22) pulled far below the bottom face:
  // the surface folds through itself and no point sees all of it.
  p.boundary_positions[index_of(p, 22)] = {Rational(1), Rational(1), Rational(-20)};
  std::string what;
  const MapErrorKind k = error_of(p, &what);
  CHECK(k == MapErrorKind::not_star_shaped);
  CHECK(what.find("boundary triangle") != std::string::npos);
}

TEST_CASE("the time limit stops the run with its outcome, not an exception") {
  MapOptions o;
  o.time_limit_seconds = 1e-9;
  const MapResult r = map_to_domain(cmx::test::problem_from(perturbed_grid(4, 4, 4, 1), "star:2"), o);
  CHECK(r.outcome == MapOutcome::time_limit);
  CHECK(r.message.find("time limit") != std::string::npos);
}
