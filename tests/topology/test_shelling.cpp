// Shelling (paper Sec. 4.3) and its conversion to an expansion sequence (Alg. 2).
#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <set>
#include <stdexcept>

#include "topo_test_util.hpp"
#include "topology/ball_check.hpp"
#include "topology/cluster_links.hpp"
#include "topology/complex_queries.hpp"
#include "topology/fixed_boundary_replay.hpp"
#include "topology/generators.hpp"
#include "topology/mesh_edits.hpp"
#include "topology/nobuenoss.hpp"
#include "topology/shelling.hpp"
#include "topology/topological_expansion.hpp"

using namespace cmx::topology;
using cmx::topology::test::flagged_submesh;

namespace {

// Replays Alg. 2's steps in the paper's setting (every vertex unexpanded at first, boundary
// included): the number of expanded vertices not satisfying Eq. (1) at their turn. Every
// `ball_every` steps (0: never) the cluster mesh is checked to be a ball.
std::size_t replay_in_paper_setting(const TetMesh& input, const ShellingExpansion& e,
                                    std::size_t ball_every) {
  TetMesh m = input;
  std::vector<char> U(m.num_vertices(), 1);
  ClusterLinkWorkspace ws;
  std::size_t failures = 0;
  for (std::size_t i = 0; i < e.steps.size(); ++i) {
    const ExpansionStep& st = e.steps[i];
    if (st.kind != ExpansionStepKind::plain_vertex) {
      const SplitResult r = st.kind == ExpansionStepKind::edge_split
                                ? split_edge(m, st.split[0], st.split[1])
                                : split_face(m, st.split[0], st.split[1], st.split[2]);
      REQUIRE(r.new_vertex == st.vertex);
      U.push_back(1);
    }
    if (!st.automatic && !is_topologically_expandable(m, st.vertex, U, ws)) ++failures;
    U[st.vertex] = 0;
    if (ball_every > 0 && i % ball_every == ball_every - 1) {
      const BallVerdict b = check_ball(flagged_submesh(m, U));
      CHECK_MESSAGE(b.ok, "step " << i << ": " << b.message);
    }
  }
  return failures;
}

// Every removal of the first `count` tets of `order` leaves a ball.
void check_removals_leave_balls(const TetMesh& m, const std::vector<TetId>& order, std::size_t count) {
  std::vector<char> alive(m.tet_capacity(), 1);
  for (std::size_t i = 0; i < count; ++i) {
    alive[order[i]] = 0;
    std::vector<Tet> rest;
    for (TetId t : m.live_tets())
      if (alive[t]) rest.push_back(m.tet(t));
    std::vector<char> used(m.num_vertices(), 0);
    for (const Tet& x : rest)
      for (VertexId v : x) used[v] = 1;
    const BallVerdict b = check_ball(flagged_submesh(TetMesh(m.num_vertices(), rest), used));
    REQUIRE_MESSAGE(b.ok, "after removing " << i + 1 << " tets: " << b.message);
  }
}

}  // namespace

TEST_CASE("shelling of grids: every removal leaves a ball") {
  for (const GridTriangulation tri : {GridTriangulation::freudenthal, GridTriangulation::reflected}) {
    const GridComplex g = grid_complex(3, 2, 2, tri);
    const ShellingResult s = find_shelling(g.mesh);
    REQUIRE_MESSAGE(s.found, s.message);
    CHECK(s.order.size() == g.mesh.num_tets());
    check_removals_leave_balls(g.mesh, s.order, s.order.size() - 1);
  }
}

