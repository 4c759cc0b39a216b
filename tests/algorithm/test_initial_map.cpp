// Initial maps (algorithm/local/initial_map.hpp): the Tutte map solves its Laplacian system
// (checked exactly, on an independent path: topology::vertex_neighbors, rational arithmetic),
// keeps the boundary exactly, is deterministic, and inverts exactly the tets a construction says
// it must; given_map checks counts and sets a differing boundary to the prescribed positions.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "generators/domain_generators.hpp"
#include "algorithm/local/initial_map.hpp"
#include "arith/rational.hpp"
#include "arith/rounding.hpp"
#include "io/boundary.hpp"
#include "io/read_mesh.hpp"
#include "kernel/homogeneous_point.hpp"
#include "kernel/orient.hpp"
#include "map_test_util.hpp"
#include "skip.hpp"
#include "topology/complex_queries.hpp"

using namespace cmx;
using namespace cmx::algorithm;
using namespace cmx::generators;

namespace {

// Tets of the problem whose target orientation is not strictly positive (exact).
std::size_t non_positive_tets(const MapProblem& p, const std::vector<Point3>& target) {
  std::vector<HPoint> h;
  for (const Point3& q : target) h.emplace_back(q[0], q[1], q[2]);
  std::size_t count = 0;
  for (const topology::Tet& t : p.tets)
    if (orient3d(h[t[0]], h[t[1]], h[t[2]], h[t[3]], PredicateContext::certain()) != Sign::positive) ++count;
  return count;
}

// The largest |deg(v) x_v - sum of the neighbours' x| over interior vertices and axes, in exact
// arithmetic on the exact targets and prescribed positions, as a double.
double largest_residual(const MapProblem& p, const std::vector<Point3>& target) {
  const topology::TetMesh mesh(p.source.size(), p.tets);
  std::vector<char> boundary(p.source.size(), 0);
  for (std::uint32_t v : p.boundary_vertices) boundary[v] = 1;
  double worst = 0;
  for (std::uint32_t v = 0; v < p.source.size(); ++v) {
    if (boundary[v]) continue;
    const std::vector<topology::VertexId> nbrs = topology::vertex_neighbors(mesh, topology::VertexId{v});
    for (int k = 0; k < 3; ++k) {
      Rational r = Rational(static_cast<long>(nbrs.size())) * target[v][k];
      for (topology::VertexId u : nbrs) r -= target[u][k];
      worst = std::max(worst, std::abs(to_double(r)));
    }
  }
  return worst;
}

bool boundary_exactly_prescribed(const MapProblem& p, const std::vector<Point3>& target) {
  for (std::size_t i = 0; i < p.boundary_vertices.size(); ++i)
    if (target[p.boundary_vertices[i]] != p.boundary_positions[i]) return false;
  return true;
}

// Checks what holds for every Tutte map, whatever its orientations.
void check_solves_its_system(const MapProblem& p, const InitialMap& m) {
  REQUIRE_MESSAGE(m.ok, m.message);
  REQUIRE(m.target.size() == p.source.size());
  CHECK(m.interior == p.source.size() - p.boundary_vertices.size());
  CHECK(boundary_exactly_prescribed(p, m.target));
  // Residual over degree is the distance to the neighbours' average, per axis.
  CHECK(largest_residual(p, m.target) < 1e-9);
}

// The Tutte map of a cone over a suspended comb, where a construction gives the answer. The comb
// P is a star-shaped polygon in z = 0 (five spikes to the right, four valleys near the origin,
// three vertices to the left); its vertices and the apexes N, S = (0, 0, +-6) are the boundary,
// one interior vertex at the origin is joined to every boundary triangle. Its neighbours are all
// the boundary vertices, and N + S = 0, so the Tutte map puts it at c = (sum of P) / (|P| + 2)
// in z = 0, where the tets over an edge (p, q) of P have the sign of orient2d(c, p, q).
struct Comb {
  MapProblem problem;
  std::vector<std::array<Rational, 2>> polygon;  // counter-clockwise, vertices 1..|P|
};

Comb suspended_comb() {
  Comb c;
  for (int j = -2; j <= 2; ++j) {
    c.polygon.push_back({Rational(18), Rational(6 * j)});
    if (j < 2) c.polygon.push_back({Rational(6), Rational(2 * j + 1)});
  }
  const std::array<std::array<int, 2>, 3> left = {{{0, 3}, {-3, 0}, {0, -3}}};
  for (const auto& [x, y] : left) c.polygon.push_back({Rational(x), Rational(y)});
  const auto m = static_cast<std::uint32_t>(c.polygon.size());
  const std::uint32_t north = m + 1, south = m + 2;
  MapProblem& p = c.problem;
  p.source.push_back({Rational(0), Rational(0), Rational(0)});
  for (const auto& q : c.polygon) p.source.push_back({q[0], q[1], Rational(0)});
  p.source.push_back({Rational(0), Rational(0), Rational(6)});
  p.source.push_back({Rational(0), Rational(0), Rational(-6)});
  for (std::uint32_t i = 0; i < m; ++i) {
    const std::uint32_t a = 1 + i, b = 1 + (i + 1) % m;
    p.tets.push_back(topology::make_tet({0, north, a, b}));
    p.tets.push_back(topology::make_tet({0, south, b, a}));
  }
  for (std::uint32_t v = 1; v <= south; ++v) {
    p.boundary_vertices.push_back(v);
    p.boundary_positions.push_back(p.source[v]);
  }
  return c;
}

std::size_t comb_edges_not_seen(const Comb& c) {
  Rational cx(0), cy(0);
  for (const auto& q : c.polygon) cx += q[0], cy += q[1];
  const Rational n(static_cast<long>(c.polygon.size() + 2));
  cx /= n;
  cy /= n;
  std::size_t count = 0;
  for (std::size_t i = 0; i < c.polygon.size(); ++i) {
    const auto& a = c.polygon[i];
    const auto& b = c.polygon[(i + 1) % c.polygon.size()];
    const Rational cross = (a[0] - cx) * (b[1] - cy) - (a[1] - cy) * (b[0] - cx);
    if (sgn(cross) <= 0) ++count;
  }
  return count;
}

// A domain's problem with its boundary on a sphere (the generated "sphere" shape: the boundary
// projected radially), a convex position with the irregular connectivity of a voxel surface.
MapProblem sphere_problem(std::uint32_t radius, std::uint64_t seed) {
  return test::problem_from(voxel_ball(radius, seed), "sphere");
}

// A nearly convex boundary: the Tutte map solves its system and leaves at most 1 % of the tets
// not positive (Tutte's theorem fails in 3D, but only locally, near irregular connectivity).
void check_folds_few(const MapProblem& p, const std::string& what) {
  const InitialMap m = tutte_map(p);
  check_solves_its_system(p, m);
  const std::size_t bad = non_positive_tets(p, m.target);
  MESSAGE(what << ": " << bad << " of " << p.tets.size() << " tets not positive");
  CHECK(bad * 100 <= p.tets.size());
}

}  // namespace

