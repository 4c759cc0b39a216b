// ShellingCounts (topology/shelling_counts.hpp) gives the answer of is_shelling_removable at every
// state a removal sequence reaches, and find_shelling, which uses it, removes the tets in the same
// order as the greedy search written with the star walks.
#include <doctest/doctest.h>

#include <queue>
#include <random>

#include "topology/generators.hpp"
#include "topology/nobuenoss.hpp"
#include "topology/shelling.hpp"
#include "topology/shelling_counts.hpp"

using namespace cmx::topology;

namespace {

// Removes tets one at a time (mostly removable ones, now and then any remaining one, so that
// the counts also meet states no shelling reaches) and compares both rules on every remaining tet
// after each removal. Returns the number of comparisons; `mismatches` counts the differing answers.
std::size_t compare_along_removals(const TetMesh& m, std::uint64_t seed, std::size_t steps,
                                   std::size_t& mismatches) {
  const TetAdjacency adj = tet_adjacency(m);
  ShellingCounts counts(m, adj);
  std::vector<char> remaining(m.tet_capacity(), 0);
  std::vector<TetId> rest = m.live_tets();
  for (TetId t : rest) remaining[t] = 1;
  std::mt19937_64 rng(seed);
  std::size_t compared = 0;
  for (std::size_t step = 0; step < steps && !rest.empty(); ++step) {
    std::vector<std::size_t> removable;
    for (std::size_t i = 0; i < rest.size(); ++i) {
      const bool expected = is_shelling_removable(m, adj, rest[i], remaining, rest.size());
      mismatches += counts.removable(rest[i]) == expected ? 0 : 1;
      ++compared;
      if (expected) removable.push_back(i);
    }
    REQUIRE(counts.remaining_count() == rest.size());
    const bool any = removable.empty() || rng() % 5 == 0;
    const std::size_t i = any ? rng() % rest.size() : removable[rng() % removable.size()];
    counts.remove(rest[i]);
    remaining[rest[i]] = 0;
    rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(i));
  }
  return compared;
}

// The greedy search of find_shelling as it was written before the counts: every candidate
// re-checked by the star walks, duplicates left in the queue.
ShellingResult reference_greedy(const TetMesh& m, std::uint64_t seed, std::size_t attempts) {
  ShellingResult r;
  const std::vector<TetId> live = m.live_tets();
  const TetAdjacency adj = tet_adjacency(m);
  for (std::size_t attempt = 0; attempt < attempts; ++attempt) {
    ++r.attempts;
    std::mt19937_64 rng(seed + 0x9e3779b97f4a7c15ull * attempt);
    std::vector<std::uint64_t> key(m.tet_capacity(), 0);
    for (TetId t : live) key[t] = rng();
    std::vector<char> remaining(m.tet_capacity(), 0);
    for (TetId t : live) remaining[t] = 1;
    std::size_t count = live.size();
    using Item = std::pair<std::uint64_t, TetId>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    for (TetId t : live)
      if (is_shelling_removable(m, adj, t, remaining, count)) queue.push({key[t], t});
    std::vector<TetId> order;
    while (!queue.empty() && count > 0) {
      const TetId t = queue.top().second;
      queue.pop();
      if (!remaining[t] || !is_shelling_removable(m, adj, t, remaining, count)) continue;
      remaining[t] = 0;
      --count;
      order.push_back(t);
      for (VertexId v : m.tet(t))
        for (TetId o : m.tets_of(v))
          if (remaining[o] && is_shelling_removable(m, adj, o, remaining, count)) queue.push({key[o], o});
    }
    r.best_removed = std::max(r.best_removed, order.size());
    if (count == 0) {
      r.found = true;
      r.order = std::move(order);
      return r;
    }
  }
  return r;
}

}  // namespace

TEST_CASE(
    "the counted removability rule answers as the star walks do, at every state of a removal sequence") {
  std::size_t mismatches = 0;
  CHECK(compare_along_removals(grid_complex(3, 3, 3).mesh, 1, 200, mismatches) > 10000);
  CHECK(compare_along_removals(grid_complex(2, 3, 4).mesh, 2, 160, mismatches) > 5000);
  const GridComplex knot = knotted_hole_ball();
  CHECK(compare_along_removals(knot.mesh, 3, 25, mismatches) > 1000);
  CHECK(mismatches == 0);
}

TEST_CASE("find_shelling removes in the order of the greedy search written with the star walks") {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const TetMesh g = grid_complex(3, 3, 3).mesh;
    const ShellingResult a = find_shelling(g, {4, seed, {}});
    const ShellingResult b = reference_greedy(g, seed, 4);
    REQUIRE(a.found == b.found);
    CHECK(a.attempts == b.attempts);
    CHECK(a.order == b.order);
  }
  // A ball no greedy attempt shells: the attempts must peel the same number of tets.
  const GridComplex knot = knotted_hole_ball();
  const ShellingResult a = find_shelling(knot.mesh, {3, 5, {}});
  const ShellingResult b = reference_greedy(knot.mesh, 5, 3);
  CHECK_FALSE(a.found);
  CHECK_FALSE(b.found);
  CHECK(a.best_removed == b.best_removed);
  CHECK(a.best_removed > 0);
}

TEST_CASE("find_shelling gives the same result for every thread count") {
  const auto same = [](const ShellingResult& a, const ShellingResult& b) {
    return a.found == b.found && a.attempts == b.attempts && a.best_removed == b.best_removed &&
           a.order == b.order;
  };
  const GridComplex grid = grid_complex(3, 3, 3);
  const GridComplex knot = knotted_hole_ball();
  for (const TetMesh* m : {&grid.mesh, &knot.mesh})
    for (std::uint64_t seed : {1u, 7u}) {
      ShellingOptions o{5, seed, {}, 1};
      const ShellingResult one = find_shelling(*m, o);
      for (std::size_t threads : {2u, 3u, 8u}) {
        o.threads = threads;
        CHECK(same(find_shelling(*m, o), one));
      }
    }
  // A deadline is polled between batches: with 3 at once and a stop after the first poll, the
  // first batch of 3 attempts runs on the knotted hole, which no attempt shells.
  std::size_t polls = 0;
  const ShellingResult cut = find_shelling(knot.mesh, {8, 1, [&polls] { return ++polls >= 1; }, 3});
  CHECK_FALSE(cut.found);
  CHECK(cut.attempts == 3);
  CHECK(cut.stopped_at_deadline);
}
