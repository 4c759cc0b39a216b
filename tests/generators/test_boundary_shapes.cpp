// Boundary-condition generators: every shape on every kind of test domain (perturbed grids, voxel
// balls, thin slabs, TetGen's Delaunay balls when built, the Shrink-and-Expand examples when
// ../shared/data is present) is star-shaped about the origin in exact arithmetic, covers exactly the
// boundary vertices, has the shape's geometry, and is the same bit for bit when generated again.
#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>
#include <string>

#include "generators/boundary_shapes.hpp"
#include "generators/domain_generators.hpp"
#include "arith/exact_decimal.hpp"
#include "io/boundary.hpp"
#include "io/read_mesh.hpp"
#include "io/write_mesh.hpp"
#include "skip.hpp"
#include "topology/ball_check.hpp"
#include "topology/complex_queries.hpp"
#include "topology/generators.hpp"
#ifdef CMX_HAVE_TETGEN_BALL
#include "support/tetgen_ball.hpp"
#endif

namespace alg = cmx::generators;
using alg::BoundaryShape;
using alg::BoundaryShapeSpec;
using cmx::topology::TetMesh;
using Positions = std::vector<std::array<double, 3>>;

namespace {

constexpr BoundaryShape all_shapes[] = {BoundaryShape::tet, BoundaryShape::stiff_tet, BoundaryShape::sphere,
                                        BoundaryShape::star};

double norm(const std::array<double, 3>& p) { return std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]); }

// The tetrahedron's corners as the generator computes them.
const std::array<std::array<double, 3>, 4> corners{{{std::sqrt(8.0) / 3, 0.0, -1.0 / 3},
                                                     {-std::sqrt(2.0) / 3, std::sqrt(2.0 / 3), -1.0 / 3},
                                                     {-std::sqrt(2.0) / 3, -std::sqrt(2.0 / 3), -1.0 / 3},
                                                     {0.0, 0.0, 1.0}}};

bool is_corner(const std::array<double, 3>& p) {
  for (const auto& c : corners)
    if (p == c) return true;
  return false;
}

// Checks one generated boundary and returns it (for determinism comparisons).
alg::GeneratedBoundary check_shape(const TetMesh& mesh, const Positions& source, BoundaryShapeSpec spec) {
  CAPTURE(alg::to_string(spec));
  const auto g = alg::generate_boundary(mesh, source, spec);
  INFO(g.message);
  REQUIRE(g.ok);
  CHECK(g.attempts >= 1);
  CHECK(alg::check_star_shaped_about_origin(mesh, g) == "");
  // Exactly the boundary vertices, ascending.
  const auto flags = cmx::topology::boundary_vertex_flags(mesh);
  std::vector<std::uint32_t> expected;
  for (std::uint32_t v = 0; v < flags.size(); ++v)
    if (flags[v]) expected.push_back(v);
  CHECK(g.vertices == expected);
  REQUIRE(g.positions.size() == g.vertices.size());
  // The shape's geometry.
  std::size_t at_corners = 0;
  for (const auto& p : g.positions) {
    const double r = norm(p);
    switch (spec.shape) {
      case BoundaryShape::tet:
      case BoundaryShape::stiff_tet:
        REQUIRE(r <= 1 + 1e-15);
        REQUIRE(r >= 1.0 / 3 - 1e-15);
        at_corners += is_corner(p);
        break;
      case BoundaryShape::sphere: REQUIRE(std::abs(r - 1) <= 4e-16); break;
      case BoundaryShape::star:
        REQUIRE(r >= 1 - 4e-16);
        REQUIRE(r < 10 + 1e-14);
        break;
    }
  }
  if (spec.shape == BoundaryShape::tet || spec.shape == BoundaryShape::stiff_tet) CHECK(at_corners == 4);
  if (spec.shape == BoundaryShape::stiff_tet) {
    // One face of the tetrahedron is a single boundary triangle: its three corners.
    std::vector<char> corner_vertex(mesh.num_vertices(), 0);
    for (std::size_t i = 0; i < g.vertices.size(); ++i) corner_vertex[g.vertices[i]] = is_corner(g.positions[i]);
    bool found = false;
    for (const auto& f : cmx::topology::boundary_faces(mesh))
      found = found || (corner_vertex[f.face[0]] && corner_vertex[f.face[1]] && corner_vertex[f.face[2]]);
    CHECK(found);
  }
  // Deterministic: the same input gives the same doubles.
  const auto again = alg::generate_boundary(mesh, source, spec);
  CHECK(again.vertices == g.vertices);
  CHECK(again.positions == g.positions);
  CHECK(again.attempts == g.attempts);
  return g;
}

