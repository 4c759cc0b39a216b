// cmx::map_to_domain on plain arrays: the same map as the layers' own call, exact and double
// verdicts, every failure a status with a message naming the culprit.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "generators/domain_generators.hpp"
#include "algorithm/map.hpp"
#include "arith/rational.hpp"
#include "arith/rounding.hpp"
#include "cmx/map.hpp"

namespace {

struct Arrays {
  std::vector<cmx::Point3d> vertices;
  std::vector<cmx::Tet> tets;
};

// A perturbed 3x3x3 grid (one interior layer): small, yet a real map (interior vertices move).
Arrays grid() {
  const cmx::generators::GeneratedDomain d = cmx::generators::perturbed_grid(3, 3, 3, 7);
  Arrays a;
  a.vertices = d.double_positions();
  for (const auto t : d.mesh.live_tets()) {
    const auto& q = d.mesh.tet(t);
    a.tets.push_back({q[0], q[1], q[2], q[3]});
  }
  return a;
}

cmx::MapOptions quick() {
  cmx::MapOptions o;
  o.threads = 1;
  return o;
}

// Exact orientation of a target tet, from the returned text.
int exact_orientation(const cmx::MapResult& r, const cmx::Tet& t) {
  std::array<std::array<cmx::Rational, 3>, 4> p;
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) p[i][k] = *cmx::parse_rational(r.target_exact[t[i]][k]);
  std::array<std::array<cmx::Rational, 3>, 3> m;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) m[i][k] = p[i + 1][k] - p[0][k];
  const cmx::Rational det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                            m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                            m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return sgn(det);
}

}  // namespace

TEST_CASE("map_to_domain on arrays gives the layers' map, verified, with positive exact tets") {
  const Arrays a = grid();
  const std::vector<std::uint32_t> ids = cmx::boundary_vertices(a.tets, a.vertices.size());
  const cmx::ShapeBoundary shape = cmx::boundary_for_shape(a.vertices, a.tets, "sphere");
  REQUIRE(shape.ids == ids);
  cmx::MapOptions o = quick();
  o.init = cmx::InitialMap::shrink;
  const cmx::MapResult r = cmx::map_to_domain(a.vertices, a.tets, shape.ids, shape.positions, o);
  REQUIRE_MESSAGE(r.ok(), r.message);
  CHECK(r.message.empty());
  CHECK(r.exact_valid);
  CHECK(r.double_valid);
  CHECK(r.input_vertices == a.vertices.size());
  CHECK(r.target.size() == r.target_exact.size());
  CHECK(r.source.size() == r.target_exact.size());
  for (const auto& t : r.tets) CHECK(exact_orientation(r, t) > 0);
  // The input's vertices keep their source positions and their boundary positions.
  for (std::size_t v = 0; v < a.vertices.size(); ++v) CHECK(r.source[v] == a.vertices[v]);
  for (std::size_t i = 0; i < shape.ids.size(); ++i) {
    const auto v = shape.ids[i];
    for (int k = 0; k < 3; ++k)
      CHECK(*cmx::parse_rational(r.target_exact[v][k]) == cmx::rational_from_double(shape.positions[i][k]));
  }
  // The homogeneous form is the same point.
  for (std::size_t v = 0; v < r.target_exact.size(); ++v) {
    const auto& h = r.target_homogeneous[v];
    const cmx::Rational w(h[3]);
    REQUIRE(w > 0);
    for (int k = 0; k < 3; ++k) CHECK(cmx::Rational(h[k]) / w == *cmx::parse_rational(r.target_exact[v][k]));
  }
  CHECK(r.report_json.find("\"exact_valid\": true") != std::string::npos);

  // The layers' own call on the same problem gives the same exact target, vertex for vertex.
  cmx::algorithm::MapProblem p;
  for (const auto& q : a.vertices)
    p.source.push_back(
        {cmx::rational_from_double(q[0]), cmx::rational_from_double(q[1]), cmx::rational_from_double(q[2])});
  for (const auto& t : a.tets) p.tets.push_back(cmx::topology::make_tet(t));
  p.boundary_vertices = shape.ids;
  for (const auto& q : shape.positions)
    p.boundary_positions.push_back(
        {cmx::rational_from_double(q[0]), cmx::rational_from_double(q[1]), cmx::rational_from_double(q[2])});
  cmx::algorithm::MapOptions internal;
  internal.threads = 1;
  const cmx::algorithm::MapResult direct = cmx::algorithm::map_to_domain(p, internal);
  REQUIRE(direct.target.size() == r.target_exact.size());
  for (std::size_t v = 0; v < direct.target.size(); ++v)
    for (int k = 0; k < 3; ++k) CHECK(cmx::to_string(direct.target[v].coordinate(k)) == r.target_exact[v][k]);
  CHECK(direct.doubles.target == r.target);
}

