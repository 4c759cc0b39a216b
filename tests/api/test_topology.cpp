// cmx/topology.hpp: the ball check on index arrays (bad input is a verdict, not a crash), boundary
// faces, Eq. (1) on small cluster meshes, and topological expansion completing or getting stuck.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "api_test_util.hpp"
#include "cmx/kernel.hpp"
#include "cmx/topology.hpp"
#include "topology/complex_queries.hpp"
#include "topology/generators.hpp"
#include "topology/nobuenoss.hpp"

namespace {

using cmx::test::error_of;

std::vector<cmx::Tet> tets_of(const cmx::topology::TetMesh& m) {
  std::vector<cmx::Tet> out;
  for (const auto t : m.live_tets()) out.push_back(cmx::topology::indices_of(m.tet(t)));
  return out;
}

// The octahedron around vertex 6 at the origin: 0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z; 8 positive tets.
const std::vector<cmx::Point3d> octahedron_points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0},
                                                     {0, 0, 1}, {0, 0, -1}, {0, 0, 0}};
std::vector<cmx::Tet> octahedron() {
  std::vector<cmx::Tet> tets;
  for (const std::uint32_t x : {0u, 1u})
    for (const std::uint32_t y : {2u, 3u})
      for (const std::uint32_t z : {4u, 5u}) {
        cmx::Tet t{6, x, y, z};
        const auto& p = octahedron_points;
        if (cmx::orient3d(p[t[0]], p[t[1]], p[t[2]], p[t[3]]) < 0) std::swap(t[2], t[3]);
        tets.push_back(t);
      }
  return tets;
}

}  // namespace

TEST_CASE("api is_ball: one tet, two tets on a face and the octahedron are balls") {
  const std::vector<cmx::Tet> one = {{0, 1, 2, 3}};
  const cmx::BallCheck b = cmx::is_ball(one, 4);
  CHECK(b.ok);
  CHECK(b.message.empty());
  const std::vector<cmx::Tet> two = {{0, 1, 2, 3}, {0, 2, 1, 4}};
  CHECK(cmx::is_ball(two, 5).ok);
  CHECK(cmx::is_ball(octahedron(), 7).ok);
}

TEST_CASE("api is_ball: failures are verdicts with a message naming the culprit") {
  SUBCASE("two tets sharing only a vertex") {
    const std::vector<cmx::Tet> tets = {{0, 1, 2, 3}, {0, 4, 5, 6}};
    const cmx::BallCheck b = cmx::is_ball(tets, 7);
    CHECK_FALSE(b.ok);
    CHECK(b.message.find("vertex 0") != std::string::npos);
  }
  SUBCASE("an index beyond vertex_count") {
    const std::vector<cmx::Tet> tets = {{0, 1, 2, 3}, {0, 2, 1, 9}};
    const cmx::BallCheck b = cmx::is_ball(tets, 5);
    CHECK_FALSE(b.ok);
    CHECK(b.message.find("tet 1 names vertex 9") != std::string::npos);
  }
  SUBCASE("an unused vertex, a repeated vertex, inconsistent orientation, no tet") {
    const std::vector<cmx::Tet> one = {{0, 1, 2, 3}};
    CHECK(cmx::is_ball(one, 5).message.find("vertex 4") != std::string::npos);
    const std::vector<cmx::Tet> repeated = {{0, 1, 1, 3}};
    CHECK_FALSE(cmx::is_ball(repeated, 4).ok);
    const std::vector<cmx::Tet> flipped = {{0, 1, 2, 3}, {0, 1, 2, 4}};
    const cmx::BallCheck f = cmx::is_ball(flipped, 5);
    CHECK_FALSE(f.ok);
    CHECK(f.message.find("orientation") != std::string::npos);
    const cmx::BallCheck e = cmx::is_ball({}, 0);
    CHECK_FALSE(e.ok);
    CHECK_FALSE(e.message.empty());
  }
}