void check_all_shapes(const TetMesh& mesh, const Positions& source) {
  REQUIRE(cmx::topology::check_ball(mesh).ok);
  for (auto shape : all_shapes) check_shape(mesh, source, BoundaryShapeSpec{shape, 1234});
  // Other seeds give other valid boundaries.
  const auto a = check_shape(mesh, source, BoundaryShapeSpec{BoundaryShape::star, 1});
  const auto b = check_shape(mesh, source, BoundaryShapeSpec{BoundaryShape::star, 2});
  CHECK(a.positions != b.positions);
}

}  // namespace

TEST_CASE("parse_boundary_shape and to_string") {
  const auto tet = alg::parse_boundary_shape("tet");
  REQUIRE(tet);
  CHECK(tet->shape == BoundaryShape::tet);
  CHECK(tet->seed == 1234);
  CHECK(alg::parse_boundary_shape("stiff-tet")->shape == BoundaryShape::stiff_tet);
  CHECK(alg::parse_boundary_shape("sphere")->shape == BoundaryShape::sphere);
  CHECK(alg::parse_boundary_shape("star")->shape == BoundaryShape::star);
  const auto star = alg::parse_boundary_shape("star:42");
  REQUIRE(star);
  CHECK(star->shape == BoundaryShape::star);
  CHECK(star->seed == 42);
  CHECK(alg::parse_boundary_shape("star:18446744073709551615")->seed == 18446744073709551615ull);
  CHECK(alg::parse_boundary_shape("tet:7")->seed == 7);  // any shape takes a seed (its corner choice)
  for (const char* bad : {"", "cube", "Tet", "star:", "star:-1", "star:+1", "star:1x", "star:18446744073709551616",
                          "stiff_tet", "star:1:2", " tet"})
    CHECK_MESSAGE(!alg::parse_boundary_shape(bad), bad);
  for (const std::string text : {"tet", "stiff-tet", "sphere", "star:1234", "star:0", "tet:9"}) {
    CAPTURE(text);
    const auto spec = alg::parse_boundary_shape(text);
    REQUIRE(spec);
    CHECK(alg::to_string(*spec) == text);
  }
  CHECK(alg::to_string(*alg::parse_boundary_shape("star")) == "star:1234");
}