TEST_CASE("the Tutte map of an unjittered grid with its box boundary is the grid, every tet positive") {
  // The Freudenthal neighbours of an inner grid vertex are symmetric about it, so the grid itself
  // solves the system; the double solution is within rounding of it.
  const GeneratedDomain d = perturbed_grid(5, 4, 6, 1, 0.0);
  const MapProblem p = test::identity_problem(d);
  const InitialMap m = tutte_map(p);
  check_solves_its_system(p, m);
  CHECK(m.interior == 4 * 3 * 5);
  double farthest = 0;
  for (std::size_t v = 0; v < p.source.size(); ++v)
    for (int k = 0; k < 3; ++k)
      farthest = std::max(farthest, std::abs(to_double(m.target[v][k] - p.source[v][k])));
  CHECK(farthest < 1e-12);
  CHECK(non_positive_tets(p, m.target) == 0);
}

TEST_CASE("the Tutte map of a jittered grid with its own boundary solves its system and inverts few tets") {
  check_folds_few(test::identity_problem(perturbed_grid(8, 8, 8, 3)), "jittered 8x8x8 grid");
}

TEST_CASE("the Tutte map of a voxel ball with a spherical boundary solves its system and inverts few tets") {
  check_folds_few(sphere_problem(5, 2), "voxel ball R=5 on a sphere");
}

