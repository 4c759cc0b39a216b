#include "support/tetgen_ball.hpp"

#define TETLIBRARY
#include <tetgen.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "kernel/orient.hpp"
#include "topology/ball_check.hpp"

namespace cmx::test {
namespace {

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * double(rng() >> 11) * 0x1p-53;
}

// A point uniform in the ball of the given radius (rejection from the cube).
std::array<double, 3> in_ball(std::mt19937_64& rng, double radius) {
  for (;;) {
    std::array<double, 3> p{uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)};
    const double r2 = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
    if (r2 <= 1) return {p[0] * radius, p[1] * radius, p[2] * radius};
  }
}

// A point uniform on the unit sphere: a cube sample in the shell 0.1 < |p| <= 1, normalised.
std::array<double, 3> on_sphere(std::mt19937_64& rng) {
  for (;;) {
    const auto p = in_ball(rng, 1.0);
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    if (r > 0.1) return {p[0] / r, p[1] / r, p[2] / r};
  }
}

}  // namespace

TetgenBall tetgen_ball(std::size_t interior_points, std::size_t surface_points, std::uint64_t seed, double quality) {
  std::mt19937_64 rng(seed);
  std::vector<std::array<double, 3>> points;
  for (std::size_t i = 0; i < surface_points; ++i) points.push_back(on_sphere(rng));
  for (std::size_t i = 0; i < interior_points; ++i) points.push_back(in_ball(rng, 0.9));

  tetgenio in, delaunay, refined;  // their destructors free the arrays (allocated with new[])
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(points.size());
  in.pointlist = new REAL[3 * points.size()];
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t a = 0; a < 3; ++a) in.pointlist[3 * i + a] = points[i][a];
  std::string flags = "Q";
  std::string refine_flags = "Qrq" + std::to_string(quality);
  try {
    tetrahedralize(flags.data(), &in, &delaunay);
    if (quality > 0) tetrahedralize(refine_flags.data(), &delaunay, &refined);
  } catch (int code) {
    throw std::runtime_error("tetgen_ball: TetGen failed with code " + std::to_string(code));
  }
  const tetgenio& out = quality > 0 ? refined : delaunay;
  if (out.numberofcorners != 4) throw std::runtime_error("tetgen_ball: TetGen returned non-linear tets");

  TetgenBall ball;
  ball.positions.resize(static_cast<std::size_t>(out.numberofpoints));
  for (std::size_t i = 0; i < ball.positions.size(); ++i)
    for (std::size_t a = 0; a < 3; ++a) ball.positions[i][a] = out.pointlist[3 * i + a];
  std::vector<topology::Tet> tets(static_cast<std::size_t>(out.numberoftetrahedra));
  for (std::size_t t = 0; t < tets.size(); ++t) {
    auto& tet = tets[t];
    for (std::size_t k = 0; k < 4; ++k) tet[k] = static_cast<topology::VertexId>(out.tetrahedronlist[4 * t + k]);
    const auto& p = ball.positions;
    const Sign s = orient3d(p[tet[0]].data(), p[tet[1]].data(), p[tet[2]].data(), p[tet[3]].data(),
                            PredicateContext::certain());
    if (s == Sign::zero) throw std::runtime_error("tetgen_ball: TetGen returned a flat tet " + std::to_string(t));
    if (s == Sign::negative) {
      std::swap(tet[2], tet[3]);
      ++ball.reoriented_tets;
    }
  }
  ball.mesh = topology::TetMesh(ball.positions.size(), tets);
  if (const auto verdict = topology::check_ball(ball.mesh); !verdict.ok)
    throw std::runtime_error("tetgen_ball: not a ball: " + verdict.message);
  return ball;
}

}  // namespace cmx::test