TEST_CASE("boundary shapes on a single tet and on two tets sharing a face") {
  const Positions tet_points{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  check_all_shapes(cmx::topology::single_tet(), tet_points);
  Positions two = tet_points;
  two.push_back({1, 1, 1});
  check_all_shapes(cmx::topology::two_tets_sharing_face(), two);
}

TEST_CASE("boundary shapes on perturbed grids") {
  for (auto [nx, ny, nz] : {std::array<std::uint32_t, 3>{2, 2, 2}, {4, 3, 3}, {6, 6, 6}}) {
    CAPTURE(nx);
    CAPTURE(ny);
    CAPTURE(nz);
    const auto d = alg::perturbed_grid(nx, ny, nz, 5);
    check_all_shapes(d.mesh, d.double_positions());
    const auto plain = alg::perturbed_grid(nx, ny, nz, 5, 0.0);  // unperturbed: many equal lengths
    check_all_shapes(plain.mesh, plain.double_positions());
  }
}

TEST_CASE("boundary shapes on voxel balls") {
  for (std::uint32_t r : {2u, 4u, 6u}) {
    CAPTURE(r);
    const auto d = alg::voxel_ball(r, 17);
    check_all_shapes(d.mesh, d.double_positions());
  }
}

TEST_CASE("boundary shapes on thin slabs") {
  for (std::uint32_t layers : {1u, 2u}) {
    CAPTURE(layers);
    const auto d = alg::thin_slab(10, 7, 23, layers);
    check_all_shapes(d.mesh, d.double_positions());
  }
}

TEST_CASE("boundary shapes on TetGen's Delaunay balls") {
#ifdef CMX_HAVE_TETGEN_BALL
  for (std::uint64_t seed : {1u, 2u}) {
    CAPTURE(seed);
    const auto ball = cmx::test::tetgen_ball(300, 200, seed);
    CHECK(cmx::topology::check_ball(ball.mesh).ok);
    check_all_shapes(ball.mesh, ball.positions);
  }
  const auto refined = cmx::test::tetgen_ball(40, 60, 3, 1.5);  // quality-refined: Steiner points
  MESSAGE("refined TetGen ball: " << refined.positions.size() << " vertices, " << refined.mesh.num_tets() << " tets");
  check_all_shapes(refined.mesh, refined.positions);
#else
  cmx::test::skip("built without CMX_WITH_TETGEN_ORACLE");
#endif
}

TEST_CASE("boundary shapes on the Shrink-and-Expand example domains") {
  namespace fs = std::filesystem;
  const fs::path dir = cmx::test::shared_dir() / "data" / "shrink-and-expand";
  if (!cmx::test::have_shared("data/shrink-and-expand")) return;
  for (const std::string name : {"prism_domain.ovm", "notch_domain.ovm"}) {
    CAPTURE(name);
    const auto data = cmx::io::read_tet_mesh((dir / name).string());
    const TetMesh mesh(data.positions.size(), data.tets);
    const auto source = cmx::io::nearest_doubles(data.positions);
    const auto start = std::chrono::steady_clock::now();
    check_all_shapes(mesh, source);
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
    MESSAGE(name << ": 6 shapes generated twice and checked in " << seconds.count() << " s");
  }
}

TEST_CASE("generated boundaries written as exact decimals read back exactly as boundary files") {
  const auto d = alg::voxel_ball(3, 8);
  const auto g = alg::generate_boundary(d.mesh, d.double_positions(), BoundaryShapeSpec{BoundaryShape::star, 3});
  REQUIRE(g.ok);
  std::string text;  // the lines `cmx boundary` writes
  for (std::size_t i = 0; i < g.vertices.size(); ++i)
    text += std::to_string(g.vertices[i]) + ' ' + cmx::exact_decimal(g.positions[i][0]) + ' ' +
            cmx::exact_decimal(g.positions[i][1]) + ' ' + cmx::exact_decimal(g.positions[i][2]) + '\n';
  const auto read = cmx::io::parse_boundary_positions(text, "generated", d.mesh.num_vertices());
  REQUIRE(read.vertices == g.vertices);
  for (std::size_t i = 0; i < g.vertices.size(); ++i)
    for (std::size_t a = 0; a < 3; ++a) REQUIRE(read.positions[i][a] == cmx::rational_from_double(g.positions[i][a]));
  cmx::io::TetMeshData domain;
  domain.positions = d.positions;
  for (auto t : d.mesh.live_tets()) domain.tets.push_back(cmx::topology::indices_of(d.mesh.tet(t)));
  CHECK_NOTHROW(cmx::io::check_boundary_coverage(domain, read, "generated"));
}

TEST_CASE("generate_boundary reports bad input instead of guessing") {
  const TetMesh tet = cmx::topology::single_tet();
  const Positions points{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const BoundaryShapeSpec spec;

  auto g = alg::generate_boundary(tet, Positions(3, {0, 0, 0}), spec);
  CHECK_FALSE(g.ok);
  CHECK(g.message.find("source positions") != std::string::npos);

  Positions nan_points = points;
  nan_points[2][1] = std::numeric_limits<double>::quiet_NaN();
  g = alg::generate_boundary(tet, nan_points, spec);
  CHECK_FALSE(g.ok);
  CHECK(g.message.find("not finite") != std::string::npos);

  // Two tets sharing only an edge: the boundary is not a closed surface (an edge in 4 faces).
  const std::vector<cmx::topology::TetIndices> bowtie{{0, 1, 2, 3}, {0, 1, 4, 5}};
  const TetMesh pinched(6, bowtie);
  g = alg::generate_boundary(pinched, Positions(6, {0, 0, 0}), spec);
  CHECK_FALSE(g.ok);
  CHECK(g.message.find("boundary edge (0, 1)") != std::string::npos);

  // An empty mesh has no boundary.
  g = alg::generate_boundary(TetMesh(0), {}, spec);
  CHECK_FALSE(g.ok);
  CHECK(g.message.find("at least 4") != std::string::npos);
}

TEST_CASE("check_star_shaped_about_origin names what is wrong") {
  const auto d = alg::perturbed_grid(3, 3, 3, 1);
  const auto good = alg::generate_boundary(d.mesh, d.double_positions(), BoundaryShapeSpec{BoundaryShape::sphere, 1});
  REQUIRE(good.ok);
  CHECK(alg::check_star_shaped_about_origin(d.mesh, good) == "");

  auto bad = good;  // one vertex moved through the origin: its faces turn away
  bad.positions[5] = {-bad.positions[5][0], -bad.positions[5][1], -bad.positions[5][2]};
  const auto why = alg::check_star_shaped_about_origin(d.mesh, bad);
  CHECK(why.find("boundary face (") == 0);
  CHECK(why.find(std::to_string(bad.vertices[5])) != std::string::npos);

  bad = good;  // a vertex at the origin: its faces' planes contain the origin
  bad.positions[0] = {0, 0, 0};
  CHECK(alg::check_star_shaped_about_origin(d.mesh, bad).find("degenerate") != std::string::npos);

  bad = good;  // a boundary vertex left out
  bad.vertices.pop_back();
  bad.positions.pop_back();
  CHECK(alg::check_star_shaped_about_origin(d.mesh, bad).find("has no position") != std::string::npos);

  bad = good;  // an interior vertex listed
  const auto flags = cmx::topology::boundary_vertex_flags(d.mesh);
  std::uint32_t interior = 0;
  while (flags[interior]) ++interior;
  bad.vertices.push_back(interior);
  bad.positions.push_back({0, 0, 2});
  CHECK(alg::check_star_shaped_about_origin(d.mesh, bad) == "vertex " + std::to_string(interior) + " is not a boundary vertex");

  bad = good;
  bad.positions[3][0] = std::numeric_limits<double>::infinity();
  CHECK(alg::check_star_shaped_about_origin(d.mesh, bad).find("not finite") != std::string::npos);
}

TEST_CASE("check_star_shaped_about_origin: a surface wrapping twice around a ray is rejected") {
  // A bipyramid over a pentagon: poles N = 0, S = 1, equator 2..6, five tets around the axis NS
  // (positive with the equator vertices at angles 72k degrees). Placing them at 144k degrees
  // instead (a pentagram) keeps every tet and every boundary face positively oriented, and the
  // origin (the midpoint of NS) on the inner side of every face, but the faces around each pole
  // now turn twice around it: a branched double cover of the sphere, not a star-shaped surface.
  std::vector<cmx::topology::TetIndices> tets;
  for (std::uint32_t k = 0; k < 5; ++k) tets.push_back({0, 1, 2 + (k + 1) % 5, 2 + k});
  const TetMesh mesh(7, tets);
  alg::GeneratedBoundary b;
  b.vertices = {0, 1, 2, 3, 4, 5, 6};
  b.positions = {{0, 0, 1}, {0, 0, -1}};
  for (int k = 0; k < 5; ++k) {
    const double angle = 2 * std::acos(-1.0) * 2 * k / 5;
    b.positions.push_back({std::cos(angle), std::sin(angle), 0});
  }
  CHECK(alg::check_star_shaped_about_origin(mesh, b) == "the boundary faces around vertex 0 wind 2 times around its ray from the origin");
  for (int k = 0; k < 5; ++k) {  // the pentagon itself is fine
    const double angle = 2 * std::acos(-1.0) * k / 5;
    b.positions[std::size_t(2 + k)] = {std::cos(angle), std::sin(angle), 0};
  }
  CHECK(alg::check_star_shaped_about_origin(mesh, b) == "");
}

namespace {

// Smallest and median area of the boundary triangles at the generated positions (doubles).
std::pair<double, double> smallest_and_median_area(const TetMesh& mesh, const alg::GeneratedBoundary& g) {
  std::vector<std::size_t> slot(mesh.num_vertices(), 0);
  for (std::size_t i = 0; i < g.vertices.size(); ++i) slot[g.vertices[i]] = i;
  std::vector<double> areas;
  for (const auto& f : cmx::topology::boundary_faces(mesh)) {
    const auto& a = g.positions[slot[f.face[0]]];
    const auto& b = g.positions[slot[f.face[1]]];
    const auto& c = g.positions[slot[f.face[2]]];
    const std::array<double, 3> u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    areas.push_back(0.5 * norm({u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]}));
  }
  std::sort(areas.begin(), areas.end());
  return {areas.front(), areas[areas.size() / 2]};
}

}  // namespace

TEST_CASE("spreading undoes the Tutte embedding's crowding of a long finger") {
  // One finger of 2 x 2 cells and length 40 on a palm: uniform weights crowd its tip into
  // triangles of area about 1e-19 (against a median of 4e-3); spreading must leave no triangle
  // below 1e-12 of the median, and stay valid, exact and deterministic like every shape.
  const auto hand = alg::thin_fingers(1, 2, 40, 0, 0.0);
  const Positions source = hand.double_positions();
  for (auto shape : {BoundaryShape::tet, BoundaryShape::sphere}) {
    const auto plain = check_shape(hand.mesh, source, BoundaryShapeSpec{shape, 1234, 0});
    const auto spread = check_shape(hand.mesh, source, BoundaryShapeSpec{shape, 1234, 30});
    const auto [plain_min, plain_median] = smallest_and_median_area(hand.mesh, plain);
    const auto [spread_min, spread_median] = smallest_and_median_area(hand.mesh, spread);
    CAPTURE(plain_min / plain_median);
    CAPTURE(spread_min / spread_median);
    CHECK(plain_min < 1e-12 * plain_median);  // the crowding the spreading is for
    CHECK(spread_min > 1e-12 * spread_median);
    CHECK(spread_min > 1e6 * plain_min);
  }
}

TEST_CASE("farthest corners give boundaries where drawn corners wall their paths off") {
  // Two fingers of 2 x 2 cells and length 80: drawn corners land on different fingers or far
  // down one, and the paths found one after another block each other in a finger only two
  // vertices wide, on every one of the 100 attempts. Corners at the ends of the longest stretch,
  // with the three paths from corner 0 found together, succeed; the result is checked like every
  // shape (exact, star-shaped, deterministic).
  const auto hand = alg::thin_fingers(2, 2, 80, 0, 0.0);
  const Positions source = hand.double_positions();
  REQUIRE(cmx::topology::check_ball(hand.mesh).ok);
  const auto drawn = alg::generate_boundary(hand.mesh, source, BoundaryShapeSpec{BoundaryShape::tet, 1234});
  CHECK_FALSE(drawn.ok);
  CHECK(drawn.message.find("no free boundary path") != std::string::npos);
  for (auto shape : {BoundaryShape::tet, BoundaryShape::sphere, BoundaryShape::star}) {
    BoundaryShapeSpec spec{shape, 1234};
    spec.corners = alg::CornerChoice::farthest;
    check_shape(hand.mesh, source, spec);
  }
  // stiff-tet keeps its triangle of corners 0, 1, 2 (at the outer end of the stretch with
  // farthest corners) and finds the three paths from corner 3 together: a different boundary,
  // checked like every other.
  BoundaryShapeSpec stiff{BoundaryShape::stiff_tet, 1234};
  const auto drawn_stiff = check_shape(hand.mesh, source, stiff);
  stiff.corners = alg::CornerChoice::farthest;
  const auto farthest_stiff = check_shape(hand.mesh, source, stiff);
  CHECK(drawn_stiff.positions != farthest_stiff.positions);
}
