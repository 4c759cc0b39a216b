#pragma once
// What the boundary-shape generator's parts share (generators/boundary_shapes.cpp, the placement;
// generators/boundary_corners.cpp, the corners and the paths between them): the boundary surface
// in local numbering, small vector helpers, message text and seeded draws. Internal to the
// generators layer; not installed.
#include <array>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "topology/tet_mesh.hpp"

namespace cmx::generators::detail {

using Vec3 = std::array<double, 3>;

// ---- small vector helpers -------------------------------------------------------------------

inline Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Vec3 scaled(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline bool finite(const Vec3& a) { return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]); }

// Message text from pieces (strings and integers); avoids "literal" + std::string, on which g++ 12
// emits a false -Wrestrict warning.
inline void append_part(std::string& out, std::string_view part) { out += part; }
template <std::integral T>
void append_part(std::string& out, T number) {
  out += std::to_string(number);
}
template <class Tag>
void append_part(std::string& out, topology::Handle<Tag> handle) {
  out += std::to_string(handle.idx());
}
template <class... Parts>
std::string text(const Parts&... parts) {
  std::string out;
  (append_part(out, parts), ...);
  return out;
}

// ---- seeded choices, identical on every platform -------------------------------------------

// SplitMix64's finaliser: spreads a seed and a counter over all 64 bits.
inline std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// Uniform on [0, n), n >= 1, by rejection (std::uniform_int_distribution is not specified
// bit for bit, this is): accept r >= 2^64 mod n, so that r mod n is unbiased.
inline std::uint64_t draw_below(std::mt19937_64& rng, std::uint64_t n) {
  const std::uint64_t reject_below = (0 - n) % n;
  for (;;) {
    const std::uint64_t r = rng();
    if (r >= reject_below) return r % n;
  }
}

// ---- the boundary surface, in local numbering ----------------------------------------------

struct Surface {
  std::vector<std::uint32_t> vertices;                  // global ids, ascending
  std::vector<std::uint32_t> local;                     // global id -> local id, or invalid_index
  std::vector<topology::Triangle> faces;                // local ids, outward
  std::vector<std::vector<std::uint32_t>> neighbors;    // local adjacency over boundary edges, ascending
};

// Builds the surface; returns "" or why the boundary is not a closed, consistently oriented surface.
std::string build_surface(const topology::TetMesh& mesh, Surface& s);

}  // namespace cmx::generators::detail
