#include "generators/domain_generators.hpp"

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "arith/rounding.hpp"
#include "kernel/homogeneous_point.hpp"
#include "kernel/orient.hpp"
#include "topology/generators.hpp"
#include "topology/nobuenoss.hpp"

namespace cmx::generators {
namespace {

constexpr int jitter_bits = 17;

void check_size(std::uint64_t nx, std::uint64_t ny, std::uint64_t nz, const char* what) {
  if (nx == 0 || ny == 0 || nz == 0) throw std::invalid_argument(std::string(what).append(": every dimension must be at least 1"));
  // Vertex ids and tet ids are 32-bit: keep both well inside.
  const std::uint64_t limit = std::uint64_t{1} << 31;
  const bool too_many = nx >= limit || ny >= limit || nz >= limit || (nx + 1) * (ny + 1) >= limit ||
                        (nx + 1) * (ny + 1) * (nz + 1) >= limit || nx * ny * nz >= limit / 6;
  if (too_many) throw std::invalid_argument(std::string(what).append(": too many cells for 32-bit vertex and tet ids"));
}

void check_amplitude(double amplitude, const char* what) {
  if (!std::isfinite(amplitude) || amplitude < 0)
    throw std::invalid_argument(std::string(what).append(": the perturbation amplitude must be finite and >= 0"));
}

GeneratedDomain from_grid(topology::GridComplex grid, std::int32_t shift) {
  GeneratedDomain d;
  d.mesh = std::move(grid.mesh);
  d.positions.reserve(grid.coords.size());
  for (const auto& c : grid.coords) d.positions.push_back({Rational(c[0] - shift), Rational(c[1] - shift), Rational(c[2] - shift)});
  return d;
}

bool star_positive(const topology::TetMesh& mesh, topology::VertexId v, const std::vector<HPoint>& points) {
  for (auto t : mesh.tets_of(v)) {
    const auto& tet = mesh.tet(t);
    if (orient3d(points[tet[0]], points[tet[1]], points[tet[2]], points[tet[3]],
                 PredicateContext::certain()) != Sign::positive)
      return false;
  }
  return true;
}

// The jitter of the header comment, vertex by vertex in index order.
void perturb(GeneratedDomain& d, std::uint64_t seed, double amplitude) {
  if (amplitude == 0) return;
  Rational step = rational_from_double(amplitude);
  mpq_div_2exp(step.get_mpq_t(), step.get_mpq_t(), jitter_bits);
  const std::int64_t centre = std::int64_t{1} << jitter_bits;
  std::mt19937_64 rng(seed);
  std::vector<HPoint> points;
  points.reserve(d.positions.size());
  for (const auto& p : d.positions) points.emplace_back(p[0], p[1], p[2]);
  for (topology::VertexId v{0}; v < d.positions.size(); ++v) {
    std::array<Rational, 3> moved = d.positions[v];
    for (auto& x : moved) {
      const auto k = static_cast<std::int64_t>(rng() >> (64 - jitter_bits));  // uniform below 2^17
      x += step * Rational(2 * k + 1 - centre);
    }
    const HPoint before = points[v];
    points[v] = HPoint(moved[0], moved[1], moved[2]);
    if (star_positive(d.mesh, v, points)) d.positions[v] = moved;
    else points[v] = before;
  }
}

// A lattice complex at its integer points, jittered.
GeneratedDomain perturbed(topology::GridComplex grid, std::uint64_t seed, double amplitude) {
  GeneratedDomain d = from_grid(std::move(grid), 0);
  perturb(d, seed, amplitude);
  return d;
}

}  // namespace

std::vector<std::array<double, 3>> GeneratedDomain::double_positions() const {
  std::vector<std::array<double, 3>> out;
  out.reserve(positions.size());
  for (const auto& p : positions) out.push_back({to_double(p[0]), to_double(p[1]), to_double(p[2])});
  return out;
}

GeneratedDomain perturbed_grid(std::uint32_t nx, std::uint32_t ny, std::uint32_t nz, std::uint64_t perturb_seed,
                               double amplitude) {
  check_size(nx, ny, nz, "perturbed_grid");
  check_amplitude(amplitude, "perturbed_grid");
  GeneratedDomain d = from_grid(topology::grid_complex(nx, ny, nz), 0);
  perturb(d, perturb_seed, amplitude);
  return d;
}

GeneratedDomain voxel_ball(std::uint32_t radius_cells, std::uint64_t perturb_seed, double amplitude) {
  if (radius_cells == 0) throw std::invalid_argument("voxel_ball: the radius must be at least 1 cell");
  const std::uint64_t n = 2 * std::uint64_t{radius_cells};
  check_size(n, n, n, "voxel_ball");
  check_amplitude(amplitude, "voxel_ball");
  // Cell (i,j,k) has centre (i + 1/2, j + 1/2, k + 1/2); the ball's centre is (R, R, R). Doubled:
  // (2i + 1 - 2R)^2 + ... <= 4 R^2, in integers.
  const auto side = static_cast<std::uint32_t>(n);
  const std::int64_t r2 = 4 * std::int64_t{radius_cells} * radius_cells;
  std::vector<char> keep(std::size_t{side} * side * side, 0);
  for (std::uint32_t k = 0; k < side; ++k)
    for (std::uint32_t j = 0; j < side; ++j)
      for (std::uint32_t i = 0; i < side; ++i) {
        const auto offset = [&](std::uint32_t c) { return 2 * std::int64_t{c} + 1 - std::int64_t(n); };
        const std::int64_t d2 = offset(i) * offset(i) + offset(j) * offset(j) + offset(k) * offset(k);
        keep[i + std::size_t{side} * (j + std::size_t{side} * k)] = d2 <= r2 ? 1 : 0;
      }
  GeneratedDomain d = from_grid(topology::voxel_complex(side, side, side, keep), static_cast<std::int32_t>(radius_cells));
  perturb(d, perturb_seed, amplitude);
  return d;
}

GeneratedDomain thin_slab(std::uint32_t nx, std::uint32_t ny, std::uint64_t perturb_seed, std::uint32_t layers,
                          double amplitude) {
  if (layers != 1 && layers != 2) throw std::invalid_argument("thin_slab: layers must be 1 or 2");
  return perturbed_grid(nx, ny, layers, perturb_seed, amplitude);
}

GeneratedDomain bings_house(std::uint32_t scale, std::uint64_t perturb_seed, double amplitude) {
  if (scale < 4 || scale % 2 != 0 || scale > 64)
    throw std::invalid_argument("bings_house: the scale must be even, at least 4 and at most 64");
  check_amplitude(amplitude, "bings_house");
  return perturbed(topology::bings_house_nobuenoss(scale), perturb_seed, amplitude);
}

GeneratedDomain bings_house_box(std::uint32_t scale, std::uint64_t perturb_seed, double amplitude) {
  if (scale < 2 || scale % 2 != 0 || scale > 64)
    throw std::invalid_argument("bings_house_box: the scale must be even, at least 2 and at most 64");
  check_amplitude(amplitude, "bings_house_box");
  return perturbed(topology::bings_house_in_box(scale), perturb_seed, amplitude);
}

GeneratedDomain compact_bings_house_box(std::uint32_t scale, std::uint64_t perturb_seed, double amplitude) {
  if (scale < 2 || scale % 2 != 0 || scale > 64)
    throw std::invalid_argument("compact_bings_house_box: the scale must be even, at least 2 and at most 64");
  check_amplitude(amplitude, "compact_bings_house_box");
  return perturbed(topology::compact_bings_house_in_box(scale), perturb_seed, amplitude);
}

GeneratedDomain knotted_hole(std::uint64_t perturb_seed, double amplitude, std::uint32_t scale) {
  if (scale < 1 || scale > 5) throw std::invalid_argument("knotted_hole: the scale must be 1 to 5");
  check_amplitude(amplitude, "knotted_hole");
  return perturbed(topology::knotted_hole_ball(scale), perturb_seed, amplitude);
}

namespace {

// The cells of thin_fingers (header comment) in a grid of nx x ny x nz cells.
struct Hand {
  std::uint32_t fingers, width, length;
  std::uint32_t nx() const { return (2 * fingers + 1) * width; }
  std::uint32_t margin() const { return length / 2 + 1; }  // room for the bends in y
  std::uint32_t ny() const { return 4 * width + 2 * margin(); }
  std::uint32_t nz() const { return 4 * width + length; }
  bool in_palm(std::uint32_t j, std::uint32_t k) const {
    return k < 4 * width && j >= margin() && j < margin() + 4 * width;
  }
  bool in_finger(std::uint32_t i, std::uint32_t j, std::uint32_t k) const {
    if (k < 4 * width || (i / width) % 2 == 0) return false;
    const std::uint32_t f = i / width / 2, h = k - 4 * width;
    const std::int64_t bend = std::int64_t{h} * h / (2 * std::int64_t{length});
    const std::int64_t y0 = std::int64_t{margin()} + 3 * width / 2 + (f % 2 == 0 ? bend : -bend);
    return std::int64_t{j} >= y0 && std::int64_t{j} < y0 + width;
  }
};

}  // namespace

GeneratedDomain thin_fingers(std::uint32_t fingers, std::uint32_t width, std::uint32_t length, std::uint64_t perturb_seed,
                             double amplitude) {
  if (fingers < 1 || fingers > 16) throw std::invalid_argument("thin_fingers: 1 to 16 fingers");
  if (width < 2 || width > 8) throw std::invalid_argument("thin_fingers: the width must be 2 to 8 cells");
  if (length < 1 || length > 400) throw std::invalid_argument("thin_fingers: the length must be 1 to 400 cells");
  check_amplitude(amplitude, "thin_fingers");
  const Hand hand{fingers, width, length};
  const std::uint32_t nx = hand.nx(), ny = hand.ny(), nz = hand.nz();
  std::vector<char> keep(std::size_t{nx} * ny * nz, 0);
  for (std::uint32_t k = 0; k < nz; ++k)
    for (std::uint32_t j = 0; j < ny; ++j)
      for (std::uint32_t i = 0; i < nx; ++i)
        keep[i + std::size_t{nx} * (j + std::size_t{ny} * k)] = hand.in_palm(j, k) || hand.in_finger(i, j, k) ? 1 : 0;
  GeneratedDomain d = from_grid(topology::voxel_complex(nx, ny, nz, keep), 0);
  perturb(d, perturb_seed, amplitude);
  return d;
}

}  // namespace cmx::generators
