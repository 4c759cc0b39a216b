#include "topology/nobuenoss.hpp"

#include <algorithm>
#include <bit>
#include <map>
#include <set>
#include <stdexcept>
#include <vector>

#include "topology/coherent_orientation.hpp"

namespace cmx::topology {
namespace {

// Turning points of a trefoil-knotted lattice arc, from sampling the trefoil
// (sin t + 2 sin 2t, cos t - 2 cos 2t, -sin 3t) for t in [pi/2 + 0.25, 5pi/2 - 0.25] at scale
// (3, 3, 9), rounding to the lattice and joining samples by axis steps. Stored as a table so
// that the mesh does not depend on libm.
constexpr std::array<std::int32_t, 3> trefoil_arc[] = {
    {0,5,7}, {0,4,7}, {0,4,6}, {-1,4,6}, {-1,4,4}, {-1,3,4}, {-1,3,3}, {-2,3,3}, {-2,3,2},
    {-2,2,2}, {-2,2,0}, {-3,2,0}, {-3,1,0}, {-3,1,-2}, {-3,0,-2}, {-3,0,-4}, {-3,-1,-4},
    {-4,-1,-4}, {-4,-1,-5}, {-4,-2,-5}, {-4,-2,-7}, {-4,-3,-7}, {-4,-3,-8}, {-4,-4,-8}, {-4,-4,-9},
    {-4,-6,-9}, {-3,-6,-9}, {-3,-7,-9}, {-3,-7,-8}, {-3,-8,-8}, {-3,-8,-7}, {-2,-8,-7}, {-2,-8,-5},
    {-2,-9,-5}, {-2,-9,-4}, {-1,-9,-4}, {-1,-9,-1}, {0,-9,-1}, {0,-9,1}, {1,-9,1}, {1,-9,4},
    {2,-9,4}, {2,-9,5}, {2,-8,5}, {2,-8,7}, {3,-8,7}, {3,-8,8}, {3,-7,8}, {3,-7,9}, {3,-6,9},
    {4,-6,9}, {4,-4,9}, {4,-4,8}, {4,-3,8}, {4,-3,7}, {4,-2,7}, {4,-2,5}, {4,-1,5}, {4,-1,4},
    {3,-1,4}, {3,0,4}, {3,0,2}, {3,1,2}, {3,1,0}, {3,2,0}, {2,2,0}, {2,2,-2}, {2,3,-2}, {2,3,-3},
    {1,3,-3}, {1,3,-4}, {1,4,-4}, {1,4,-6}, {0,4,-6}, {0,4,-7}, {0,5,-7}, {-1,5,-7}, {-1,5,-8},
    {-2,5,-8}, {-2,6,-8}, {-2,6,-9}, {-4,6,-9}, {-4,6,-8}, {-5,6,-8}, {-5,6,-7}, {-6,6,-7},
    {-6,6,-5}, {-7,6,-5}, {-7,6,-4}, {-7,5,-4}, {-7,5,-2}, {-8,5,-2}, {-8,5,0}, {-8,4,0}, {-8,4,3},
    {-8,3,3}, {-8,3,6}, {-8,2,6}, {-8,2,7}, {-8,1,7}, {-8,1,9}, {-7,1,9}, {-7,-1,9}, {-6,-1,9},
    {-6,-1,8}, {-5,-1,8}, {-5,-2,8}, {-5,-2,7}, {-4,-2,7}, {-4,-2,6}, {-3,-2,6}, {-3,-3,6},
    {-3,-3,4}, {-2,-3,4}, {-2,-3,3}, {-1,-3,3}, {-1,-3,1}, {0,-3,1}, {0,-3,-1}, {1,-3,-1},
    {1,-3,-3}, {2,-3,-3}, {2,-3,-4}, {3,-3,-4}, {3,-3,-5}, {3,-2,-5}, {3,-2,-6}, {4,-2,-6},
    {4,-2,-7}, {5,-2,-7}, {5,-2,-8}, {5,-1,-8}, {6,-1,-8}, {6,-1,-9}, {7,-1,-9}, {7,1,-9},
    {8,1,-9}, {8,1,-7}, {8,2,-7}, {8,2,-6}, {8,3,-6}, {8,3,-3}, {8,4,-3}, {8,4,0}, {8,5,0},
    {8,5,2}, {7,5,2}, {7,5,4}, {7,6,4}, {7,6,5}, {6,6,5}, {6,6,7}};

// The same sampling of the unknotted curve (2.5 cos t, 2.5 sin t, 0.3 sin t).
constexpr std::array<std::int32_t, 3> circle_arc[] = {
    {-2,7,3}, {-3,7,3}, {-3,7,2}, {-4,7,2}, {-4,6,2}, {-5,6,2}, {-5,5,2}, {-6,5,2}, {-6,4,2},
    {-6,4,1}, {-7,4,1}, {-7,1,1}, {-7,1,0}, {-7,-1,0}, {-7,-1,-1}, {-7,-4,-1}, {-6,-4,-1},
    {-6,-4,-2}, {-6,-5,-2}, {-5,-5,-2}, {-5,-6,-2}, {-4,-6,-2}, {-4,-7,-2}, {-3,-7,-2}, {-3,-7,-3},
    {3,-7,-3}, {3,-7,-2}, {4,-7,-2}, {4,-6,-2}, {5,-6,-2}, {5,-5,-2}, {6,-5,-2}, {6,-4,-2},
    {6,-4,-1}, {7,-4,-1}, {7,-1,-1}, {7,-1,0}, {7,1,0}, {7,1,1}, {7,4,1}, {6,4,1}, {6,4,2},
    {6,5,2}, {5,5,2}, {5,6,2}, {4,6,2}, {4,7,2}, {3,7,2}, {3,7,3}, {2,7,3}};

}  // namespace

GridComplex ball_with_hole(std::span<const std::array<std::int32_t, 3>> corners, std::int32_t margin,
                           std::uint32_t scale) {
  if (corners.empty()) return grid_complex(1, 1, 1);
  // The tunnel as a list of lattice cells.
  std::vector<std::array<std::int32_t, 3>> cells{corners[0]};
  for (std::size_t i = 1; i < corners.size(); ++i) {
    std::array<std::int32_t, 3> q = cells.back();
    for (int a = 0; a < 3; ++a)
      while (q[a] != corners[i][a]) {
        q[a] += corners[i][a] > q[a] ? 1 : -1;
        cells.push_back(q);
      }
  }
  std::array<std::int32_t, 3> lo = cells[0], hi = cells[0];
  for (const auto& c : cells)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], c[a]);
      hi[a] = std::max(hi[a], c[a]);
    }
  const std::int32_t top = hi[2] + margin + 1;
  for (std::int32_t z = corners[0][2] + 1; z <= top; ++z) cells.push_back({corners[0][0], corners[0][1], z});
  const std::array<std::int32_t, 3> origin{lo[0] - margin, lo[1] - margin, lo[2] - margin};
  const auto nx = static_cast<std::uint32_t>(hi[0] + margin - origin[0] + 1);
  const auto ny = static_cast<std::uint32_t>(hi[1] + margin - origin[1] + 1);
  const auto nz = static_cast<std::uint32_t>(top - origin[2] + 1);
  std::vector<char> keep(std::size_t{nx} * ny * nz, 1);
  for (const auto& c : cells) {
    const auto i = static_cast<std::size_t>(c[0] - origin[0]), j = static_cast<std::size_t>(c[1] - origin[1]),
               k = static_cast<std::size_t>(c[2] - origin[2]);
    keep[i + nx * (j + ny * k)] = 0;
  }
  if (scale <= 1) return voxel_complex(nx, ny, nz, keep);
  // A finer mesh of the same solid: fine cell (i, j, k) is kept when the cell containing it is.
  const std::uint32_t fx = nx * scale, fy = ny * scale, fz = nz * scale;
  std::vector<char> fine(std::size_t{fx} * fy * fz);
  for (std::uint32_t k = 0; k < fz; ++k)
    for (std::uint32_t j = 0; j < fy; ++j)
      for (std::uint32_t i = 0; i < fx; ++i)
        fine[i + std::size_t{fx} * (j + std::size_t{fy} * k)] =
            keep[i / scale + std::size_t{nx} * (j / scale + std::size_t{ny} * (k / scale))];
  return voxel_complex(fx, fy, fz, fine);
}