TEST_CASE("removability rule: neither a tet with four shared faces nor a tet pinching an edge can go") {
  const GridComplex g = grid_complex(3, 3, 3);
  std::vector<char> all(g.mesh.tet_capacity(), 1);
  const TetAdjacency adj = tet_adjacency(g.mesh);
  const auto bf = boundary_vertex_flags(g.mesh);
  std::size_t interior_tets = 0, removable = 0;
  for (TetId t : g.mesh.live_tets()) {
    removable += is_shelling_removable(g.mesh, adj, t, all, g.mesh.num_tets()) ? 1 : 0;
    bool on_boundary = false;
    for (VertexId v : g.mesh.tet(t)) on_boundary = on_boundary || bf[v];
    if (!on_boundary) {
      ++interior_tets;
      CHECK(!is_shelling_removable(g.mesh, adj, t, all, g.mesh.num_tets()));
    }
  }
  CHECK(interior_tets == 6);
  CHECK(removable > 0);
  // Peel two tets of the fan around the diagonal (0,0,0)-(1,1,1) of the corner cell: the
  // diagonal is then on the boundary, and a fan tet with both faces at the diagonal shared has
  // t ∩ (rest) a disc but t ∩ boundary not a disc: removing it would pinch the diagonal.
  const VertexId o{0}, d{1 + 4 * (1 + 4 * 1)};
  std::vector<TetId> fan = tets_around_edge(g.mesh, o, d);
  REQUIRE(fan.size() == 6);
  std::vector<char> rem = all;
  std::size_t count = g.mesh.num_tets();
  std::size_t peeled = 0;
  for (int pass = 0; pass < 6 && peeled < 2; ++pass)
    for (TetId t : fan)
      if (rem[t] && peeled < 2 && is_shelling_removable(g.mesh, adj, t, rem, count)) {
        rem[t] = 0;
        --count;
        ++peeled;
      }
  REQUIRE(peeled == 2);
  // Every fan tet still present whose two faces at the diagonal are shared is now blocked.
  std::size_t blocked = 0;
  for (TetId t : fan) {
    if (!rem[t]) continue;
    int shared_at_diag = 0;
    const Tet& x = g.mesh.tet(t);
    for (int i = 0; i < 4; ++i)
      if (x[i] != o && x[i] != d && adj.neighbor[t][i] != invalid_index && rem[adj.neighbor[t][i]])
        ++shared_at_diag;
    if (shared_at_diag == 2) {
      CHECK(!is_shelling_removable(g.mesh, adj, t, rem, count));
      ++blocked;
    }
  }
  CHECK(blocked > 0);
}

TEST_CASE("Alg. 2: shelling -> expansion sequence, each step leaves a ball and satisfies Eq. (1)") {
  const GridComplex g = grid_complex(2, 2, 2);
  const ShellingResult s = find_shelling(g.mesh);
  REQUIRE(s.found);
  const ShellingExpansion e = shelling_to_expansion_sequence(g.mesh, s.order);
  REQUIRE_MESSAGE(e.ok, e.message);
  CHECK(e.steps.size() == s.order.size() - 1 + 4);
  std::size_t plain = 0, edge = 0, face = 0;
  // Replay: every vertex starts unexpanded (boundary included).
  TetMesh m = g.mesh;
  std::vector<char> U(m.num_vertices(), 1);
  ClusterLinkWorkspace ws;
  std::size_t remaining_cells = s.order.size();
  for (std::size_t i = 0; i < e.steps.size(); ++i) {
    const ExpansionStep& st = e.steps[i];
    if (st.kind == ExpansionStepKind::edge_split) {
      const SplitResult r = split_edge(m, st.split[0], st.split[1]);
      REQUIRE(r.ok);
      CHECK(r.new_vertex == st.vertex);
      U.push_back(1);
      ++edge;
    } else if (st.kind == ExpansionStepKind::face_split) {
      const SplitResult r = split_face(m, st.split[0], st.split[1], st.split[2]);
      REQUIRE(r.ok);
      CHECK(r.new_vertex == st.vertex);
      U.push_back(1);
      ++face;
    } else {
      ++plain;
    }
    if (!st.automatic) CHECK(is_topologically_expandable(m, st.vertex, U, ws));
    U[st.vertex] = 0;
    if (i + 4 < e.steps.size()) {
      --remaining_cells;
      // The cluster mesh is the closure of the remaining cells: a ball of that many tets.
      const TetMesh cluster = flagged_submesh(m, U);
      CHECK(cluster.num_tets() == remaining_cells);
      const BallVerdict b = check_ball(cluster);
      REQUIRE_MESSAGE(b.ok, "step " << i << ": " << b.message);
      const SubcomplexCounts c = subcomplex_counts(m, VertexSubset(U));
      CHECK(c.euler == 1);
      CHECK(c.components == 1);
      CHECK(c.tets == remaining_cells);
    }
  }
  for (char u : U) CHECK(u == 0);
  CHECK(m.num_vertices() == e.mesh.num_vertices());
  CHECK(m.num_tets() == e.mesh.num_tets());
  CHECK(plain > 0);
  CHECK(edge + face > 0);
}

