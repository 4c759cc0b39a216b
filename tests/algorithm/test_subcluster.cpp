// Subcluster expansion (paper Sec. 4.2.5) on shrunk states built by the method's own validation
// and preprocessing: its cones agree with the ordinary expansion cone where they must, a search
// leaves the state as it found it, and a committed plan keeps every invariant.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>

#include "algorithm/expansion/subcluster.hpp"
#include "algorithm/problem/preprocess.hpp"
#include "algorithm/problem/validate_problem.hpp"
#include "algorithm/verify/invariants.hpp"
#include "map_test_util.hpp"
#include "shrunk_state.hpp"

using namespace cmx;
using namespace cmx::algorithm;
using namespace cmx::generators;

using cmx::test::Shrunk;
using cmx::test::shrunk;

namespace {

bool same_halfspace(const InnerHalfSpace& a, const InnerHalfSpace& b) {
  return a.u == b.u && a.w == b.w;
}

// Every half-space of a is one of b's.
bool contained(const std::vector<InnerHalfSpace>& a, const std::vector<InnerHalfSpace>& b) {
  return std::all_of(a.begin(), a.end(), [&](const InnerHalfSpace& h) {
    return std::any_of(b.begin(), b.end(), [&](const InnerHalfSpace& g) { return same_halfspace(h, g); });
  });
}

}  // namespace

TEST_CASE("the coincidence cone of one cluster vertex is its expansion cone") {
  Shrunk s = shrunk(test::problem_from(perturbed_grid(4, 4, 3, 7), "star:2"));
  std::size_t checked = 0;
  for (VertexId v{0}; v < s.e.num_vertices(); ++v) {
    if (!s.e.unexpanded[v]) continue;
    const ExpansionCone a = coincidence_cone(s.e, {v}), b = gather_expansion_cone(s.e, v);
    CAPTURE(v);
    CHECK(a.halfspaces.size() == b.halfspaces.size());
    CHECK(contained(a.halfspaces, b.halfspaces));
    CHECK(contained(b.halfspaces, a.halfspaces));
    ++checked;
  }
  CHECK(checked >= 18);  // the 3 x 3 x 2 interior grid vertices, and any preprocessing splits
}

TEST_CASE("a subcluster search leaves the state unchanged, and its plan keeps every invariant") {
  Shrunk s = shrunk(test::problem_from(perturbed_grid(4, 4, 3, 7), "sphere"));
  const std::vector<HPoint> target = s.e.target;
  const std::vector<char> flags = s.e.unexpanded;
  topology::ClusterLinkWorkspace ws;
  SubclusterCounters counters;
  std::size_t plans = 0;
  for (VertexId v{0}; v < s.e.num_vertices() && plans == 0; ++v) {
    if (!s.e.unexpanded[v]) continue;
    for (std::size_t size = 2; size <= 4 && plans == 0; ++size) {
      const auto plan = plan_subcluster(s.e, v, size, PlacementOptions{}, ws, counters);
      CHECK(s.e.target == target);
      CHECK(s.e.unexpanded == flags);
      if (!plan) continue;
      ++plans;
      REQUIRE(plan->size() >= 2);
      REQUIRE(plan->size() <= size);
      CHECK(plan->front().v != plan->back().v);
      for (const SubclusterMove& m : *plan) {
        CHECK(s.e.unexpanded[m.v] == 1);
        CHECK(m.placement.ok());
        s.e.target[m.v] = m.placement.position;
        s.e.unexpanded[m.v] = 0;
      }
      // Every tet is positive or has two cluster vertices, the cluster is simply connected,
      // boundary and source untouched: the state the loop goes on from.
      CHECK(check_invariants(s.e, s.prescribed) == "");
    }
  }
  CHECK(plans == 1);
  CHECK(counters.candidates > 0);
}

TEST_CASE("the subclusters tried around a vertex: v and its cluster neighbours, smallest first, at most 14") {
  Shrunk s = shrunk(test::problem_from(perturbed_grid(5, 4, 4, 3), "tet"));
  for (VertexId v{0}; v < s.e.num_vertices(); ++v) {
    if (!s.e.unexpanded[v]) continue;
    const auto sets = subcluster_candidates(s.e, v, 4);
    CHECK(sets.size() <= 14);
    std::size_t last = 2;
    for (const auto& set : sets) {
      CHECK(set.front() == v);
      CHECK(set.size() >= last);
      last = set.size();
      for (VertexId w : set) CHECK(s.e.unexpanded[w] == 1);
      CHECK(std::count(set.begin(), set.end(), v) == 1);
    }
    CHECK(subcluster_candidates(s.e, v, 1).empty());
    for (const auto& set : subcluster_candidates(s.e, v, 2)) CHECK(set.size() == 2);
  }
}

TEST_CASE("a deferred cluster vertex joins only the subclusters of deferred vertices") {
  Shrunk s = shrunk(test::problem_from(perturbed_grid(5, 4, 4, 3), "tet"));
  const std::uint32_t half = static_cast<std::uint32_t>(s.e.num_vertices() / 2);
  const auto order = topology::parse_expansion_order("priority,defer:" + std::to_string(half) + "-" +
                                                     std::to_string(s.e.num_vertices()));
  REQUIRE(order);
  std::size_t mixed_without = 0, deferred_sets = 0;
  for (VertexId v{0}; v < s.e.num_vertices(); ++v) {
    if (!s.e.unexpanded[v]) continue;
    for (const auto& set : subcluster_candidates(s.e, v, 4))
      for (VertexId w : set) mixed_without += order->deferred(w) != order->deferred(v) ? 1 : 0;
    for (const auto& set : subcluster_candidates(s.e, v, 4, *order)) {
      deferred_sets += order->deferred(v) ? 1 : 0;
      for (VertexId w : set)
        if (!order->deferred(v)) CHECK(!order->deferred(w));
    }
  }
  CHECK(mixed_without > 0);  // without the order, the two ranges do meet in subclusters
  CHECK(deferred_sets > 0);  // a deferred vertex still has its own, with any neighbour
}
