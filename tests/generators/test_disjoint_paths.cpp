// Vertex-disjoint paths of least total length (generators/disjoint_paths.hpp): found together,
// they exist where paths found one after another wall each other off; they respect blocked
// vertices and the other targets; and they are empty exactly when no such set exists.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "generators/disjoint_paths.hpp"

using cmx::generators::disjoint_paths;
using Graph = std::vector<std::vector<std::uint32_t>>;

namespace {

struct WeightedGraph {
  Graph neighbors;
  std::map<std::pair<std::uint32_t, std::uint32_t>, double> lengths;
  explicit WeightedGraph(std::size_t n) : neighbors(n) {}
  void add(std::uint32_t a, std::uint32_t b, double len) {
    neighbors[a].push_back(b);
    neighbors[b].push_back(a);
    lengths[{a, b}] = len;
    lengths[{b, a}] = len;
  }
  double length(std::uint32_t a, std::uint32_t b) const { return lengths.at({a, b}); }
};

// Every path is a walk over edges from `from` to its target; no vertex but `from` is shared.
double check_paths(const WeightedGraph& g, std::uint32_t from, const std::vector<std::uint32_t>& to,
                   const std::vector<std::vector<std::uint32_t>>& paths, const std::vector<char>& blocked) {
  REQUIRE(paths.size() == to.size());
  std::set<std::uint32_t> seen;
  double total = 0;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const auto& p = paths[i];
    REQUIRE(p.size() >= 2);
    CHECK(p.front() == from);
    CHECK(p.back() == to[i]);
    for (std::size_t k = 1; k < p.size(); ++k) {
      total += g.length(p[k - 1], p[k]);  // throws when not an edge
      CHECK_FALSE(blocked[p[k]]);
      CHECK(seen.insert(p[k]).second);
    }
  }
  return total;
}

}  // namespace

TEST_CASE("disjoint_paths finds the pair that shortest paths one after another miss") {
  // s = 0 reaches t1 = 3 cheaply through a = 1, which is t2 = 4's only way in: the shortest path
  // to t1 first would leave t2 unreachable; together, t1 goes round through b = 2.
  WeightedGraph g(5);
  g.add(0, 1, 1);
  g.add(0, 2, 5);
  g.add(1, 3, 1);
  g.add(1, 4, 1);
  g.add(2, 3, 1);
  const std::vector<std::uint32_t> to{3, 4};
  const std::vector<char> blocked(5, 0);
  const auto paths = disjoint_paths(g.neighbors, [&](auto a, auto b) { return g.length(a, b); }, 0, to, blocked);
  CHECK(check_paths(g, 0, to, paths, blocked) == doctest::Approx(8));
  CHECK(paths[0] == std::vector<std::uint32_t>{0, 2, 3});
  CHECK(paths[1] == std::vector<std::uint32_t>{0, 1, 4});
}

TEST_CASE("disjoint_paths: a path never runs through another target or a blocked vertex") {
  // A square 0-1-2-3 with a diagonal 0-2 and a pendant route 0-4-3: from 0 to 1 and 3 the short
  // ways are direct; with 2 as a target too, 1's path must not pass 2.
  WeightedGraph g(5);
  g.add(0, 1, 10);
  g.add(1, 2, 1);
  g.add(2, 3, 1);
  g.add(0, 2, 1);
  g.add(0, 4, 1);
  g.add(4, 3, 1);
  std::vector<char> blocked(5, 0);
  const auto len = [&](auto a, auto b) { return g.length(a, b); };
  {
    const std::vector<std::uint32_t> to{1, 2, 3};
    const auto paths = disjoint_paths(g.neighbors, len, 0, to, blocked);
    CHECK(check_paths(g, 0, to, paths, blocked) == doctest::Approx(13));
    CHECK(paths[0] == std::vector<std::uint32_t>{0, 1});
  }
  {
    blocked[4] = 1;  // 3 is now reachable only through 2, which 1 or 2 itself needs
    const std::vector<std::uint32_t> to{2, 3};
    const auto paths = disjoint_paths(g.neighbors, len, 0, to, blocked);
    CHECK(paths.empty());
    const std::vector<std::uint32_t> to_one{3};
    const auto one = disjoint_paths(g.neighbors, len, 0, to_one, blocked);
    CHECK(check_paths(g, 0, to_one, one, blocked) == doctest::Approx(2));
  }
}

TEST_CASE("disjoint_paths: three paths down a tunnel of triangles, as on a triangulated sphere") {
  // A triangulated tube of 3 vertices per ring, capped: rings 1..n, apex 0 at one end and the
  // three targets on the far ring. Three paths from the apex fit only by taking one row each.
  const std::uint32_t rings = 12;
  WeightedGraph g(1 + 3 * rings);
  const auto at = [](std::uint32_t ring, std::uint32_t k) { return 1 + 3 * ring + k % 3; };
  for (std::uint32_t k = 0; k < 3; ++k) g.add(0, at(0, k), 1);
  for (std::uint32_t r = 0; r < rings; ++r)
    for (std::uint32_t k = 0; k < 3; ++k) {
      g.add(at(r, k), at(r, k + 1), 1);
      if (r + 1 < rings) {
        g.add(at(r, k), at(r + 1, k), 1);
        g.add(at(r, k), at(r + 1, k + 1), 1.5);
      }
    }
  const std::vector<std::uint32_t> to{at(rings - 1, 0), at(rings - 1, 2), at(rings - 1, 1)};
  const std::vector<char> blocked(g.neighbors.size(), 0);
  const auto paths = disjoint_paths(g.neighbors, [&](auto a, auto b) { return g.length(a, b); }, 0, to, blocked);
  CHECK(check_paths(g, 0, to, paths, blocked) == doctest::Approx(3 * rings));
  // The same input, the same paths.
  CHECK(disjoint_paths(g.neighbors, [&](auto a, auto b) { return g.length(a, b); }, 0, to, blocked) == paths);
}
