// check_stars (algorithm/local/stars.hpp) finds each way a star set can be wrong: every test
// breaks one thing in a valid set and expects the check to name it.
#include <doctest/doctest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "algorithm/local/stars.hpp"
#include "test_stars_util.hpp"

using namespace cmx;
using namespace cmx::algorithm;
using cmx::test::identity_map;
using cmx::test::InitialMap;

namespace {

struct Case {
  InitialMap map;
  StarSet stars;
};

// A folded region: one or more valid stars, each with interior vertices.
Case valid_case() {
  Case c{identity_map(6), {}};
  cmx::test::fold(c.map, {3, 3, 3}, 1.1, 0.3);
  StarOptions o;
  o.max_share = 1.0;
  c.stars = grow_stars(c.map.mesh(), c.map.target, c.map.boundary, o);
  REQUIRE(c.stars.ok);
  REQUIRE_FALSE(c.stars.stars.empty());
  REQUIRE(check_stars(c.map.mesh(), c.map.target, c.stars) == "");
  return c;
}

// A star made here from its tets alone: what check_stars expects of every field.
Star hand_made_star(const InitialMap& m, std::vector<topology::TetId> tets, const std::vector<TetState>& states) {
  Star s;
  std::sort(tets.begin(), tets.end());
  std::map<topology::Triangle, std::vector<topology::Triangle>> faces;  // sorted corners -> oriented copies
  for (topology::TetId t : tets) {
    const topology::Tet& x = m.mesh().tet(t);
    s.vertices.insert(s.vertices.end(), x.begin(), x.end());
    s.defects += states[t] != TetState::positive ? 1 : 0;
    for (int i = 0; i < 4; ++i) {
      topology::Triangle key = topology::tet_face(x, i);
      std::sort(key.begin(), key.end());
      faces[key].push_back(topology::tet_face(x, i));
    }
  }
  std::sort(s.vertices.begin(), s.vertices.end());
  s.vertices.erase(std::unique(s.vertices.begin(), s.vertices.end()), s.vertices.end());
  std::set<topology::VertexId> on_boundary;
  for (const auto& [key, copies] : faces)
    if (copies.size() == 1) {
      s.boundary.push_back(copies[0]);
      on_boundary.insert(key.begin(), key.end());
    }
  for (topology::VertexId v : s.vertices) {
    const auto around = m.mesh().tets_of(v);
    if (!on_boundary.count(v) && std::all_of(around.begin(), around.end(), [&](topology::TetId t) {
          return std::binary_search(tets.begin(), tets.end(), t);
        }))
      s.interior.push_back(v);
  }
  s.tets = std::move(tets);
  return s;
}

bool says(const std::string& verdict, const std::string& part) {
  CAPTURE(verdict);
  return verdict.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("check_stars accepts a star built by hand and finds a defect outside every star") {
  Case c = valid_case();
  const Star again = hand_made_star(c.map, c.stars.stars[0].tets, c.stars.states);
  c.stars.stars[0] = again;
  CHECK(check_stars(c.map.mesh(), c.map.target, c.stars) == "");
  // Without its first star, that star's defects are in no star.
  c.stars.tets_in_stars -= again.tets.size();
  c.stars.growth_steps -= again.tets.size() - again.defects;
  c.stars.stars.erase(c.stars.stars.begin());
  CHECK(says(check_stars(c.map.mesh(), c.map.target, c.stars), "in no star"));
}

TEST_CASE("check_stars finds a star that is not a ball") {
  Case c = valid_case();
  // Add a far tet, touching the star nowhere: two components.
  Star& s = c.stars.stars[0];
  const topology::TetId far = c.map.mesh().live_tets().back();
  REQUIRE_FALSE(std::binary_search(s.tets.begin(), s.tets.end(), far));
  s.tets.push_back(far);
  CHECK(says(check_stars(c.map.mesh(), c.map.target, c.stars), "not a ball"));
}

TEST_CASE("check_stars finds a boundary that is not star-shaped") {
  // The identity map of a plain grid (every tet positive) and, as a star, the tets of the cells
  // of a U: (0..2, 0, 0) and (0, 1, 0), (2, 1, 0). No point sees the inner faces of both arms.
  InitialMap m = identity_map(4, 1, 0.0);
  StarSet set = grow_stars(m.mesh(), m.target, m.boundary);
  REQUIRE(set.ok);
  REQUIRE(set.stars.empty());
  const auto in_u = [&](topology::TetId t) {
    double c[3] = {0, 0, 0};
    for (topology::VertexId v : m.mesh().tet(t))
      for (int k = 0; k < 3; ++k) c[k] += to_double(cmx::test::coordinate(m, v, k)) / 4;
    const int x = int(c[0]), y = int(c[1]), z = int(c[2]);
    return z == 0 && ((y == 0 && x <= 2) || (y == 1 && (x == 0 || x == 2)));
  };
  std::vector<topology::TetId> tets;
  for (topology::TetId t : m.mesh().live_tets())
    if (in_u(t)) tets.push_back(t);
  REQUIRE(tets.size() == 5 * 6);
  set.stars.push_back(hand_made_star(m, tets, set.states));
  set.tets_in_stars = set.growth_steps = tets.size();
  CHECK(says(check_stars(m.mesh(), m.target, set), "not star-shaped"));
  // The bottom row alone is a box: star-shaped.
  tets.erase(std::remove_if(tets.begin(), tets.end(), [&](topology::TetId t) {
    double y = 0;
    for (topology::VertexId v : m.mesh().tet(t)) y += to_double(cmx::test::coordinate(m, v, 1)) / 4;
    return y > 1;
  }), tets.end());
  set.stars[0] = hand_made_star(m, tets, set.states);
  set.tets_in_stars = set.growth_steps = tets.size();
  CHECK(check_stars(m.mesh(), m.target, set) == "");
}

TEST_CASE("check_stars finds wrong interior vertices, boundary triangles and counts") {
  {
    Case c = valid_case();
    c.stars.stars[0].interior.push_back(c.stars.stars[0].boundary.front()[0]);
    std::sort(c.stars.stars[0].interior.begin(), c.stars.stars[0].interior.end());
    CHECK(says(check_stars(c.map.mesh(), c.map.target, c.stars), "interior vertices"));
  }
  {
    Case c = valid_case();
    std::swap(c.stars.stars[0].boundary.front()[1], c.stars.stars[0].boundary.front()[2]);
    CHECK(says(check_stars(c.map.mesh(), c.map.target, c.stars), "boundary triangles"));
  }
  {
    Case c = valid_case();
    c.stars.stars[0].defects += 1;
    CHECK(says(check_stars(c.map.mesh(), c.map.target, c.stars), "non-positive"));
  }
  {
    Case c = valid_case();
    c.stars.tets_in_stars += 1;
    CHECK(says(check_stars(c.map.mesh(), c.map.target, c.stars), "tets_in_stars"));
  }
  {
    Case c = valid_case();
    for (topology::TetId t : c.stars.stars[0].tets)
      if (c.stars.states[t] != TetState::positive) {
        c.stars.states[t] = TetState::positive;
        break;
      }
    CHECK(says(check_stars(c.map.mesh(), c.map.target, c.stars), "state"));
  }
}

TEST_CASE("check_stars finds stars that share a tet or are out of order") {
  Case c = valid_case();
  c.stars.stars.push_back(c.stars.stars.back());
  c.stars.tets_in_stars += c.stars.stars.back().tets.size();
  CHECK(says(check_stars(c.map.mesh(), c.map.target, c.stars), "earlier star"));
}