TEST_CASE("api boundary_faces: outward faces of one tet and of the octahedron") {
  const std::vector<cmx::Point3d> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<cmx::Tet> one = {{0, 1, 2, 3}};
  const auto faces = cmx::boundary_faces(one, 4);
  REQUIRE(faces.size() == 4);
  for (const auto& f : faces) {
    std::uint32_t opposite = 6 - f[0] - f[1] - f[2];
    CHECK(cmx::orient3d(p[f[0]], p[f[1]], p[f[2]], p[opposite]) == -1);  // the tet lies behind the face
  }
  const auto hull = cmx::boundary_faces(octahedron(), 7);
  CHECK(hull.size() == 8);
  for (const auto& f : hull) {
    CHECK(std::find(f.begin(), f.end(), 6u) == f.end());
    CHECK(cmx::orient3d(octahedron_points[f[0]], octahedron_points[f[1]], octahedron_points[f[2]],
                        {0, 0, 0}) == -1);
  }
  const std::vector<cmx::Tet> bad = {{0, 1, 2, 7}};
  CHECK(error_of([&] { (void)cmx::boundary_faces(bad, 4); }).find("tet 0 names vertex 7") !=
        std::string::npos);
}

TEST_CASE("api is_expandable: Eq. 1 on the octahedron's centre for several cluster meshes") {
  const std::vector<cmx::Tet> tets = octahedron();
  using Ids = std::vector<std::uint32_t>;
  CHECK(cmx::is_expandable(tets, 7, Ids{6, 0}, 6));           // Lk• one vertex
  CHECK(cmx::is_expandable(tets, 7, Ids{6, 0, 2}, 6));        // Lk• an edge
  CHECK(cmx::is_expandable(tets, 7, Ids{6, 0, 2, 4}, 6));     // Lk• a triangle
  CHECK_FALSE(cmx::is_expandable(tets, 7, Ids{6, 0, 1}, 6));  // two points: b0 = 2
  CHECK_FALSE(cmx::is_expandable(tets, 7, Ids{6}, 6));        // empty link: expanded automatically
  CHECK_FALSE(cmx::is_expandable(tets, 7, Ids{0, 1, 2, 3, 4, 5, 6}, 6));  // the whole sphere: chi 2
  CHECK(cmx::is_expandable(tets, 7, Ids{0, 1, 2, 3, 4, 6}, 6));           // the sphere minus a vertex: a disc
  // Errors: the vertex is not a cluster vertex, an index is out of range, the mesh is no ball.
  CHECK(error_of([&] {
          (void)cmx::is_expandable(tets, 7, Ids{0, 2}, 6);
        }).find("vertex 6 is not a cluster vertex") != std::string::npos);
  CHECK(error_of([&] {
          (void)cmx::is_expandable(tets, 7, Ids{6, 8}, 6);
        }).find("cluster vertex 8 out of range") != std::string::npos);
  const std::vector<cmx::Tet> pinched = {{0, 1, 2, 3}, {0, 4, 5, 6}};
  CHECK(error_of([&] { (void)cmx::is_expandable(pinched, 7, Ids{0}, 0); }).find("not a ball") !=
        std::string::npos);
}

TEST_CASE("api expand_topologically: a grid completes in every order") {
  const auto g = cmx::topology::grid_complex(3, 3, 3);
  const std::vector<cmx::Tet> tets = tets_of(g.mesh);
  const std::size_t n = g.mesh.num_vertices();
  std::vector<std::uint32_t> interior;
  const std::vector<char> flags = cmx::topology::interior_vertex_flags(g.mesh);
  for (std::uint32_t v = 0; v < n; ++v)
    if (flags[v]) interior.push_back(v);
  REQUIRE(interior.size() == 8);
  for (const char* order : {"priority", "index", "random:7"}) {
    INFO(order);
    const cmx::TopologicalExpansion r = cmx::expand_topologically(tets, n, {}, order);
    CHECK(r.complete);
    CHECK(r.initially_simply_connected);
    CHECK(r.remaining.empty());
    std::vector<std::uint32_t> sorted = r.sequence;
    std::sort(sorted.begin(), sorted.end());
    CHECK(sorted == interior);
  }
  // The index order expands the lowest expandable index first: the first interior vertex.
  CHECK(cmx::expand_topologically(tets, n, {}, "index").sequence.front() == interior.front());
  // A given cluster: two vertices apart, each expands on its own.
  const std::vector<std::uint32_t> apart = {interior.front(), interior.back()};
  const cmx::TopologicalExpansion r = cmx::expand_topologically(tets, n, apart);
  CHECK(r.complete);
  CHECK(r.sequence.size() == 2);
  CHECK(error_of([&] {
          (void)cmx::expand_topologically(tets, n, {}, "spiral");
        }).find("unknown order 'spiral'") != std::string::npos);
}