GridComplex knotted_hole_ball(std::uint32_t scale) { return ball_with_hole(trefoil_arc, 2, scale); }

GridComplex unknotted_hole_ball(std::uint32_t scale) { return ball_with_hole(circle_arc, 2, scale); }

namespace {

// Axis-aligned rectangle in design units: the coordinate `axis` is fixed to `at`, the other two
// range over [lo, hi] (in increasing axis order), minus optional rectangular holes.
struct Sheet {
  int axis;
  int at;
  std::array<int, 2> lo, hi;
  std::vector<std::array<int, 4>> holes;  // open holes (lo0, lo1, hi0, hi1)
};

bool on_sheet(const Sheet& s, const std::array<std::int64_t, 3>& p, std::int64_t unit) {
  if (p[s.axis] != s.at * unit) return false;
  const int a0 = s.axis == 0 ? 1 : 0, a1 = s.axis == 2 ? 1 : 2;
  const std::int64_t u = p[a0], w = p[a1];
  if (u < s.lo[0] * unit || u > s.hi[0] * unit || w < s.lo[1] * unit || w > s.hi[1] * unit) return false;
  for (const auto& h : s.holes)
    if (u > h[0] * unit && u < h[2] * unit && w > h[1] * unit && w < h[3] * unit) return false;
  return true;
}

// The sheets of Bing's house with two rooms, in design units: box [0,10]x[0,4]x[0,8], floor z=4.
// Tube T1 (x in [2,4], y in [1,3]) leads from below through the lower room into the upper room;
// tube T2 (x in [6,8], y in [1,3]) leads from above through the upper room into the lower room.
// Wall W1 (y=2, x in [0,2], z in [0,4]) ties T1 to the outer wall x=0; wall W2 (y=2, x in
// [8,10], z in [4,8]) ties T2 to the outer wall x=10.
std::vector<Sheet> bings_house_sheets() {
  std::vector<Sheet> sheets;
  sheets.push_back({2, 0, {0, 0}, {10, 4}, {{2, 1, 4, 3}}});           // bottom, hole under T1
  sheets.push_back({2, 8, {0, 0}, {10, 4}, {{6, 1, 8, 3}}});           // top, hole over T2
  sheets.push_back({2, 4, {0, 0}, {10, 4}, {{2, 1, 4, 3}, {6, 1, 8, 3}}});  // floor
  sheets.push_back({0, 0, {0, 0}, {4, 8}, {}});                        // x = 0
  sheets.push_back({0, 10, {0, 0}, {4, 8}, {}});                       // x = 10
  sheets.push_back({1, 0, {0, 0}, {10, 8}, {}});                       // y = 0
  sheets.push_back({1, 4, {0, 0}, {10, 8}, {}});                       // y = 4
  // Tube T1 walls, z in [0,4].
  sheets.push_back({0, 2, {1, 0}, {3, 4}, {}});
  sheets.push_back({0, 4, {1, 0}, {3, 4}, {}});
  sheets.push_back({1, 1, {2, 0}, {4, 4}, {}});
  sheets.push_back({1, 3, {2, 0}, {4, 4}, {}});
  // Tube T2 walls, z in [4,8].
  sheets.push_back({0, 6, {1, 4}, {3, 8}, {}});
  sheets.push_back({0, 8, {1, 4}, {3, 8}, {}});
  sheets.push_back({1, 1, {6, 4}, {8, 8}, {}});
  sheets.push_back({1, 3, {6, 4}, {8, 8}, {}});
  // Supporting walls.
  sheets.push_back({1, 2, {0, 0}, {2, 4}, {}});
  sheets.push_back({1, 2, {8, 4}, {10, 8}, {}});
  return sheets;
}

// The same two rooms in a compact box, [0,5]x[0,3]x[0,2] with the floor at z=1: tube
// T1 (x in [1,2], y in [1,2]) from below, T2 (x in [3,4], y in [1,2]) from above, the walls in
// the tubes' side planes (W1: y=1, x in [0,1], lower room; W2: y=2, x in [4,5], upper room). A
// room is one design unit high, so at 2 cells per unit one layer of grid points lies inside it.
std::vector<Sheet> compact_house_sheets() {
  std::vector<Sheet> sheets;
  sheets.push_back({2, 0, {0, 0}, {5, 3}, {{1, 1, 2, 2}}});                // bottom, hole under T1
  sheets.push_back({2, 2, {0, 0}, {5, 3}, {{3, 1, 4, 2}}});                // top, hole over T2
  sheets.push_back({2, 1, {0, 0}, {5, 3}, {{1, 1, 2, 2}, {3, 1, 4, 2}}});  // floor
  sheets.push_back({0, 0, {0, 0}, {3, 2}, {}});                            // x = 0
  sheets.push_back({0, 5, {0, 0}, {3, 2}, {}});                            // x = 5
  sheets.push_back({1, 0, {0, 0}, {5, 2}, {}});                            // y = 0
  sheets.push_back({1, 3, {0, 0}, {5, 2}, {}});                            // y = 3
  // Tube T1 walls, z in [0,1].
  sheets.push_back({0, 1, {1, 0}, {2, 1}, {}});
  sheets.push_back({0, 2, {1, 0}, {2, 1}, {}});
  sheets.push_back({1, 1, {1, 0}, {2, 1}, {}});
  sheets.push_back({1, 2, {1, 0}, {2, 1}, {}});
  // Tube T2 walls, z in [1,2].
  sheets.push_back({0, 3, {1, 1}, {2, 2}, {}});
  sheets.push_back({0, 4, {1, 1}, {2, 2}, {}});
  sheets.push_back({1, 1, {3, 1}, {4, 2}, {}});
  sheets.push_back({1, 2, {3, 1}, {4, 2}, {}});
  // Supporting walls.
  sheets.push_back({1, 1, {0, 0}, {1, 1}, {}});
  sheets.push_back({1, 2, {4, 1}, {5, 2}, {}});
  return sheets;
}

struct HouseDesign {
  std::vector<Sheet> sheets;
  std::int64_t x, y, z;  // the box, in design units
};

HouseDesign two_room_house() {
  return {bings_house_sheets(), 10, 4, 8};
}
HouseDesign compact_house() {
  return {compact_house_sheets(), 5, 3, 2};
}

// The house at `unit` grid cells per design unit, offset by `off` cells on each side.
struct HouseGrid {
  std::vector<Sheet> sheets;
  std::int64_t unit, off;
  std::uint32_t nx, ny, nz;  // cells
  HouseGrid(const HouseDesign& d, std::int64_t u, std::int64_t o)
      : sheets(d.sheets),
        unit(u),
        off(o),
        nx(static_cast<std::uint32_t>(d.x * u + 2 * o)),
        ny(static_cast<std::uint32_t>(d.y * u + 2 * o)),
        nz(static_cast<std::uint32_t>(d.z * u + 2 * o)) {}
  bool on_house(std::int64_t i, std::int64_t j, std::int64_t k) const {
    const std::array<std::int64_t, 3> p{i - off, j - off, k - off};
    for (const Sheet& s : sheets)
      if (on_sheet(s, p, unit)) return true;
    return false;
  }
};

}  // namespace

