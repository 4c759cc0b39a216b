#include "io/orientation.hpp"

#include <algorithm>
#include <cstdint>

#include "io/io_error.hpp"
#include "kernel/homogeneous_point.hpp"
#include "kernel/orient.hpp"

namespace cmx::io {
namespace {

std::size_t line_of(const std::vector<std::size_t>& tet_lines, std::size_t t) {
  return t < tet_lines.size() ? tet_lines[t] : 0;
}

std::string describe(const Tet& t) {
  return "(" + std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) + ", " +
         std::to_string(t[3]) + ")";
}

std::vector<HPoint> to_hpoints(const TetMeshData& mesh) {
  std::vector<HPoint> points;
  points.reserve(mesh.positions.size());
  for (const auto& p : mesh.positions) points.emplace_back(p[0], p[1], p[2]);
  return points;
}

std::vector<Sign> signs_of(const TetMeshData& mesh) {
  const auto points = to_hpoints(mesh);
  std::vector<Sign> signs;
  signs.reserve(mesh.tets.size());
  for (const auto& t : mesh.tets)
    signs.push_back(
        orient3d(points[t[0]], points[t[1]], points[t[2]], points[t[3]], PredicateContext::certain()));
  return signs;
}

}  // namespace

OrientationCounts count_orientations(const TetMeshData& mesh) {
  OrientationCounts c;
  const auto signs = signs_of(mesh);
  for (std::size_t i = 0; i < signs.size(); ++i) {
    if (signs[i] == Sign::positive) {
      if (!c.positive++) c.first_positive = i;
    } else if (signs[i] == Sign::negative) {
      if (!c.negative++) c.first_negative = i;
    } else if (!c.zero++) {
      c.first_zero = i;
    }
  }
  return c;
}

void validate_and_orient(TetMeshData& mesh, const ReadOptions& options, const std::string& file,
                         const std::vector<std::size_t>& tet_lines) {
  const std::size_t n = mesh.positions.size();
  // Combinatorial checks first: they need no arithmetic and make the geometric messages precise.
  std::vector<std::pair<Tet, std::uint32_t>> keys;
  keys.reserve(mesh.tets.size());
  for (std::size_t i = 0; i < mesh.tets.size(); ++i) {
    Tet k = mesh.tets[i];
    for (auto v : k)
      if (v >= n)  // readers check this already; kept so the function is safe on its own
        throw IoError(ErrorKind::index_out_of_range, file, line_of(tet_lines, i),
                      "tet " + std::to_string(i) + " has vertex index " + std::to_string(v) + " >= " +
                          std::to_string(n) + " vertices");
    std::sort(k.begin(), k.end());
    if (k[0] == k[1] || k[1] == k[2] || k[2] == k[3])
      throw IoError(ErrorKind::degenerate_tet, file, line_of(tet_lines, i),
                    "tet " + std::to_string(i) + " " + describe(mesh.tets[i]) + " repeats a vertex");
    keys.emplace_back(k, std::uint32_t(i));
  }
  std::sort(keys.begin(), keys.end());
  for (std::size_t i = 1; i < keys.size(); ++i)
    if (keys[i].first == keys[i - 1].first) {
      const auto first = keys[i - 1].second, second = keys[i].second;
      throw IoError(ErrorKind::duplicate, file, line_of(tet_lines, second),
                    "tet " + std::to_string(second) + " " + describe(mesh.tets[second]) +
                        " has the same vertices as tet " + std::to_string(first) +
                        (line_of(tet_lines, first) ? " (line " + std::to_string(line_of(tet_lines, first)) + ")" : ""));
    }
  keys = {};
  if (options.orientation == Orientation::keep) return;

  const auto signs = signs_of(mesh);
  std::size_t pos = 0, neg = 0;
  for (std::size_t i = 0; i < signs.size(); ++i) {
    if (signs[i] == Sign::zero) {
      if (!options.allow_degenerate)
        throw IoError(ErrorKind::degenerate_tet, file, line_of(tet_lines, i),
                      "tet " + std::to_string(i) + " " + describe(mesh.tets[i]) + " has zero volume");
      continue;
    }
    (signs[i] == Sign::positive ? pos : neg)++;
  }
  if (pos && neg) {
    // Name the first tet of the minority sign: with a few inverted tets that is the culprit.
    const Sign minority = neg <= pos ? Sign::negative : Sign::positive;
    const auto it = std::find(signs.begin(), signs.end(), minority);
    const std::size_t i = std::size_t(it - signs.begin());
    throw IoError(ErrorKind::inconsistent_orientation, file, line_of(tet_lines, i),
                  "inconsistent orientation: tet " + std::to_string(i) + " " + describe(mesh.tets[i]) + " is " +
                      (minority == Sign::negative ? "negatively" : "positively") + " oriented, but " +
                      std::to_string(minority == Sign::negative ? pos : neg) + " of " +
                      std::to_string(pos + neg) + " tets are " +
                      (minority == Sign::negative ? "positively" : "negatively") + " oriented");
  }
  if (neg) {
    for (auto& t : mesh.tets) std::swap(t[2], t[3]);
    mesh.orientation_flipped = true;
  }
}

}  // namespace cmx::io