TEST_CASE("map_to_domain: exact text input, raw pointers and the default init give verified maps") {
  const Arrays a = grid();
  const cmx::ShapeBoundary shape = cmx::boundary_for_shape(a.vertices, a.tets, "tet");
  const cmx::MapResult from_doubles =
      cmx::map_to_domain(a.vertices, a.tets, shape.ids, shape.positions, quick());
  REQUIRE_MESSAGE(from_doubles.ok(), from_doubles.message);
  CHECK(from_doubles.exact_valid);
  // The same problem as exact text (the doubles' exact values) maps to the same target.
  std::vector<cmx::ExactPoint3> v_text, p_text;
  const auto text = [](const cmx::Point3d& q) {
    return cmx::ExactPoint3{cmx::to_string(cmx::rational_from_double(q[0])),
                            cmx::to_string(cmx::rational_from_double(q[1])),
                            cmx::to_string(cmx::rational_from_double(q[2]))};
  };
  for (const auto& q : a.vertices) v_text.push_back(text(q));
  for (const auto& q : shape.positions) p_text.push_back(text(q));
  const cmx::MapResult from_text = cmx::map_to_domain(v_text, a.tets, shape.ids, p_text, quick());
  REQUIRE_MESSAGE(from_text.ok(), from_text.message);
  CHECK(from_text.target_exact == from_doubles.target_exact);
  // Raw pointers and counts.
  const cmx::MapResult from_raw =
      cmx::map_to_domain(a.vertices.data()->data(), a.vertices.size(), a.tets.data()->data(), a.tets.size(),
                         shape.ids.data(), shape.positions.data()->data(), shape.ids.size(), quick());
  REQUIRE_MESSAGE(from_raw.ok(), from_raw.message);
  CHECK(from_raw.target_exact == from_doubles.target_exact);
  CHECK(from_raw.tets == from_doubles.tets);
}

TEST_CASE("map_to_domain: an initial map that is already valid comes back unchanged") {
  const Arrays a = grid();
  const std::vector<std::uint32_t> ids = cmx::boundary_vertices(a.tets, a.vertices.size());
  std::vector<cmx::Point3d> positions;
  for (const auto v : ids) positions.push_back(a.vertices[v]);
  cmx::MapOptions o = quick();
  o.init = cmx::InitialMap::given;
  o.initial_target_doubles = a.vertices;  // the identity: no tet to repair
  const cmx::MapResult r = cmx::map_to_domain(a.vertices, a.tets, ids, positions, o);
  REQUIRE_MESSAGE(r.ok(), r.message);
  CHECK(r.tets == a.tets);
  CHECK(r.target == a.vertices);
}

namespace {
// A refused run: the status and reason, a message holding `words`, and no map.
void expect(const cmx::MapResult& r, cmx::MapStatus status, const std::string& words, const std::string& reason = "") {
  CHECK(r.status == status);
  CHECK(r.reason == (reason.empty() ? cmx::to_string(status) : reason));
  CHECK_FALSE(r.ok());
  CHECK_MESSAGE(r.message.find(words) != std::string::npos, r.message);
  CHECK(r.tets.empty());
  CHECK(r.target.empty());
}
}  // namespace