TEST_CASE("Furch: greedy shelling peels the unknotted-hole ball but not the knotted-hole ball") {
  const GridComplex control = unknotted_hole_ball();
  const ShellingResult ok = find_shelling(control.mesh, {2, 1, {}});
  CHECK(ok.found);
  const GridComplex knot = knotted_hole_ball();
  const ShellingResult no = find_shelling(knot.mesh, {2, 1, {}});
  CHECK(!no.found);
  CHECK(no.attempts == 2);
  CHECK(no.best_removed > 0);
  CHECK(no.best_removed < knot.mesh.num_tets());
  CHECK(no.message.find("no shelling found") != std::string::npos);
  // The fallback says so and replays nothing.
  const ShellingFallback none = shelling_fallback(knot.mesh, {2, 1, {}});
  CHECK(!none.shelling_found);
  CHECK(!none.replayed);
  CHECK(none.tets >= knot.mesh.num_tets());  // its chords split first
  CHECK(none.best_removed < none.tets);
  CHECK(none.message.find("may not be shellable") != std::string::npos);
  // Alg. 2 on the control: every expanded vertex satisfies Eq. (1) when its turn comes, and
  // the cluster mesh stays a ball (checked every 2000 steps).
  const ShellingExpansion e = shelling_to_expansion_sequence(control.mesh, ok.order);
  REQUIRE(e.ok);
  const std::size_t failures = replay_in_paper_setting(control.mesh, e, 2000);
  CHECK(failures == 0);
}

TEST_CASE("find_shelling starts no attempt once told to stop, but always makes the first") {
  const GridComplex knot = knotted_hole_ball();
  ShellingOptions late{4, 1, [] { return true; }};
  const ShellingResult r = find_shelling(knot.mesh, late);
  CHECK(!r.found);
  CHECK(r.attempts == 1);
  CHECK(r.stopped_at_deadline);
  CHECK(r.message.find("cut short by the deadline") != std::string::npos);
  const ShellingResult free = find_shelling(knot.mesh, {2, 1, {}});
  CHECK(free.attempts == 2);
  CHECK(!free.stopped_at_deadline);
  CHECK(free.message.find("deadline") == std::string::npos);
}

namespace {

// What the house-in-a-box constructions and the dunce-hat ball promise (topology/nobuenoss.hpp): a
// shellable ball whose last `house` vertices form a NOBUENOSS that index order, or any order
// deferring them, meets.
void check_nobuenoss_last(const TetMesh& mesh, std::size_t house) {
  const BallVerdict ball = check_ball(mesh);
  REQUIRE_MESSAGE(ball.ok, ball.message);
  const std::size_t n = mesh.num_vertices();
  REQUIRE(house > 0);
  // The house's vertices are the last ids and all interior.
  const std::vector<char> interior = interior_vertex_flags(mesh);
  for (std::size_t v = n - house; v < n; ++v) CHECK(interior[v]);
  // Index order expands every other interior vertex and is left with exactly the house: a
  // NOBUENOSS (Euler characteristic 1, connected, 2-dimensional, no vertex satisfying Eq. (1)).
  const TopologicalExpansionResult stuck = topological_expansion(mesh, *parse_expansion_order("index"));
  CHECK(stuck.stuck);
  REQUIRE(stuck.remaining.size() == house);
  CHECK(stuck.remaining.front() == VertexId(n - house));
  CHECK(stuck.remaining_euler == 1);
  CHECK(stuck.remaining_components == 1);
  std::vector<char> left(n, 0);
  for (VertexId v : stuck.remaining) left[v] = 1;
  const SubcomplexCounts c = subcomplex_counts(mesh, VertexSubset(left));
  CHECK(c.tets == 0);
  CHECK(c.triangles > 0);
  // The default order does not meet it.
  CHECK(!topological_expansion(mesh, {}).stuck);
  // The ball is shellable, and Alg. 2 replays the shelling topologically: in the paper's setting
  // (every vertex unexpanded at first) ...
  const ShellingResult s = find_shelling(mesh, {2, 1, {}});
  REQUIRE(s.found);
  const ShellingExpansion e = shelling_to_expansion_sequence(mesh, s.order);
  REQUIRE_MESSAGE(e.ok, e.message);
  CHECK(replay_in_paper_setting(mesh, e, 0) == 0);
  // ... and in cmx's, with the boundary expanded from the start.
  const FixedBoundaryReplay f = replay_with_fixed_boundary(mesh, e);
  CHECK_MESSAGE(f.ok, f.first_failure);
  CHECK(f.eq1_failures == 0);
  CHECK(f.left == 0);
  CHECK(f.expansions >= n - ball.boundary_vertices);
  std::size_t split_steps = 0;
  for (const ExpansionStep& st : e.steps) split_steps += st.kind != ExpansionStepKind::plain_vertex ? 1 : 0;
  CHECK(f.boundary_splits + f.free_splits + f.cluster_splits == split_steps);
  CHECK(f.boundary_splits > 0);
  CHECK(f.cluster_splits > 0);
  // The steps whose cone is empty while the split edge's ends sit at the shrink point.
  CHECK(f.empty_cone_edge_splits > 0);
  CHECK(f.empty_cone_edge_splits <= f.cluster_splits);
  // Every interior vertex of the input is expanded once; the other expansions are split vertices.
  CHECK(f.input_expansions == n - ball.boundary_vertices);
  CHECK(f.expansions == f.input_expansions + f.cluster_splits);
  // shelling_fallback chains the same three steps with its own search (8 attempts, seed 1).
  const ShellingFallback chained = shelling_fallback(mesh);
  CHECK(chained.shelling_found);
  REQUIRE(chained.replayed);
  CHECK(chained.replay.ok);
  CHECK(chained.replay.input_expansions == f.input_expansions);
  CHECK(chained.message.find("expands every interior vertex") != std::string::npos);
  MESSAGE("fixed-boundary replay: " << f.expansions << " expansions, splits " << f.boundary_splits
                                    << " boundary, " << f.free_splits << " free, " << f.cluster_splits
                                    << " of cluster simplices (" << f.empty_cone_edge_splits
                                    << " cluster-edge splits with an empty cone)");
  // Deferring the house steers every order onto it, the default order included.
  const std::string defer = ",defer:" + std::to_string(n - house) + "-" + std::to_string(n);
  for (const char* base : {"priority", "random:1", "random:2"}) {
    const auto order = parse_expansion_order(base + defer);
    REQUIRE(order);
    const TopologicalExpansionResult d = topological_expansion(mesh, *order);
    CAPTURE(base);
    CHECK(d.stuck);
    CHECK(d.remaining == stuck.remaining);
  }
}

}  // namespace