TEST_CASE(
    "the Tutte map of a suspended comb inverts exactly the tets over the edges its centre does not see") {
  const Comb c = suspended_comb();
  const InitialMap m = tutte_map(c.problem);
  check_solves_its_system(c.problem, m);
  CHECK(m.interior == 1);
  const std::size_t unseen = comb_edges_not_seen(c);
  REQUIRE(unseen > 0);  // the construction really folds
  CHECK(non_positive_tets(c.problem, m.target) == 2 * unseen);
}

TEST_CASE("the Tutte map is the same on every run") {
  const MapProblem p = sphere_problem(4, 5);
  const InitialMap a = tutte_map(p), b = tutte_map(p);
  REQUIRE(a.ok);
  REQUIRE(b.ok);
  CHECK(a.target == b.target);
}

TEST_CASE("a mesh without interior vertices has the prescribed boundary as its Tutte map") {
  const MapProblem p = test::identity_problem(thin_slab(4, 3, 7, 1));
  const InitialMap m = tutte_map(p);
  REQUIRE_MESSAGE(m.ok, m.message);
  CHECK(m.interior == 0);
  CHECK(boundary_exactly_prescribed(p, m.target));
}

TEST_CASE("tutte_map refuses a vertex in no tet, a component without boundary, malformed boundary lists and a boundary beyond the doubles") {
  MapProblem p = test::identity_problem(perturbed_grid(2, 2, 2, 4));
  SUBCASE("a vertex in no tet") {
    p.source.push_back({Rational(9), Rational(9), Rational(9)});
    const InitialMap m = tutte_map(p);
    CHECK_FALSE(m.ok);
    CHECK(m.message ==
          "vertex " + std::to_string(p.source.size() - 1) + " is in no tet and not a boundary vertex");
  }
  SUBCASE("a tet whose vertices are all interior and disconnected from the boundary") {
    const auto n = static_cast<std::uint32_t>(p.source.size());
    for (int i = 0; i < 4; ++i) p.source.push_back({Rational(i), Rational(i * i), Rational(i * i * i)});
    p.tets.push_back(topology::make_tet({n, n + 1, n + 2, n + 3}));
    const InitialMap m = tutte_map(p);
    CHECK_FALSE(m.ok);
    CHECK(m.message == "interior vertex " + std::to_string(n) + " has no path to a boundary vertex");
  }
  SUBCASE("boundary lists of different sizes") {
    p.boundary_positions.pop_back();
    CHECK_FALSE(tutte_map(p).ok);
    CHECK_FALSE(given_map(p, p.source).ok);
  }
  SUBCASE("a boundary vertex listed twice") {
    p.boundary_vertices.back() = p.boundary_vertices.front();
    const InitialMap m = tutte_map(p);
    CHECK_FALSE(m.ok);
    CHECK(m.message == "boundary vertex " + std::to_string(p.boundary_vertices.front()) + " is listed twice");
  }
  SUBCASE("a prescribed coordinate beyond the doubles") {
    mpz_class huge;
    mpz_ui_pow_ui(huge.get_mpz_t(), 10, 400);
    p.boundary_positions.front()[2] = Rational(huge);
    const InitialMap m = tutte_map(p);
    CHECK_FALSE(m.ok);
    CHECK(m.message == "the prescribed position of boundary vertex " +
                           std::to_string(p.boundary_vertices.front()) + " is beyond the doubles");
  }
  SUBCASE("a tet vertex out of range") {
    p.tets.back()[2] = topology::VertexId(p.source.size());
    const InitialMap m = tutte_map(p);
    CHECK_FALSE(m.ok);
    CHECK(m.message == "tet " + std::to_string(p.tets.size() - 1) + " lists vertex " +
                           std::to_string(p.source.size()) + ", beyond the " +
                           std::to_string(p.source.size()) + " vertices");
  }
}