TEST_CASE("map_to_domain: bad input is a status with a message naming the culprit") {
  const Arrays a = grid();
  const cmx::ShapeBoundary shape = cmx::boundary_for_shape(a.vertices, a.tets, "sphere");
  {
    auto v = a.vertices;
    v[5][1] = std::numeric_limits<double>::quiet_NaN();
    expect(cmx::map_to_domain(v, a.tets, shape.ids, shape.positions, quick()), cmx::MapStatus::invalid_input,
           "vertex 5: coordinate y is NaN");
  }
  {
    auto p = shape.positions;
    p[2][0] = std::numeric_limits<double>::infinity();
    expect(cmx::map_to_domain(a.vertices, a.tets, shape.ids, p, quick()), cmx::MapStatus::invalid_input,
           "boundary position of vertex " + std::to_string(shape.ids[2]) + ": coordinate x is infinite");
  }
  {
    auto t = a.tets;
    t[3][2] = std::uint32_t(a.vertices.size() + 10);
    const auto r = cmx::map_to_domain(a.vertices, t, shape.ids, shape.positions, quick());
    expect(r, cmx::MapStatus::invalid_input, std::to_string(a.vertices.size() + 10));
  }
  {
    auto ids = shape.ids;
    auto p = shape.positions;
    ids.pop_back();
    p.pop_back();
    expect(cmx::map_to_domain(a.vertices, a.tets, ids, p, quick()), cmx::MapStatus::invalid_input,
           std::to_string(shape.ids.back()), "boundary_mismatch");
  }
  {
    auto p = shape.positions;
    for (auto& q : p) q[0] = -q[0];  // mirrored: the boundary turned inside out
    expect(cmx::map_to_domain(a.vertices, a.tets, shape.ids, p, quick()), cmx::MapStatus::invalid_input, "",
           "boundary_orientation");
  }
  {
    auto p = shape.positions;
    p.pop_back();
    expect(cmx::map_to_domain(a.vertices, a.tets, shape.ids, p, quick()), cmx::MapStatus::invalid_input,
           "boundary ids but");
  }
  {
    std::vector<cmx::ExactPoint3> v;
    for (const auto& q : a.vertices)
      v.push_back({std::to_string(q[0]), std::to_string(q[1]), std::to_string(q[2])});
    v[4][2] = "1/0";
    std::vector<cmx::ExactPoint3> p;
    for (const auto& q : shape.positions)
      p.push_back({std::to_string(q[0]), std::to_string(q[1]), std::to_string(q[2])});
    expect(cmx::map_to_domain(v, a.tets, shape.ids, p, quick()), cmx::MapStatus::invalid_input,
           "vertex 4: coordinate z '1/0' is not an exact number");
  }
  CHECK_THROWS_AS(cmx::boundary_for_shape(a.vertices, a.tets, "teapot"), cmx::Error);
  CHECK_THROWS_WITH_AS(cmx::boundary_for_shape(a.vertices, a.tets, "tet", "nearest"),
                       "unknown corner choice 'nearest' (random or farthest)", cmx::Error);
  CHECK_THROWS_AS(cmx::boundary_vertices(std::vector<cmx::Tet>{{0, 1, 2, 9}}, 4), cmx::Error);
}

TEST_CASE("map_to_domain: bad options are statuses with messages naming the option") {
  const Arrays a = grid();
  const cmx::ShapeBoundary shape = cmx::boundary_for_shape(a.vertices, a.tets, "sphere");
  {
    cmx::MapOptions o = quick();
    o.order = "sideways";
    expect(cmx::map_to_domain(a.vertices, a.tets, shape.ids, shape.positions, o),
           cmx::MapStatus::invalid_options, "option order: 'sideways'");
    o = quick();
    o.time_limit_seconds = -1;
    expect(cmx::map_to_domain(a.vertices, a.tets, shape.ids, shape.positions, o),
           cmx::MapStatus::invalid_options, "time_limit_seconds");
    o = quick();
    o.filter = "naive";
    expect(cmx::map_to_domain(a.vertices, a.tets, shape.ids, shape.positions, o),
           cmx::MapStatus::invalid_options, "not exact");
    o = quick();
    o.init = cmx::InitialMap::given;  // and no initial target
    expect(cmx::map_to_domain(a.vertices, a.tets, shape.ids, shape.positions, o),
           cmx::MapStatus::invalid_input, "initial target: 0 positions");
  }
}

TEST_CASE("map_to_domain: the stop callback cancels a run") {
  const Arrays a = grid();
  const cmx::ShapeBoundary shape = cmx::boundary_for_shape(a.vertices, a.tets, "star");
  cmx::MapOptions o = quick();
  o.init = cmx::InitialMap::shrink;
  std::size_t polls = 0;
  o.stop = [&] { return ++polls > 3; };
  const cmx::MapResult r = cmx::map_to_domain(a.vertices, a.tets, shape.ids, shape.positions, o);
  CHECK(r.status == cmx::MapStatus::cancelled);
  CHECK(polls > 3);
  CHECK(r.tets.empty());
  CHECK(std::string(cmx::to_string(r.status)) == "cancelled");
}

