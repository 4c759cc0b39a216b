#pragma once
// Initial maps for the star tests (algorithm/local/stars.hpp), built on the project's own
// domains, and checks of a star set written apart from check_stars.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "generators/domain_generators.hpp"
#include "algorithm/local/stars.hpp"
#include "arith/rational.hpp"
#include "arith/rounding.hpp"
#include "kernel/homogeneous_point.hpp"
#include "kernel/orient.hpp"
#include "kernel/plane.hpp"
#include "lp/chebyshev_center.hpp"
#include "topology/ball_check.hpp"
#include "topology/complex_queries.hpp"

namespace cmx::test {

// A domain with its target positions: the identity map to start from, which every test then
// perturbs. The domain's own boundary must be star-shaped, so that the whole mesh is a valid
// star: a jittered cube is for small grids, not always (9 cells, seed 11 is not), so
// identity_map requires it.
struct InitialMap {
  generators::GeneratedDomain domain;
  std::vector<HPoint> target;
  std::vector<char> boundary;  // boundary vertex flags
  [[nodiscard]] const topology::TetMesh& mesh() const { return domain.mesh; }
};

inline bool boundary_star_shaped(const InitialMap& m) {
  std::vector<lp::HalfSpace> kernel;
  for (const topology::BoundaryFace& f : topology::boundary_faces(m.domain.mesh)) {
    const InnerHalfSpace h = inner_halfspace(m.target[f.face[0]], m.target[f.face[1]], m.target[f.face[2]]);
    kernel.push_back({Rational(h.u[0]), Rational(h.u[1]), Rational(h.u[2]), Rational(h.w)});
  }
  return lp::chebyshev_center(kernel).status == lp::ChebyshevStatus::interior;
}

inline InitialMap identity_map_unchecked(std::uint32_t cells, std::uint64_t seed, double amplitude) {
  InitialMap m{generators::perturbed_grid(cells, cells, cells, seed, amplitude), {}, {}};
  for (const auto& p : m.domain.positions) m.target.emplace_back(p[0], p[1], p[2]);
  m.boundary = topology::boundary_vertex_flags(m.domain.mesh);
  return m;
}

inline InitialMap identity_map(std::uint32_t cells, std::uint64_t seed = 1,
                               double amplitude = generators::default_perturb_amplitude) {
  InitialMap m = identity_map_unchecked(cells, seed, amplitude);
  REQUIRE_MESSAGE(boundary_star_shaped(m), "the jittered grid's boundary is not star-shaped: choose another seed");
  return m;
}

inline Rational coordinate(const InitialMap& m, topology::VertexId v, int axis) {
  return m.domain.positions[v][std::size_t(axis)];
}

// Moves every interior vertex that `pick` accepts by `offset(v)` (exact).
template <class Pick, class Offset>
void move_interior(InitialMap& m, Pick pick, Offset offset) {
  for (topology::VertexId v{0}; v < m.target.size(); ++v) {
    if (m.boundary[v] || !pick(v)) continue;
    const std::array<Rational, 3> d = offset(v);
    m.target[v] = HPoint(m.target[v].coordinate(0) + d[0], m.target[v].coordinate(1) + d[1],
                         m.target[v].coordinate(2) + d[2]);
  }
}

// A random dyadic offset in (-amplitude, amplitude)^3 for each vertex that a coin with
// probability `share` picks.
inline void displace_randomly(InitialMap& m, std::uint64_t seed, double share, double amplitude) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto dyadic = [&] { return rational_from_double(std::ldexp(std::round(std::ldexp((2 * unit(rng) - 1) * amplitude, 10)), -10)); };
  move_interior(
      m, [&](topology::VertexId) { return unit(rng) < share; },
      [&](topology::VertexId) { return std::array<Rational, 3>{dyadic(), dyadic(), dyadic()}; });
}

// Reflects the interior vertices within `radius` (max norm) of `centre` through the plane
// x = centre.x + shift: a fold.
inline void fold(InitialMap& m, const std::array<double, 3>& centre, double radius, double shift) {
  const auto near = [&](topology::VertexId v) {
    for (int k = 0; k < 3; ++k)
      if (std::fabs(to_double(coordinate(m, v, k)) - centre[std::size_t(k)]) > radius) return false;
    return true;
  };
  const Rational plane = rational_from_double(centre[0] + shift);
  move_interior(m, near, [&](topology::VertexId v) {
    return std::array<Rational, 3>{2 * (plane - m.target[v].coordinate(0)), Rational(0), Rational(0)};
  });
}

inline bool defect(const InitialMap& m, topology::TetId t) {
  const topology::Tet& x = m.mesh().tet(t);
  return orient3d(m.target[x[0]], m.target[x[1]], m.target[x[2]], m.target[x[3]],
                  PredicateContext::certain()) != Sign::positive;
}

inline std::size_t count_defects(const InitialMap& m) {
  std::size_t n = 0;
  for (topology::TetId t : m.mesh().live_tets()) n += defect(m, t) ? 1 : 0;
  return n;
}

// check_ball on the star's tets, renumbered here.
inline bool star_is_ball(const topology::TetMesh& mesh, const algorithm::Star& s) {
  std::vector<topology::VertexId> index(mesh.num_vertices(), topology::invalid_vertex);
  std::vector<topology::Tet> tets;
  std::uint32_t next = 0;
  for (topology::TetId t : s.tets) {
    topology::Tet x = mesh.tet(t);
    for (auto& v : x) v = index[v] == topology::invalid_vertex ? (index[v] = topology::VertexId{next++}) : index[v];
    tets.push_back(x);
  }
  return topology::check_ball(topology::TetMesh(next, tets)).ok;
}

// The checks the tests make on every star set, check_stars aside: (d) and the balls, each
// defect with a vertex interior to its star, and interior vertices off the domain boundary.
inline void check_independently(const InitialMap& m, const algorithm::StarSet& set) {
  REQUIRE_MESSAGE(set.ok, set.message);
  CHECK(algorithm::check_stars(m.mesh(), m.target, set) == "");
  std::vector<char> in_star(m.mesh().tet_capacity(), 0);
  for (const algorithm::Star& s : set.stars) {
    CHECK(star_is_ball(m.mesh(), s));
    for (topology::TetId t : s.tets) in_star[t] = 1;
    for (topology::VertexId v : s.interior) CHECK_FALSE(m.boundary[v]);
    for (topology::TetId t : s.tets) {
      if (!defect(m, t)) continue;
      const topology::Tet& x = m.mesh().tet(t);
      const bool freed = std::any_of(x.begin(), x.end(), [&](topology::VertexId v) {
        return std::binary_search(s.interior.begin(), s.interior.end(), v);
      });
      const bool fixed = std::all_of(x.begin(), x.end(), [&](topology::VertexId v) { return m.boundary[v] != 0; });
      CHECK((freed || fixed));
    }
  }
  std::size_t outside_defects = 0;
  for (topology::TetId t : m.mesh().live_tets()) outside_defects += !in_star[t] && defect(m, t) ? 1 : 0;
  CHECK(outside_defects == 0);
}

}  // namespace cmx::test
