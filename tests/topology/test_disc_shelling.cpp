// Shelling a triangulated disc onto the star of a vertex (topology/disc_shelling.hpp): every
// step leaves a disc containing the star, the steps are of the kinds claimed, and what is left
// at the end is exactly the star.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <set>

#include "topology/disc_shelling.hpp"

namespace {

using cmx::topology::DiscShellingKind;
using cmx::topology::Triangle;
using cmx::topology::VertexId;

// An n x n grid of vertices, each cell cut by a diagonal whose direction the seed draws.
std::vector<Triangle> grid_disc(std::uint32_t n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<Triangle> out;
  const auto id = [n](std::uint32_t i, std::uint32_t j) { return VertexId{i * n + j}; };
  for (std::uint32_t i = 0; i + 1 < n; ++i)
    for (std::uint32_t j = 0; j + 1 < n; ++j) {
      const VertexId a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (rng() % 2) {
        out.push_back({a, b, c});
        out.push_back({a, c, d});
      } else {
        out.push_back({a, b, d});
        out.push_back({b, c, d});
      }
    }
  return out;
}

bool has(const Triangle& t, VertexId v) { return std::find(t.begin(), t.end(), v) != t.end(); }

std::vector<Triangle> star_of(const std::vector<Triangle>& disc, VertexId w) {
  std::vector<Triangle> out;
  for (const Triangle& t : disc)
    if (has(t, w)) out.push_back(t);
  return out;
}

// Replays the steps on the disc, checking after each that a disc containing star(w) is left and
// that the step's kind matches the triangle's free edges before it went.
void check_replay(const std::vector<Triangle>& disc, VertexId w, const cmx::topology::DiscShelling& s) {
  std::vector<Triangle> left = disc;
  for (const auto& step : s.steps) {
    const auto it = std::find(left.begin(), left.end(), step.triangle);
    REQUIRE(it != left.end());
    CHECK_FALSE(has(step.triangle, w));
    std::set<VertexId> before;
    for (const Triangle& t : left) before.insert(t.begin(), t.end());
    left.erase(it);
    std::set<VertexId> after;
    for (const Triangle& t : left) after.insert(t.begin(), t.end());
    REQUIRE(cmx::topology::is_disc(left));
    if (step.kind == DiscShellingKind::ear) {
      CHECK(before.size() == after.size() + 1);  // the ear leaves
      CHECK_FALSE(after.count(step.apex));
    } else {
      CHECK(before.size() == after.size());  // no vertex leaves
      CHECK(has(step.triangle, step.free_edge[0]));
      CHECK(has(step.triangle, step.free_edge[1]));
      CHECK(after.count(step.apex));
    }
  }
  CHECK(left == s.left);
}

// The grid disc after `flips` random flips of interior edges (an edge (a, b) between triangles
// (a, b, c) and (b, a, d) becomes (c, d) when (c, d) is not an edge yet): irregular degrees,
// vertices of valence 3 to 10, the same disc topologically.
std::vector<Triangle> flipped_disc(std::uint32_t n, std::uint32_t seed, int flips) {
  std::vector<Triangle> tris = grid_disc(n, seed);
  std::mt19937 rng(seed * 7919u);
  const auto shares = [](const Triangle& t, VertexId a, VertexId b) { return has(t, a) && has(t, b); };
  for (int f = 0; f < flips; ++f) {
    const std::size_t i = rng() % tris.size();
    const std::size_t k = rng() % 3;
    const VertexId a = tris[i][k], b = tris[i][(k + 1) % 3], c = tris[i][(k + 2) % 3];
    std::size_t j = tris.size();
    for (std::size_t x = 0; x < tris.size(); ++x)
      if (x != i && shares(tris[x], a, b)) j = x;
    if (j == tris.size()) continue;  // a boundary edge
    VertexId d = tris[j][0];
    for (VertexId y : tris[j])
      if (y != a && y != b) d = y;
    const bool cd_exists = std::any_of(tris.begin(), tris.end(), [&](const Triangle& t) { return shares(t, c, d); });
    if (cd_exists) continue;
    tris[i] = {c, a, d};
    tris[j] = {d, b, c};
  }
  return tris;
}

}  // namespace

TEST_CASE("is_disc: a grid is a disc, a pinched pair, a bowtie and an annulus are not") {
  CHECK(cmx::topology::is_disc(grid_disc(4, 1)));
  CHECK(cmx::topology::is_disc(std::vector<Triangle>{{VertexId{0}, VertexId{1}, VertexId{2}}}));
  // Two triangles sharing a vertex only: a bowtie.
  CHECK_FALSE(cmx::topology::is_disc(std::vector<Triangle>{{VertexId{0}, VertexId{1}, VertexId{2}},
                                                            {VertexId{0}, VertexId{3}, VertexId{4}}}));
  // A 3 x 3 grid without its centre cell's two triangles: an annulus (two boundary cycles).
  std::vector<Triangle> annulus = grid_disc(4, 7);
  annulus.erase(annulus.begin() + 8, annulus.begin() + 10);
  CHECK_FALSE(cmx::topology::is_disc(annulus));
  CHECK_FALSE(cmx::topology::is_disc(std::vector<Triangle>{}));
}