TEST_CASE("map_to_domain: the trace rows, the statistics and the report fields describe the run") {
  const Arrays a = grid();
  const cmx::ShapeBoundary shape = cmx::boundary_for_shape(a.vertices, a.tets, "sphere");
  cmx::MapOptions o = quick();
  o.init = cmx::InitialMap::shrink;
  std::vector<std::size_t> steps;
  std::size_t rows_without_kind = 0;
  o.trace = [&](const cmx::MapTraceRow& row) {
    steps.push_back(row.step);
    if (row.kind.empty() || row.lp.empty()) ++rows_without_kind;
  };
  const cmx::MapResult r = cmx::map_to_domain(a.vertices, a.tets, shape.ids, shape.positions, o);
  REQUIRE_MESSAGE(r.ok(), r.message);
  // One row per expansion, numbered 1, 2, ...; every interior vertex of the shrink is expanded.
  const cmx::MapStatistics& s = r.statistics;
  const std::size_t expansions = s.expansions_simple + s.expansions_subcluster + s.expansions_star_shapified +
                                 s.expansions_inflated + s.expansions_automatic;
  CHECK(expansions > 0);
  REQUIRE(steps.size() >= expansions);
  for (std::size_t i = 0; i < steps.size(); ++i) CHECK(steps[i] == i + 1);
  CHECK(rows_without_kind == 0);
  // The statistics agree with the arrays returned.
  CHECK(s.input_vertices == a.vertices.size());
  CHECK(s.input_tets == a.tets.size());
  CHECK(s.output_vertices == r.target.size());
  CHECK(s.output_tets == r.tets.size());
  CHECK(s.growth_ratio == doctest::Approx(double(r.tets.size()) / double(a.tets.size())));
  CHECK(s.double_checked);
  CHECK(s.max_bits > 0);
  // report_json is status, reason, message, then report_fields in order.
  REQUIRE_FALSE(r.report_fields.empty());
  std::size_t at = r.report_json.find("\"message\"");
  for (const cmx::ReportField& f : r.report_fields) {
    const std::size_t next = r.report_json.find("\"" + f.key + "\": " + f.json, at);
    CHECK_MESSAGE(next != std::string::npos, f.key);
    at = next;
  }
}

// The count of one expansion statistic in a report ("merged", "flip_collapses", ...).
std::size_t report_count(const cmx::MapResult& r, const std::string& key) {
  const std::size_t at = r.report_json.find("\"" + key + "\": ");
  REQUIRE(at != std::string::npos);
  return std::stoul(r.report_json.substr(at + key.size() + 4));
}

TEST_CASE("map_to_domain: merge and flip_collapse switch those collapses off") {
  const Arrays a = grid();
  const cmx::ShapeBoundary shape = cmx::boundary_for_shape(a.vertices, a.tets, "tet");  // merges here
  cmx::MapOptions o = quick();
  o.init = cmx::InitialMap::shrink;
  const cmx::MapResult all = cmx::map_to_domain(a.vertices, a.tets, shape.ids, shape.positions, o);
  REQUIRE_MESSAGE(all.ok(), all.message);
  REQUIRE(report_count(all, "merged") > 0);
  REQUIRE(report_count(all, "flip_collapses") > 0);
  o.flip_collapse = false;
  const cmx::MapResult no_flips = cmx::map_to_domain(a.vertices, a.tets, shape.ids, shape.positions, o);
  REQUIRE_MESSAGE(no_flips.ok(), no_flips.message);
  CHECK(no_flips.exact_valid);
  CHECK(report_count(no_flips, "flip_collapses") == 0);
  o.merge = false;
  const cmx::MapResult no_merges = cmx::map_to_domain(a.vertices, a.tets, shape.ids, shape.positions, o);
  REQUIRE_MESSAGE(no_merges.ok(), no_merges.message);
  CHECK(no_merges.exact_valid);
  CHECK(report_count(no_merges, "merged") == 0);
}

TEST_CASE("boundary_for_shape with farthest corners: the same vertices, another placement, and it maps") {
  const Arrays a = grid();
  const cmx::ShapeBoundary drawn = cmx::boundary_for_shape(a.vertices, a.tets, "tet");
  const cmx::ShapeBoundary far = cmx::boundary_for_shape(a.vertices, a.tets, "tet", "farthest");
  CHECK(far.ids == drawn.ids);
  CHECK(far.positions != drawn.positions);
  const cmx::MapResult r = cmx::map_to_domain(a.vertices, a.tets, far.ids, far.positions, quick());
  CHECK(r.status == cmx::MapStatus::success);
}