TEST_CASE("given_map rejects a wrong count and keeps a valid map unchanged") {
  const MapProblem p = test::identity_problem(voxel_ball(3, 6));
  SUBCASE("one position too few") {
    std::vector<Point3> positions = p.source;
    positions.pop_back();
    const InitialMap m = given_map(p, positions);
    CHECK_FALSE(m.ok);
    CHECK(m.message == "the initial map has " + std::to_string(p.source.size() - 1) +
                           " positions, the problem has " + std::to_string(p.source.size()) + " vertices");
  }
  SUBCASE("the source itself, a valid map onto its own boundary") {
    const InitialMap m = given_map(p, p.source);
    REQUIRE(m.ok);
    CHECK(m.message.empty());
    CHECK(m.target == p.source);
    CHECK(m.interior == p.source.size() - p.boundary_vertices.size());
  }
}

TEST_CASE("given_map sets boundary vertices off their prescribed positions to them and notes how many") {
  const MapProblem p = test::identity_problem(voxel_ball(3, 8));
  std::vector<Point3> positions = p.source;
  const Rational shift(1, 1000000);
  for (std::size_t i : {std::size_t{3}, std::size_t{11}}) positions[p.boundary_vertices[i]][1] += shift;
  std::uint32_t interior_vertex = 0;
  while (std::find(p.boundary_vertices.begin(), p.boundary_vertices.end(), interior_vertex) !=
         p.boundary_vertices.end())
    ++interior_vertex;
  positions[interior_vertex][0] += shift;  // an interior position is the map's own: kept
  const InitialMap m = given_map(p, positions);
  REQUIRE(m.ok);
  CHECK(boundary_exactly_prescribed(p, m.target));
  CHECK(m.target[interior_vertex] == positions[interior_vertex]);
  CHECK(m.message ==
        "note: 2 boundary vertices of the initial map were not at their prescribed positions and were "
        "set to them (first: vertex " +
            std::to_string(p.boundary_vertices[3]) + ")");
}

TEST_CASE("the Tutte maps of the Galaxy Maps pairs are their parameter meshes and fold as many tets") {
  // Each *_parameter.vtk holds a plain Tutte map (shared data README): ours must agree with it.
  if (!test::have_shared("data/galaxy-maps")) return;
  const std::filesystem::path dir = test::shared_dir() / "data" / "galaxy-maps";
  for (const std::string name : {"example", "cub_rockerarm291", "tlc_polycube_bird", "tgs_100349"}) {
    CAPTURE(name);
    const io::TetMeshData mesh = io::read_tet_mesh((dir / (name + "_object.vtk")).string());
    io::ReadOptions keep;
    keep.orientation = io::Orientation::keep;
    const std::string parameter_path = (dir / (name + "_parameter.vtk")).string();
    const io::TetMeshData parameter = io::read_tet_mesh(parameter_path, keep);
    const io::BoundaryPositions b =
        io::read_boundary_positions_from_codomain(mesh, parameter, parameter_path);
    const MapProblem p{topology::make_tets(mesh.tets), mesh.positions, b.vertices, b.positions, {}};
    const InitialMap ours = tutte_map(p);
    check_solves_its_system(p, ours);
    const InitialMap theirs = given_map(p, parameter.positions);
    REQUIRE(theirs.ok);
    double farthest = 0;
    for (std::size_t v = 0; v < p.source.size(); ++v)
      for (int k = 0; k < 3; ++k)
        farthest = std::max(farthest, std::abs(to_double(ours.target[v][k] - theirs.target[v][k])));
    CHECK(farthest < 1e-9);
    const std::size_t bad = non_positive_tets(p, ours.target);
    MESSAGE(name << ": " << bad << " tets not positive, Tutte solved in " << ours.seconds << " s");
    CHECK(bad > 0);
    CHECK(bad == non_positive_tets(p, theirs.target));
  }
}

