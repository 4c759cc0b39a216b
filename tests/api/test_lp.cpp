// cmx/lp.hpp: exact Chebyshev centres of known polytopes, every status, both row forms and both
// LP backends; bad values and options are a cmx::Error naming them.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "api_test_util.hpp"
#include "cmx/lp.hpp"

namespace {

using cmx::test::error_of;

using Rows = std::vector<std::array<double, 4>>;
using TextRows = std::vector<std::array<std::string, 4>>;

// lo <= x, y, z <= hi for each axis, as rows a x + b y + c z <= d.
Rows box(const cmx::Point3d& lo, const cmx::Point3d& hi) {
  Rows rows;
  for (std::size_t k = 0; k < 3; ++k) {
    std::array<double, 4> low{0, 0, 0, -lo[k]}, high{0, 0, 0, hi[k]};
    low[k] = -1;
    high[k] = 1;
    rows.push_back(low);
    rows.push_back(high);
  }
  return rows;
}

cmx::ChebyshevCentreOptions with(const std::string& lp, const std::string& norm) {
  cmx::ChebyshevCentreOptions o;
  o.lp = lp;
  o.norm = norm;
  return o;
}

}  // namespace

TEST_CASE("api chebyshev_centre: the unit cube has centre 1/2 exactly and radius 1/2") {
  const Rows cube = box({0, 0, 0}, {1, 1, 1});
  for (const char* lp : {"certified", "exact"})
    for (const char* norm : {"l2-upper", "l1"}) {
      INFO(lp << " " << norm);
      const cmx::ChebyshevCentre r = cmx::chebyshev_centre(cube, with(lp, norm));
      CHECK(r.status == cmx::CentreStatus::interior);
      CHECK(r.ok());
      CHECK(r.centre_exact == cmx::ExactPoint3{"1/2", "1/2", "1/2"});
      CHECK(r.centre == cmx::Point3d{0.5, 0.5, 0.5});
      CHECK(r.radius_exact == "1/2");  // axis normals have an exact norm: no slack in the weight
      CHECK(r.radius == 0.5);
    }
  // The same cube as exact text, with a decimal and a fraction.
  const TextRows text = {{"-1", "0", "0", "0"},  {"1", "0", "0", "1"},  {"0", "-1", "0", "0.0"},
                         {"0", "1", "0", "2/2"}, {"0", "0", "-1", "0"}, {"0", "0", "1", "1e0"}};
  const cmx::ChebyshevCentre t = cmx::chebyshev_centre(text);
  CHECK(t.status == cmx::CentreStatus::interior);
  CHECK(t.centre_exact == cmx::ExactPoint3{"1/2", "1/2", "1/2"});
  CHECK(t.radius_exact == "1/2");
}

TEST_CASE("api chebyshev_centre: a box with thirds, given exactly") {
  // 1/3 <= x <= 2/3, 0 <= y <= 1/3, -1/3 <= z <= 0: a cube of side 1/3 that doubles cannot hold.
  const TextRows rows = {{"-3", "0", "0", "-1"}, {"3", "0", "0", "2"},  {"0", "-1", "0", "0"},
                         {"0", "3", "0", "1"},   {"0", "0", "-3", "1"}, {"0", "0", "1", "0"}};
  const cmx::ChebyshevCentre r = cmx::chebyshev_centre(rows);
  REQUIRE(r.status == cmx::CentreStatus::interior);
  CHECK(r.centre_exact == cmx::ExactPoint3{"1/2", "1/6", "-1/6"});
  CHECK(r.radius_exact == "1/6");
  CHECK(r.centre[1] == 1.0 / 6);  // the nearest double
  CHECK(r.radius == 1.0 / 6);
}

TEST_CASE("api chebyshev_centre: the corner tetrahedron's inradius, from below") {
  // x, y, z >= 0 and x + y + z <= 1: the inscribed ball has radius 1/(3 + sqrt 3) and centre
  // (r, r, r). The weight of the slanted row is an upper bound of sqrt 3, so r is at most a few
  // ulps below the true radius, never above.
  Rows rows = {{-1, 0, 0, 0}, {0, -1, 0, 0}, {0, 0, -1, 0}, {1, 1, 1, 1}};
  const cmx::ChebyshevCentre r = cmx::chebyshev_centre(rows);
  REQUIRE(r.status == cmx::CentreStatus::interior);
  const double exact = 1 / (3 + std::sqrt(3.0));
  CHECK(r.radius <= exact * (1 + 1e-15));
  CHECK(r.radius >= exact * (1 - 1e-14));
  CHECK(r.centre_exact[0] == r.radius_exact);
  CHECK(r.centre_exact[1] == r.radius_exact);
  CHECK(r.centre_exact[2] == r.radius_exact);
  // l1 weights: |(1,1,1)|_1 = 3, so r = 1/6: the largest cube of half-side r at (r, r, r).
  const cmx::ChebyshevCentre c = cmx::chebyshev_centre(rows, with("certified", "l1"));
  CHECK(c.radius_exact == "1/6");
  CHECK(c.centre_exact == cmx::ExactPoint3{"1/6", "1/6", "1/6"});
}