GridComplex bings_house_nobuenoss(std::uint32_t scale) {
  // One cell of margin on each side; the offset is 2 so that design points stay at even grid
  // coordinates (the reflected triangulation then puts a face diagonal through every crease).
  const HouseGrid h(two_room_house(), std::max<std::uint32_t>(scale, 4) & ~1u, 2);
  // Keep exactly the cells with a corner on the house: the house points are then the interior
  // vertices (features are >= 4 cells apart, so no other point has all 8 cells kept).
  std::vector<char> keep(std::size_t{h.nx} * h.ny * h.nz, 0);
  for (std::uint32_t k = 0; k < h.nz; ++k)
    for (std::uint32_t j = 0; j < h.ny; ++j)
      for (std::uint32_t i = 0; i < h.nx; ++i) {
        bool touch = false;
        for (int c = 0; c < 8 && !touch; ++c) touch = h.on_house(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
        if (touch) keep[i + std::size_t{h.nx} * (j + std::size_t{h.ny} * k)] = 1;
      }
  return voxel_complex(h.nx, h.ny, h.nz, keep, GridTriangulation::reflected);
}

namespace {

GridComplex house_in_box(const HouseGrid& h, std::size_t* house_vertices) {
  GridComplex box = voxel_complex(h.nx, h.ny, h.nz, {}, GridTriangulation::reflected);
  // Renumber: the vertices off the house first, the house's last, each in grid order.
  const std::size_t n = box.coords.size();
  std::vector<char> house(n, 0);
  std::size_t count = 0;
  for (std::size_t v = 0; v < n; ++v) {
    const auto& c = box.coords[v];
    house[v] = h.on_house(c[0], c[1], c[2]) ? 1 : 0;
    count += static_cast<std::size_t>(house[v]);
  }
  std::vector<VertexId> to(n);
  std::uint32_t off_house = 0, on_house = static_cast<std::uint32_t>(n - count);
  for (std::size_t v = 0; v < n; ++v) to[v] = VertexId{house[v] ? on_house++ : off_house++};
  GridComplex out;
  out.coords.resize(n);
  for (std::size_t v = 0; v < n; ++v) out.coords[to[v]] = box.coords[v];
  std::vector<Tet> tets;
  tets.reserve(box.mesh.num_tets());
  for (TetId t{0}; t < box.mesh.tet_capacity(); ++t) {
    if (!box.mesh.is_alive(t)) continue;
    const Tet x = box.mesh.tet(t);
    tets.push_back({to[x[0]], to[x[1]], to[x[2]], to[x[3]]});
  }
  out.mesh = TetMesh(n, tets);
  if (house_vertices) *house_vertices = count;
  return out;
}

}  // namespace

GridComplex bings_house_in_box(std::uint32_t scale, std::size_t* house_vertices) {
  return house_in_box(HouseGrid(two_room_house(), std::max<std::uint32_t>(scale, 2) & ~1u, 2),
                      house_vertices);
}

GridComplex compact_bings_house_in_box(std::uint32_t scale, std::size_t* house_vertices) {
  return house_in_box(HouseGrid(compact_house(), std::max<std::uint32_t>(scale, 2) & ~1u, 2), house_vertices);
}

namespace {

// Hachimori's 8-vertex dunce hat, vertices 1 to 8 (the numbering of its published facet list).
constexpr std::array<std::array<std::uint32_t, 3>, 17> dunce_hat_triangles{{{1, 3, 5},
                                                                            {2, 3, 5},
                                                                            {2, 4, 5},
                                                                            {1, 2, 4},
                                                                            {1, 3, 4},
                                                                            {3, 4, 8},
                                                                            {1, 2, 8},
                                                                            {1, 7, 8},
                                                                            {1, 2, 7},
                                                                            {2, 3, 7},
                                                                            {3, 6, 7},
                                                                            {1, 3, 6},
                                                                            {1, 5, 6},
                                                                            {4, 5, 6},
                                                                            {4, 6, 8},
                                                                            {6, 7, 8},
                                                                            {2, 3, 8}}};

// The dunce hat's vertex at each position 1..8 along the moment curve of C(8,4).
constexpr std::array<std::uint32_t, 9> on_moment_curve{0, 2, 5, 1, 4, 6, 3, 8, 7};

using Simplex = std::vector<std::uint32_t>;  // sorted vertex ids

Simplex sorted_simplex(Simplex s) {
  std::sort(s.begin(), s.end());
  return s;
}

bool contains(const Simplex& big, const Simplex& small) {
  return std::includes(big.begin(), big.end(), small.begin(), small.end());
}

// Facets of the boundary of C(8,4): the 4-sets S of {1..8} such that any two positions not in S
// have an even number of members of S between them (Gale's evenness condition).
std::vector<Simplex> cyclic_polytope_boundary() {
  std::vector<Simplex> facets;
  for (std::uint32_t mask = 0; mask < 256; ++mask) {
    if (std::popcount(mask) != 4) continue;
    bool even = true;
    for (std::uint32_t a = 0; a < 8 && even; ++a)
      for (std::uint32_t b = a + 1; b < 8 && even; ++b) {
        if ((mask >> a & 1) || (mask >> b & 1)) continue;
        const std::uint32_t between = mask & ((1u << b) - (1u << (a + 1)));
        even = std::popcount(between) % 2 == 0;
      }
    if (!even) continue;
    Simplex f;
    for (std::uint32_t i = 0; i < 8; ++i)
      if (mask >> i & 1) f.push_back(on_moment_curve[i + 1]);
    facets.push_back(sorted_simplex(f));
  }
  return facets;
}

// The bistellar 3-2 move on edge (d, e) whose three tets close around the triangle `link`.
void move_3_2(std::vector<Simplex>& facets, std::uint32_t d, std::uint32_t e, const Simplex& link) {
  std::erase_if(facets, [&](const Simplex& f) { return contains(f, sorted_simplex({d, e})); });
  facets.push_back(sorted_simplex({link[0], link[1], link[2], d}));
  facets.push_back(sorted_simplex({link[0], link[1], link[2], e}));
}

// Stellar subdivision of the simplex `s` at a new vertex `w`: every tet containing s becomes
// the tets that replace one vertex of s by w.
void stellar_subdivide(std::vector<Simplex>& tets, const Simplex& s, std::uint32_t w) {
  std::vector<Simplex> out;
  for (const Simplex& t : tets) {
    if (!contains(t, s)) {
      out.push_back(t);
      continue;
    }
    for (std::uint32_t x : s) {
      Simplex u;
      for (std::uint32_t y : t)
        if (y != x) u.push_back(y);
      u.push_back(w);
      out.push_back(sorted_simplex(u));
    }
  }
  tets = std::move(out);
}

// The faces of `s` with k vertices (sorted, as s is).
std::vector<Simplex> faces_of(const Simplex& s, int k) {
  std::vector<Simplex> out;
  for (std::uint32_t mask = 0; mask < (1u << s.size()); ++mask) {
    if (std::popcount(mask) != k) continue;
    Simplex f;
    for (std::size_t i = 0; i < s.size(); ++i)
      if (mask >> i & 1) f.push_back(s[i]);
    out.push_back(std::move(f));
  }
  return out;
}

// The k-faces of `tets` with every vertex in 1..8 that are not faces of the dunce hat, in order.
std::vector<Simplex> foreign_faces(const std::vector<Simplex>& tets, int k) {
  std::set<Simplex> hat;
  for (const auto& t : dunce_hat_triangles)
    for (Simplex& f : faces_of({t.begin(), t.end()}, k)) hat.insert(std::move(f));
  std::set<Simplex> out;
  for (const Simplex& t : tets)
    for (Simplex& f : faces_of(t, k))
      if (f.back() <= 8 && !hat.count(f)) out.insert(std::move(f));
  return {out.begin(), out.end()};
}

// The prisms between each boundary triangle and its copy, each cut into three tets by the
// vertex order (so that neighbouring prisms agree on their common square).
void add_collar(std::vector<Simplex>& tets, std::uint32_t& next) {
  std::map<Simplex, int> faces;
  for (const Simplex& t : tets)
    for (const Simplex& f : faces_of(t, 3)) ++faces[f];
  std::map<std::uint32_t, std::uint32_t> copy;
  for (const auto& [f, n] : faces)
    if (n == 1)
      for (std::uint32_t v : f) copy.emplace(v, 0);
  for (auto& [v, c] : copy) c = next++;
  for (const auto& [f, n] : faces) {
    if (n != 1) continue;
    const std::uint32_t a = f[0], b = f[1], c = f[2];
    tets.push_back(sorted_simplex({a, b, c, copy[c]}));
    tets.push_back(sorted_simplex({a, b, copy[b], copy[c]}));
    tets.push_back(sorted_simplex({a, copy[a], copy[b], copy[c]}));
  }
}

}  // namespace

TetMesh dunce_hat_ball(std::size_t* hat_vertices, std::uint32_t collars) {
  if (collars < 1 || collars > 64) throw std::invalid_argument("dunce_hat_ball: collars must be 1 to 64");
  std::vector<Simplex> tets = cyclic_polytope_boundary();
  // Edge (2, 8) of the cyclic polytope (positions), whose link is positions 1, 3, 7.
  move_3_2(tets, on_moment_curve[2], on_moment_curve[8],
           sorted_simplex({on_moment_curve[1], on_moment_curve[3], on_moment_curve[7]}));
  // A 3-sphere minus a tet is a ball.
  std::erase(tets, Simplex{1, 2, 4, 5});
  std::sort(tets.begin(), tets.end());
  std::uint32_t next = 9;
  for (int k : {2, 3})
    for (auto f = foreign_faces(tets, k); !f.empty(); f = foreign_faces(tets, k))
      stellar_subdivide(tets, f.front(), next++);
  for (std::uint32_t c = 0; c < collars; ++c) add_collar(tets, next);
  // Ids: 9.. (subdivision vertices, then collar copies) to 0.., the dunce hat's 1..8 last.
  const std::uint32_t others = next - 9;
  const auto id = [&](std::uint32_t v) { return VertexId{v > 8 ? v - 9 : others + v - 1}; };
  std::vector<Tet> out;
  for (const Simplex& t : tets) out.push_back({id(t[0]), id(t[1]), id(t[2]), id(t[3])});
  if (hat_vertices) *hat_vertices = 8;
  TetMesh mesh(others + 8, out);
  if (const CoherentOrientation o = orient_coherently(mesh); !o.ok)
    throw std::logic_error("dunce_hat_ball: not orientable: " + o.message);
  return mesh;
}

}  // namespace cmx::topology