TEST_CASE("Bing's house in a box: shellable, yet greedy index-order expansion meets the house") {
  std::size_t house = 0;
  const GridComplex g = bings_house_in_box(2, &house);
  check_nobuenoss_last(g.mesh, house);
}

TEST_CASE("the compact Bing's house in a box: the same, at a fifth of the size") {
  std::size_t house = 0;
  const GridComplex g = compact_bings_house_in_box(2, &house);
  CHECK(g.mesh.num_tets() == 6720);
  CHECK(g.mesh.num_vertices() == 1485);
  CHECK(house == 309);
  check_nobuenoss_last(g.mesh, house);
}

TEST_CASE("the dunce-hat ball: 90 tets, shellable, and greedy expansion with the hat last meets it") {
  std::size_t hat = 0;
  const TetMesh mesh = dunce_hat_ball(&hat);
  CHECK(mesh.num_tets() == 90);
  CHECK(mesh.num_vertices() == 27);
  REQUIRE(hat == 8);
  // The hat is the full subcomplex on the last 8 ids: Hachimori's dunce hat (8 vertices, 24
  // edges, 17 triangles, no tet), every edge in two triangles or more (no free edge).
  std::vector<char> on_hat(27, 0);
  for (std::size_t v = 19; v < 27; ++v) on_hat[v] = 1;
  const SubcomplexCounts c = subcomplex_counts(mesh, VertexSubset(on_hat));
  CHECK(c.edges == 24);
  CHECK(c.triangles == 17);
  CHECK(c.tets == 0);
  for (std::uint32_t a = 19; a < 27; ++a)
    for (std::uint32_t b = a + 1; b < 27; ++b) {
      std::set<std::uint32_t> apexes;
      for (TetId t : tets_around_edge(mesh, VertexId(a), VertexId(b)))
        for (VertexId x : mesh.tet(t))
          if (x != VertexId(a) && x != VertexId(b) && on_hat[x]) apexes.insert(x);
      CAPTURE(a);
      CAPTURE(b);
      if (!tets_around_edge(mesh, VertexId(a), VertexId(b)).empty()) CHECK(apexes.size() >= 2);
    }
  check_nobuenoss_last(mesh, hat);
  // More collars put the hat deeper: 6 vertices and 24 tets each, the same promises.
  const TetMesh deeper = dunce_hat_ball(&hat, 3);
  CHECK(deeper.num_vertices() == 39);
  CHECK(deeper.num_tets() == 138);
  check_nobuenoss_last(deeper, hat);
  // The replay can be stopped once a condition holds: here, at the first vertex of the hat.
  const ShellingResult s = find_shelling(mesh, {2, 1, {}});
  REQUIRE(s.found);
  const ShellingExpansion e = shelling_to_expansion_sequence(mesh, s.order);
  REQUIRE(e.ok);
  const FixedBoundaryReplay whole = replay_with_fixed_boundary(mesh, e);
  CHECK_FALSE(whole.stopped);
  const FixedBoundaryReplay part =
      replay_with_fixed_boundary(mesh, e, 0, [](const TetMesh&, const std::vector<char>& unexpanded) {
        for (std::size_t v = 19; v < 27; ++v)
          if (!unexpanded[v]) return true;
        return false;
      });
  CHECK(part.stopped);
  CHECK_FALSE(part.ok);
  CHECK(part.expansions < whole.expansions);
  CHECK(part.left > 0);
  // Started from a given cluster (a replay planned again part-way): from every interior vertex it
  // is the replay above; from the input vertices the part expanded, only the others are expanded;
  // from none, nothing is.
  std::vector<char> cluster(mesh.num_vertices());
  const std::vector<char> boundary = boundary_vertex_flags(mesh);
  for (std::size_t v = 0; v < cluster.size(); ++v) cluster[v] = boundary[v] ? 0 : 1;
  const FixedBoundaryReplay from_all = replay_with_fixed_boundary(mesh, e, 0, {}, &cluster);
  CHECK(from_all.ok == whole.ok);
  CHECK(from_all.expansions == whole.expansions);
  std::vector<char> at_stop;
  const FixedBoundaryReplay until =
      replay_with_fixed_boundary(mesh, e, 0, [&](const TetMesh&, const std::vector<char>& unexpanded) {
        for (std::size_t v = 19; v < 27; ++v)
          if (!unexpanded[v]) {
            at_stop.assign(unexpanded.begin(),
                           unexpanded.begin() + static_cast<std::ptrdiff_t>(mesh.num_vertices()));
            return true;
          }
        return false;
      });
  REQUIRE(until.stopped);
  REQUIRE(until.input_expansions > 0);
  const FixedBoundaryReplay rest = replay_with_fixed_boundary(mesh, e, 0, {}, &at_stop);
  CHECK(rest.input_expansions == whole.input_expansions - until.input_expansions);
  const std::vector<char> none(mesh.num_vertices(), 0);
  const FixedBoundaryReplay from_none = replay_with_fixed_boundary(mesh, e, 0, {}, &none);
  CHECK(from_none.ok);
  CHECK(from_none.expansions == 0);
  CHECK_THROWS_AS((void)dunce_hat_ball(nullptr, 0), std::invalid_argument);
  CHECK_THROWS_AS((void)dunce_hat_ball(nullptr, 65), std::invalid_argument);
}