TEST_CASE("api expand_topologically: Bing's house and Furch's knotted hole get stuck") {
  const auto house = cmx::topology::bings_house_nobuenoss(4);
  const cmx::TopologicalExpansion h =
      cmx::expand_topologically(tets_of(house.mesh), house.mesh.num_vertices());
  CHECK_FALSE(h.complete);
  CHECK(h.initially_simply_connected);  // stuck from a simply connected cluster mesh: a NOBUENOSS
  CHECK(h.sequence.empty());
  CHECK(h.remaining.size() >= 2);
  CHECK(std::is_sorted(h.remaining.begin(), h.remaining.end()));
  const auto knot = cmx::topology::knotted_hole_ball();
  const std::vector<cmx::Tet> tets = tets_of(knot.mesh);
  const cmx::TopologicalExpansion k = cmx::expand_topologically(tets, knot.mesh.num_vertices());
  CHECK_FALSE(k.complete);
  CHECK(k.initially_simply_connected);
  CHECK_FALSE(k.sequence.empty());
  // Every remaining vertex really fails Eq. (1) on the remaining cluster mesh.
  for (const std::uint32_t v : {k.remaining.front(), k.remaining.back()})
    CHECK_FALSE(cmx::is_expandable(tets, knot.mesh.num_vertices(), k.remaining, v));
  const auto control = cmx::topology::unknotted_hole_ball();
  CHECK(cmx::expand_topologically(tets_of(control.mesh), control.mesh.num_vertices()).complete);
}

TEST_CASE("api replay_shelling: the house box replays completely, the knotted hole has no shelling found") {
  const auto box = cmx::topology::bings_house_in_box();
  const std::vector<cmx::Tet> tets = tets_of(box.mesh);
  const std::size_t n = box.mesh.num_vertices();
  // Greedy expansion in index order is stuck on the house; the fallback is not.
  CHECK_FALSE(cmx::expand_topologically(tets, n, {}, "index").complete);
  const cmx::ShellingReplay r = cmx::replay_shelling(tets, n);
  CHECK(r.shelling_found);
  CHECK_MESSAGE(r.completed, r.message);
  CHECK(r.eq1_failures == 0);
  CHECK(r.left == 0);
  CHECK(r.best_removed == tets.size());
  // The sequence: split vertices numbered in step order from n on; the expanded steps are the
  // reported expansions; every input vertex appears once as a plain step or is a boundary vertex.
  std::size_t expanded = 0, splits = 0;
  std::uint32_t next = static_cast<std::uint32_t>(n);
  for (const cmx::ReplayStep& s : r.steps) {
    expanded += s.expanded ? 1 : 0;
    if (s.kind == cmx::ReplayStep::Kind::vertex) {
      CHECK(s.vertex < n);
      CHECK(s.split[0] == UINT32_MAX);
    } else {
      ++splits;
      CHECK(s.vertex == next++);
      CHECK(s.split[1] != UINT32_MAX);
      CHECK((s.split[2] == UINT32_MAX) == (s.kind == cmx::ReplayStep::Kind::edge_split));
    }
  }
  CHECK(expanded == r.expansions);
  CHECK(splits == r.boundary_splits + r.cluster_splits + r.free_splits);
  CHECK(r.chord_expansions == r.chords.size());  // none here
  CHECK(r.expansions == r.input_expansions + r.chord_expansions + r.cluster_splits);
  CHECK(r.empty_cone_edge_splits > 0);

  const auto knot = cmx::topology::knotted_hole_ball();
  const cmx::ShellingReplay k = cmx::replay_shelling(tets_of(knot.mesh), knot.mesh.num_vertices(), 1, 2);
  CHECK_FALSE(k.shelling_found);
  CHECK_FALSE(k.completed);
  CHECK(k.attempts == 2);
  CHECK(k.steps.empty());
  CHECK(k.message.find("may not be shellable") != std::string::npos);

  CHECK(error_of([&] { (void)cmx::replay_shelling(tets, n, 1, 0); }).find("attempts") != std::string::npos);
  std::vector<cmx::Tet> twice = tets;
  twice.push_back(tets.front());
  CHECK(error_of([&] { (void)cmx::replay_shelling(twice, n); }).find("not a ball") != std::string::npos);
}