TEST_CASE("api chebyshev_centre: a long box has an optimal centre on its axis") {
  const cmx::ChebyshevCentre r = cmx::chebyshev_centre(box({0, 0, 0}, {4, 1, 1}));
  REQUIRE(r.status == cmx::CentreStatus::interior);
  CHECK(r.radius_exact == "1/2");
  CHECK(r.centre[0] >= 0.5);
  CHECK(r.centre[0] <= 3.5);
  CHECK(r.centre_exact[1] == "1/2");
  CHECK(r.centre_exact[2] == "1/2");
}

TEST_CASE("api chebyshev_centre: infeasible, flat and unbounded sets are statuses") {
  SUBCASE("x >= 1 and x <= 0 inside a box") {
    Rows rows = box({-5, -5, -5}, {5, 5, 5});
    rows.push_back({-1, 0, 0, -1});
    rows.push_back({1, 0, 0, 0});
    const cmx::ChebyshevCentre r = cmx::chebyshev_centre(rows);
    CHECK(r.status == cmx::CentreStatus::infeasible);
    CHECK_FALSE(r.ok());
    CHECK(r.radius == 0);
  }
  SUBCASE("a zero row 0 <= -1") {
    Rows rows = box({0, 0, 0}, {1, 1, 1});
    rows.push_back({0, 0, 0, -1});
    CHECK(cmx::chebyshev_centre(rows).status == cmx::CentreStatus::infeasible);
  }
  SUBCASE("a flat box: 0 <= x <= 0") {
    const cmx::ChebyshevCentre r = cmx::chebyshev_centre(box({0, 0, 0}, {0, 1, 1}));
    CHECK(r.status == cmx::CentreStatus::empty_interior);
    CHECK(r.radius_exact == "0");
    CHECK(r.centre_exact[0] == "0");
    CHECK(r.centre[1] >= 0);
    CHECK(r.centre[1] <= 1);
  }
  SUBCASE("one half-space, and none") {
    CHECK(cmx::chebyshev_centre(Rows{{1, 0, 0, 1}}).status == cmx::CentreStatus::unbounded);
    CHECK(cmx::chebyshev_centre(Rows{}).status == cmx::CentreStatus::unbounded);
    CHECK(cmx::chebyshev_centre(Rows{{0, 0, 0, 1}}).status == cmx::CentreStatus::unbounded);
  }
}

TEST_CASE("api chebyshev_centre: rows of the form a x + b y + c z + d >= 0, negated") {
  // x >= 0 is 1 x + 0 >= 0, i.e. the row (-1, 0, 0, 0); x <= 2 is -x + 2 >= 0, the row (1, 0, 0, 2).
  Rows geq = {{1, 0, 0, 0}, {-1, 0, 0, 2}, {0, 1, 0, 0}, {0, -1, 0, 2}, {0, 0, 1, 0}, {0, 0, -1, 2}};
  for (auto& row : geq)
    for (std::size_t k = 0; k < 3; ++k) row[k] = -row[k];
  const cmx::ChebyshevCentre r = cmx::chebyshev_centre(geq);
  CHECK(r.centre_exact == cmx::ExactPoint3{"1", "1", "1"});
  CHECK(r.radius_exact == "1");
}

TEST_CASE("api chebyshev_centre: bad values and options throw cmx::Error naming them") {
  Rows rows = box({0, 0, 0}, {1, 1, 1});
  rows[2][2] = std::numeric_limits<double>::quiet_NaN();
  CHECK(error_of([&] { (void)cmx::chebyshev_centre(rows); }).find("row 2, c is NaN") != std::string::npos);
  rows[2][2] = 0;
  rows[4][3] = -std::numeric_limits<double>::infinity();
  CHECK(error_of([&] { (void)cmx::chebyshev_centre(rows); }).find("row 4, d is infinite") !=
        std::string::npos);
  const TextRows text = {{"1", "0", "0", "1"}, {"-1", "0", "zero", "0"}};
  CHECK(error_of([&] { (void)cmx::chebyshev_centre(text); }).find("row 1, c 'zero' is not an exact number") !=
        std::string::npos);
  const Rows cube = box({0, 0, 0}, {1, 1, 1});
  CHECK(error_of([&] { (void)cmx::chebyshev_centre(cube, with("simplex", "l1")); }).find("lp 'simplex'") !=
        std::string::npos);
  CHECK(error_of([&] { (void)cmx::chebyshev_centre(cube, with("exact", "l3")); }).find("norm 'l3'") !=
        std::string::npos);
  cmx::ChebyshevCentreOptions o;
  o.weight_bits = 54;
  CHECK(error_of([&] { (void)cmx::chebyshev_centre(cube, o); }).find("weight_bits 54") != std::string::npos);
}

TEST_CASE("api chebyshev_centre: status names") {
  CHECK(std::string(cmx::to_string(cmx::CentreStatus::interior)) == "interior");
  CHECK(std::string(cmx::to_string(cmx::CentreStatus::empty_interior)) == "empty_interior");
  CHECK(std::string(cmx::to_string(cmx::CentreStatus::infeasible)) == "infeasible");
  CHECK(std::string(cmx::to_string(cmx::CentreStatus::unbounded)) == "unbounded");
}