TEST_CASE("tutte_map without the exact map gives the same doubles, and exact_target the same rationals") {
  const MapProblem p = sphere_problem(4, 3);
  const InitialMap full = tutte_map(p);
  InitialMap lean = tutte_map(p, false);
  REQUIRE(full.ok);
  REQUIRE(lean.ok);
  CHECK(lean.target.empty());
  CHECK(lean.doubles == full.doubles);
  // The doubles are the exact map rounded to nearest: exact for interior vertices.
  for (std::size_t v = 0; v < p.source.size(); ++v)
    for (int k = 0; k < 3; ++k) REQUIRE(full.doubles[v][k] == to_double(full.target[v][k]));
  exact_target(p, lean);
  CHECK(lean.target == full.target);
  CHECK(boundary_exactly_prescribed(p, lean.target));
}

TEST_CASE("tutte_map predicts its factorisation's cost and refuses one beyond max_flops, before factorising") {
  const MapProblem p = test::identity_problem(perturbed_grid(8, 8, 8, 3));
  const InitialMap unlimited = tutte_map(p);
  REQUIRE_MESSAGE(unlimited.ok, unlimited.message);
  // 343 interior vertices: L has at least one entry below the diagonal per column but the last,
  // so the estimate is at least 342 and a budget of 300 is refused, with the estimate and the count.
  const InitialMap refused = tutte_map(p, true, 300);
  CHECK_FALSE(refused.ok);
  CHECK(refused.message.find("multiply-adds for 343 interior vertices, more than the 300 allowed") != std::string::npos);
  CHECK(refused.target.empty());
  // A budget above the estimate changes nothing.
  const InitialMap within = tutte_map(p, true, 1e12);
  REQUIRE(within.ok);
  CHECK(within.target == unlimited.target);
}

TEST_CASE("a Tutte screen sees the conjugate-gradient map above its cost, and only a rejection changes the result") {
  const MapProblem p = sphere_problem(4, 3);
  const InitialMap plain = tutte_map(p, false);
  REQUIRE_MESSAGE(plain.ok, plain.message);
  double extent = 0;
  for (const auto& q : plain.doubles)
    for (double x : q) extent = std::max(extent, std::abs(x));
  std::size_t asked = 0;
  double farthest = 0;
  TutteScreen screen;
  screen.above_flops = 0;
  screen.reject = [&](const std::vector<std::array<double, 3>>& approximate) -> std::string {
    ++asked;
    REQUIRE(approximate.size() == plain.doubles.size());
    for (std::size_t v = 0; v < approximate.size(); ++v)
      for (int k = 0; k < 3; ++k) farthest = std::max(farthest, std::abs(approximate[v][k] - plain.doubles[v][k]));
    return {};
  };
  const InitialMap kept = tutte_map(p, false, std::numeric_limits<double>::infinity(), &screen);
  REQUIRE(kept.ok);
  CHECK(asked == 1);
  CHECK(farthest < 1e-8 * extent);  // the approximate solve is the map, nearly
  CHECK(kept.doubles == plain.doubles);  // and a screen that keeps it changes nothing
  CHECK_FALSE(kept.screened_out);

  screen.reject = [](const std::vector<std::array<double, 3>>&) -> std::string { return "folds too much"; };
  const InitialMap given_up = tutte_map(p, true, std::numeric_limits<double>::infinity(), &screen);
  CHECK_FALSE(given_up.ok);
  CHECK(given_up.screened_out);
  CHECK(given_up.message == "folds too much");
  CHECK(given_up.target.empty());

  screen.above_flops = 1e12;  // below the cost only: never asked
  asked = 0;
  screen.reject = [&](const std::vector<std::array<double, 3>>&) -> std::string {
    ++asked;
    return "never";
  };
  CHECK(tutte_map(p, false, std::numeric_limits<double>::infinity(), &screen).ok);
  CHECK(asked == 0);
}