TEST_CASE(
    "fixed-boundary replay on grids: the last cluster vertex goes automatically, boundary steps may follow") {
  // In the paper's setting the last step of Alg. 2 is the automatic one; with the boundary in
  // place the cluster can empty earlier, the last cell's boundary vertices coming after it. Its
  // last cluster vertex has an empty Lk• and must not be counted as failing Eq. (1).
  std::size_t early = 0, replays = 0;
  for (const GridTriangulation tri : {GridTriangulation::freudenthal, GridTriangulation::reflected})
    for (std::uint32_t n = 2; n <= 4; ++n)
      for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        CAPTURE(n);
        CAPTURE(seed);
        const GridComplex g = grid_complex(n, n, n, tri);
        const ShellingResult s = find_shelling(g.mesh, {4, seed, {}});
        REQUIRE(s.found);
        const ShellingExpansion e = shelling_to_expansion_sequence(g.mesh, s.order);
        REQUIRE(e.ok);
        const FixedBoundaryReplay f = replay_with_fixed_boundary(g.mesh, e, 1);
        CHECK_MESSAGE(f.ok, f.first_failure);
        CHECK(f.left == 0);
        CHECK(f.checks == f.expansions + 1);  // simply connected before and after every expansion
        CHECK(f.check_failures == 0);
        ++replays;
        std::size_t last = 0;
        for (std::size_t i = 0; i < f.step_expanded.size(); ++i)
          if (f.step_expanded[i]) last = i;
        if (last + 1 < e.steps.size()) ++early;
      }
  MESSAGE(early << " of " << replays << " replays empty the cluster before their last step");
  CHECK(early > 0);  // the case this test is about does occur
}