TEST_CASE("disc shelling onto a star: grids of several sizes and diagonals, every witness") {
  for (std::uint32_t n : {2u, 3u, 5u})
    for (std::uint32_t seed = 1; seed <= 4; ++seed) {
      const std::vector<Triangle> disc = grid_disc(n, seed);
      for (std::uint32_t w = 0; w < n * n; ++w) {
        CAPTURE(n);
        CAPTURE(seed);
        CAPTURE(w);
        const auto s = cmx::topology::shell_disc_onto_star(disc, VertexId{w});
        REQUIRE_MESSAGE(s.complete, s.message);
        CHECK(s.message.empty());
        CHECK(s.steps.size() == disc.size() - star_of(disc, VertexId{w}).size());
        CHECK(s.left == star_of(disc, VertexId{w}));
        check_replay(disc, VertexId{w}, s);
      }
    }
}

TEST_CASE("disc shelling: both kinds of step occur, and a free edge is never taken whose apex is on the boundary") {
  const std::vector<Triangle> disc = grid_disc(6, 3);
  const auto s = cmx::topology::shell_disc_onto_star(disc, VertexId{14});
  REQUIRE(s.complete);
  const auto count = [&](DiscShellingKind k) {
    return std::count_if(s.steps.begin(), s.steps.end(), [k](const auto& x) { return x.kind == k; });
  };
  CHECK(count(DiscShellingKind::ear) > 0);
  CHECK(count(DiscShellingKind::free_edge) > 0);
  check_replay(disc, VertexId{14}, s);
}

TEST_CASE("disc shelling: the star alone needs no step, and bad inputs are named, not shelled") {
  // A hexagon fan around vertex 0.
  std::vector<Triangle> fan;
  for (std::uint32_t i = 1; i <= 6; ++i) fan.push_back({VertexId{0}, VertexId{i}, VertexId{i % 6 + 1}});
  const auto s = cmx::topology::shell_disc_onto_star(fan, VertexId{0});
  CHECK(s.complete);
  CHECK(s.steps.empty());
  CHECK(s.left == fan);

  const auto absent = cmx::topology::shell_disc_onto_star(fan, VertexId{9});
  CHECK_FALSE(absent.complete);
  CHECK(absent.message.find("witness 9 is not a vertex") != std::string::npos);

  std::vector<Triangle> three_on_an_edge = {{VertexId{0}, VertexId{1}, VertexId{2}},
                                            {VertexId{0}, VertexId{1}, VertexId{3}},
                                            {VertexId{0}, VertexId{1}, VertexId{4}}};
  const auto bad = cmx::topology::shell_disc_onto_star(three_on_an_edge, VertexId{2});
  CHECK_FALSE(bad.complete);
  CHECK(bad.message.find("edge (0, 1) is in 3 triangles") != std::string::npos);

  std::vector<Triangle> twice = {{VertexId{0}, VertexId{1}, VertexId{2}}, {VertexId{2}, VertexId{1}, VertexId{0}}};
  CHECK(cmx::topology::shell_disc_onto_star(twice, VertexId{0}).message.find("listed twice") != std::string::npos);
}

TEST_CASE("disc shelling: a witness on the boundary of a long strip, from either end") {
  const std::vector<Triangle> disc = grid_disc(2, 1);  // one cell
  std::vector<Triangle> strip;
  for (std::uint32_t k = 0; k < 20; ++k) {  // a 2 x 21 strip of cells, diagonals alternating
    const VertexId a{2 * k}, b{2 * k + 1}, c{2 * k + 3}, d{2 * k + 2};
    if (k % 2) {
      strip.push_back({a, b, c});
      strip.push_back({a, c, d});
    } else {
      strip.push_back({a, b, d});
      strip.push_back({b, c, d});
    }
  }
  REQUIRE(cmx::topology::is_disc(strip));
  for (VertexId w : {VertexId{0}, VertexId{41}, VertexId{20}}) {
    const auto s = cmx::topology::shell_disc_onto_star(strip, w);
    REQUIRE_MESSAGE(s.complete, s.message);
    check_replay(strip, w, s);
  }
  CHECK(cmx::topology::shell_disc_onto_star(disc, VertexId{0}).complete);
}

TEST_CASE("disc shelling: irregular discs from random flips, every witness") {
  for (std::uint32_t seed = 1; seed <= 30; ++seed) {
    const std::vector<Triangle> disc = flipped_disc(5, seed, 300);
    REQUIRE(cmx::topology::is_disc(disc));
    for (std::uint32_t w = 0; w < 25; ++w) {
      CAPTURE(seed);
      CAPTURE(w);
      const auto s = cmx::topology::shell_disc_onto_star(disc, VertexId{w});
      REQUIRE_MESSAGE(s.complete, s.message);
      CHECK(s.left == star_of(disc, VertexId{w}));
      check_replay(disc, VertexId{w}, s);
    }
  }
}
