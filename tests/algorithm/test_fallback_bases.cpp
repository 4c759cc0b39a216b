// The fallback star-shapification (refinement/shelled_star_shapify.cpp) on bases where bends and
// pushes failed, cut out of the project's own knotted-hole runs and kept as files
// (fallback_bases/README.md): each step replayed on its own, the result checked exactly.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "algorithm/expansion/cluster_expansion.hpp"
#include "algorithm/expansion/cone_base.hpp"
#include "algorithm/map.hpp"
#include "algorithm/verify/invariants.hpp"
#include "fallback_base.hpp"
#include "topology/cluster_links.hpp"

namespace alg = cmx::algorithm;

namespace {

const std::string data_dir = std::string(CMX_SOURCE_DIR) + "/tests/algorithm/fallback_bases";

// The kept bases, by name; `fails` selects those on which the fallback is known to fail.
std::vector<std::string> bases(bool fails) {
  std::vector<std::string> out;
  for (const auto& f : std::filesystem::directory_iterator(data_dir)) {
    const std::string name = f.path().filename().string();
    if (f.path().extension() == ".base" && (name.find("_fails_") != std::string::npos) == fails)
      out.push_back(name);
  }
  std::sort(out.begin(), out.end());
  return out;
}

bool satisfies_eq1(const alg::Embedding& e, cmx::topology::VertexId v) {
  cmx::topology::ClusterLinkWorkspace ws;
  return cmx::topology::classify_cluster_vertex(e.mesh, v, e.unexpanded, ws).expandable;
}

// The step on a copy of the base: whether it expanded v, and the state after it.
struct Stepped {
  bool expanded = false;
  alg::Embedding state;
  alg::MapStatistics stats;
};
Stepped step(const cmx::test::FallbackBase& b, alg::RefinementStep s) {
  Stepped out;
  out.state = b.state;
  const alg::ExpansionSettings settings;
  out.expanded = alg::refine_by(out.state, b.v, s, settings, out.stats);
  CHECK(out.expanded == !out.state.unexpanded[b.v]);
  return out;
}

// A kept base, checked to be what the data says: a valid state of the method (every invariant),
// v a cluster vertex that satisfies Eq. (1), on which bends and pushes fail.
cmx::test::FallbackBase read_checked(const std::string& name) {
  cmx::test::FallbackBase b = cmx::test::read_fallback_base(data_dir + "/" + name);
  REQUIRE(alg::check_invariants(b.state, cmx::test::prescribed_of(b.state)).empty());
  REQUIRE(b.state.unexpanded[b.v]);
  REQUIRE(satisfies_eq1(b.state, b.v));
  CHECK_FALSE(step(b, alg::RefinementStep::bends).expanded);
  CHECK_FALSE(step(b, alg::RefinementStep::pushes).expanded);
  return b;
}

}  // namespace

TEST_CASE(
    "fallback bases from the knotted-hole runs: bends and pushes fail, the shelling star-shapification "
    "expands") {
  const std::vector<std::string> names = bases(false);
  REQUIRE(names.size() >= 6);
  for (const std::string& name : names) {
    CAPTURE(name);
    const cmx::test::FallbackBase b = read_checked(name);
    const Stepped shelled = step(b, alg::RefinementStep::shelling);
    CHECK(shelled.expanded);
    CHECK(shelled.stats.shelled_star_shapifications == 1);
    CHECK(shelled.stats.shelled_pushes >= 1);
    // Every invariant, exactly: each tet positive in the target unless it has two cluster
    // vertices, in the source always, the cluster mesh simply connected, the boundary in place.
    CHECK(alg::check_invariants(shelled.state, cmx::test::prescribed_of(b.state)) == "");
    // The pushed vertices are left in the cluster by this step, each a candidate of its own
    // or waiting for the loop: none is lost from the mesh.
    std::size_t cluster_before = 0, cluster_after = 0;
    for (char u : b.state.unexpanded) cluster_before += u ? 1 : 0;
    for (char u : shelled.state.unexpanded) cluster_after += u ? 1 : 0;
    CHECK(cluster_after == cluster_before - 1 + shelled.stats.shelled_pushes);
  }
}

TEST_CASE("a base that is one vertex: no step applied, the inflation of an isolated base vertex expands it") {
  // Kept from the stiff-tet run (fallback_bases/README.md): v satisfies Eq. (1) while its
  // expanded link is one vertex b, with no base edge. The fallback needs a base triangle, the
  // inflation of dangling edges a base edge, the paper's inflation a cut vertex (Sec. 4.2.1):
  // none applies. The repair (inflate_isolated) splits an edge from b to a cluster vertex of the
  // ring around spoke (v, b) and expands the new vertex, which gives v a base edge at b.
  const std::vector<std::string> names = bases(true);
  REQUIRE(names.size() >= 1);
  for (const std::string& name : names) {
    CAPTURE(name);
    const cmx::test::FallbackBase b = read_checked(name);
    const alg::ConeBase base = alg::cone_base(b.state, b.v);
    CHECK(base.verts.size() == 1);
    CHECK(base.adj.empty());
    CHECK_FALSE(step(b, alg::RefinementStep::shelling).expanded);
    const Stepped inflated = step(b, alg::RefinementStep::all);
    CHECK(inflated.expanded);
    CHECK(inflated.stats.isolated_inflations == 1);
    CHECK(alg::check_invariants(inflated.state, cmx::test::prescribed_of(b.state)) == "");
  }
}

TEST_CASE(
    "fallback bases: after the fallback, the refinement of the pushed vertices expands every one of them") {
  // The contraction of the predecessor's star-shapification, in cmx's terms: the vertices the
  // fallback pushed into the cluster, last pushed first, each refined as the loop refines a
  // candidate (refine_by, the whole refinement), in passes until one expands none. On these bases
  // every pushed vertex is expanded, nothing the refinement adds is left in the cluster, and every
  // invariant holds after each expansion. (Inside the loop the contraction is one pass at the
  // next depth, which has fewer steps, and can leave some to the queue: `shelled_pushes_left`,
  // docs/algorithm/expansion.md, "What is not proved".)
  for (const std::string& name : bases(false)) {
    CAPTURE(name);
    const cmx::test::FallbackBase b = read_checked(name);
    Stepped s = step(b, alg::RefinementStep::shelling);
    REQUIRE(s.expanded);
    const std::size_t first_new = b.state.num_vertices();
    std::vector<cmx::topology::VertexId> pushed;  // last pushed first
    for (std::size_t i = s.state.num_vertices(); i-- > first_new;)
      if (s.state.unexpanded[i]) pushed.push_back(cmx::topology::VertexId{static_cast<std::uint32_t>(i)});
    REQUIRE(pushed.size() == s.stats.shelled_pushes);
    const std::size_t before_contraction = s.state.num_vertices();
    for (bool progress = true; progress;) {
      progress = false;
      for (cmx::topology::VertexId c : pushed) {
        if (!s.state.unexpanded[c]) continue;
        const alg::ExpansionSettings settings;
        alg::MapStatistics stats;
        if (!alg::refine_by(s.state, c, alg::RefinementStep::all, settings, stats)) continue;
        progress = true;
        CHECK(alg::check_invariants(s.state, cmx::test::prescribed_of(s.state)) == "");
      }
    }
    for (cmx::topology::VertexId c : pushed) CHECK_FALSE(s.state.unexpanded[c]);
    for (std::size_t i = before_contraction; i < s.state.num_vertices(); ++i)
      CHECK_FALSE(s.state.unexpanded[i]);
  }
}
