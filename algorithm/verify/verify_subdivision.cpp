#include "algorithm/verify/verify_subdivision.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "algorithm/describe.hpp"
#include "arith/rational.hpp"

namespace cmx::algorithm {
namespace {

// Message text from pieces (g++ 12 warns falsely on "literal" + std::string chains).
template <class... Parts>
std::string text(const Parts&... parts) {
  std::string out;
  (out.append(parts), ...);
  return out;
}

using Coordinates = std::vector<std::pair<std::uint32_t, Rational>>;  // sorted by input vertex, no zeros

// The mean of two or three vertices' coordinates.
Coordinates mean(const std::vector<const Coordinates*>& of) {
  std::map<std::uint32_t, Rational> sum;
  for (const Coordinates* c : of)
    for (const auto& [v, x] : *c) sum[v] += x;
  const Rational weight(1, static_cast<long>(of.size()));
  Coordinates out;
  for (auto& [v, x] : sum)
    if (x != 0) out.emplace_back(v, x * weight);
  return out;
}

// Barycentric coordinates of every output vertex, or "" replaced by why they cannot be had.
std::string barycentric(std::size_t input_vertices, const std::vector<std::array<std::uint32_t, 3>>& parents,
                        std::vector<Coordinates>& out) {
  out.assign(parents.size(), {});
  for (std::size_t v = 0; v < parents.size(); ++v) {
    if (v < input_vertices) {
      out[v] = {{static_cast<std::uint32_t>(v), Rational(1)}};
      continue;
    }
    std::vector<const Coordinates*> of;
    for (auto p : parents[v])
      if (p != topology::invalid_index) {
        if (p >= v) return text("vertex ", std::to_string(v), " names a parent that is not older: ", std::to_string(p));
        of.push_back(&out[p]);
      }
    if (of.size() < 2) return text("added vertex ", std::to_string(v), " has no split it came from");
    out[v] = mean(of);
  }
  return {};
}

Rational det4(std::array<std::array<Rational, 4>, 4> m) {
  Rational det(1);
  for (int c = 0; c < 4; ++c) {
    int pivot = c;
    while (pivot < 4 && m[pivot][c] == 0) ++pivot;
    if (pivot == 4) return Rational(0);
    if (pivot != c) std::swap(m[pivot], m[c]), det = -det;
    det *= m[c][c];
    for (int r = c + 1; r < 4; ++r) {
      if (m[r][c] == 0) continue;
      const Rational f = m[r][c] / m[c][c];
      for (int k = c; k < 4; ++k) m[r][k] -= f * m[c][k];
    }
  }
  return det;
}

}  // namespace

std::string verify_subdivision(const std::vector<topology::Tet>& input_tets, std::size_t input_vertices,
                               const std::vector<topology::Tet>& tets,
                               const std::vector<std::array<std::uint32_t, 3>>& parents,
                               const std::vector<std::uint32_t>& origin) {
  std::vector<Coordinates> made;  // by creation number
  if (std::string why = barycentric(input_vertices, parents, made); !why.empty()) return why;
  if (origin.size() < input_vertices) return "fewer vertex origins than input vertices";
  for (std::size_t v = 0; v < input_vertices; ++v)
    if (origin[v] != v) return text("input vertex ", std::to_string(v), " is not its own origin");
  std::vector<const Coordinates*> coords;
  for (auto o : origin) {
    if (o >= made.size()) return text("a vertex origin is out of range: ", std::to_string(o));
    coords.push_back(&made[o]);
  }
  std::map<std::array<std::uint32_t, 4>, std::size_t> by_vertices;
  for (std::size_t k = 0; k < input_tets.size(); ++k) {
    std::array<std::uint32_t, 4> key{};
    for (int i = 0; i < 4; ++i) key[std::size_t(i)] = input_tets[k][std::size_t(i)].idx();
    std::sort(key.begin(), key.end());
    by_vertices.emplace(key, k);
  }
  std::vector<Rational> filled(input_tets.size());
  for (const auto& t : tets) {
    std::vector<std::uint32_t> support;
    for (auto v : t) {
      if (v.idx() >= coords.size()) return text("output tet ", ids_text(t), " names a vertex without a record");
      for (const auto& [u, x] : *coords[v.idx()]) support.push_back(u);
    }
    std::sort(support.begin(), support.end());
    support.erase(std::unique(support.begin(), support.end()), support.end());
    std::array<std::uint32_t, 4> key{};
    if (support.size() == 4) std::copy(support.begin(), support.end(), key.begin());
    const auto in = support.size() == 4 ? by_vertices.find(key) : by_vertices.end();
    if (in == by_vertices.end())
      return text("output tet ", ids_text(t), " lies in no input tet (its vertices span ", std::to_string(support.size()),
                  " input vertices", support.size() == 4 ? " that are not a tet's" : "", ")");
    const topology::Tet& host = input_tets[in->second];
    std::array<std::array<Rational, 4>, 4> m{};
    for (int r = 0; r < 4; ++r)
      for (const auto& [u, x] : *coords[t[std::size_t(r)].idx()])
        for (int c = 0; c < 4; ++c)
          if (host[std::size_t(c)].idx() == u) m[std::size_t(r)][std::size_t(c)] = x;
    const Rational volume = det4(m);
    if (volume <= 0)
      return text("output tet ", ids_text(t), " is ", volume == 0 ? "flat" : "inverted", " inside input tet ",
                  ids_text(host), " (barycentric coordinates)");
    filled[in->second] += volume;
  }
  for (std::size_t k = 0; k < input_tets.size(); ++k)
    if (filled[k] != 1)
      return text("the output tets inside input tet ", ids_text(input_tets[k]), " fill ", filled[k].get_str(),
                  " of it, not exactly all");
  return {};
}

}  // namespace cmx::algorithm