TEST_CASE(
    "fixed-boundary replay needs the chords split: the unknotted control fails Eq. (1) with them, not "
    "without") {
  // With the boundary in place, a chord (an interior simplex whose vertices all lie on the
  // boundary) inside the remaining ball is a hole in the cluster mesh, and Alg. 2's steps around
  // it fail Eq. (1). The control has 316 chord simplices; shelling_fallback splits them first.
  const GridComplex control = unknotted_hole_ball();
  std::size_t failing = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    CAPTURE(seed);
    const ShellingResult s = find_shelling(control.mesh, {4, seed, {}});
    REQUIRE(s.found);
    const ShellingExpansion e = shelling_to_expansion_sequence(control.mesh, s.order);
    REQUIRE(e.ok);
    // The cluster mesh is checked every 100 expansions to be simply connected: with the chords
    // in place it is not, at some check, on the failing seeds (35 and 1 of 192 checks).
    const FixedBoundaryReplay raw = replay_with_fixed_boundary(control.mesh, e, 100);
    CHECK(raw.checks == 1 + (raw.expansions + 99) / 100);
    if (!raw.ok) {
      ++failing;
      CHECK(raw.eq1_failures > 0);
      CHECK(raw.check_failures > 0);
    }
    const ShellingFallback f = shelling_fallback(control.mesh, {4, seed, {}}, 100);
    CHECK(f.replay.checks > 0);
    CHECK(f.replay.check_failures == 0);
    CHECK(f.chords.size() == 316);
    REQUIRE(f.replayed);
    CHECK_MESSAGE(f.replay.ok, f.message);
    CHECK(f.replay.eq1_failures == 0);
    CHECK(f.message.find("after 316 chord splits") != std::string::npos);
    // Every chord vertex is a new interior vertex, expanded by the replay like an input vertex.
    for (const ChordSplit& c : f.chords) CHECK(c.vertex >= control.mesh.num_vertices());
    const std::vector<char> interior = interior_vertex_flags(control.mesh);
    const auto initial = static_cast<std::size_t>(std::count(interior.begin(), interior.end(), 1));
    CHECK(f.replay.input_expansions == initial);
    CHECK(f.chord_expansions == f.chords.size());
  }
  CHECK(failing >= 1);  // the case this test is about does occur
}

TEST_CASE("cheapest steps first: still a shelling, with fewer cluster-edge splits that need inflation") {
  // ShellingOptions::interior orders removals by what Alg. 2 makes of them with the boundary in
  // place; the geometric replay (algorithm/expansion/shelling_replay.cpp) pays only for splits of
  // all-interior simplices, the edge splits above all.
  const GridComplex g = grid_complex(4, 4, 4);
  const std::vector<char> interior = interior_vertex_flags(g.mesh);
  ShellingOptions cheap;
  cheap.interior = &interior;
  const ShellingResult seeded = find_shelling(g.mesh);
  const ShellingResult cheapest = find_shelling(g.mesh, cheap);
  REQUIRE(seeded.found);
  REQUIRE(cheapest.found);
  const auto all_interior_splits = [&](const ShellingResult& s) {
    const ShellingExpansion e = shelling_to_expansion_sequence(g.mesh, s.order);
    REQUIRE(e.ok);
    return replay_with_fixed_boundary(g.mesh, e).empty_cone_edge_splits;
  };
  const std::size_t seeded_splits = all_interior_splits(seeded),
                    cheapest_splits = all_interior_splits(cheapest);
  MESSAGE("edge splits facing a mirrored pair: seeded ", seeded_splits, ", cheapest first ", cheapest_splits);
  CHECK(cheapest_splits < seeded_splits);
  // Every removal still leaves a ball (checked here on the first half, at every step).
  check_removals_leave_balls(g.mesh, cheapest.order, cheapest.order.size() / 2);
  // The same order for every thread count.
  cheap.max_attempts = 4;
  cheap.threads = 3;
  CHECK(find_shelling(g.mesh, cheap).order == cheapest.order);
}
