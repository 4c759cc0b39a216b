#include "topology/disc_shelling.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <set>

namespace cmx::topology {
namespace {

Edge edge_of(VertexId a, VertexId b) { return a < b ? Edge{a, b} : Edge{b, a}; }

std::array<Edge, 3> edges_of(const Triangle& t) {
  return {edge_of(t[0], t[1]), edge_of(t[1], t[2]), edge_of(t[2], t[0])};
}

bool contains(const Triangle& t, VertexId v) { return t[0] == v || t[1] == v || t[2] == v; }

// Triangles per edge over the live triangles.
using EdgeCount = std::map<Edge, int>;

EdgeCount edge_counts(std::span<const Triangle> tris, const std::vector<char>& live) {
  EdgeCount count;
  for (std::size_t i = 0; i < tris.size(); ++i)
    if (live[i])
      for (const Edge& e : edges_of(tris[i])) ++count[e];
  return count;
}

// Vertices on a boundary edge of the live triangles.
std::set<VertexId> boundary_vertices(const EdgeCount& count) {
  std::set<VertexId> out;
  for (const auto& [e, n] : count)
    if (n == 1) out.insert({e[0], e[1]});
  return out;
}

// The step that removes triangle t from the live disc, if t is removable (header comment).
std::optional<DiscShellingStep> removal(const Triangle& t, const EdgeCount& count,
                                        const std::set<VertexId>& boundary) {
  const std::array<Edge, 3> e = edges_of(t);
  int free = 0;
  for (const Edge& x : e) free += count.at(x) == 1;
  DiscShellingStep step;
  step.triangle = t;
  for (int i = 0; i < 3; ++i) {
    const VertexId opposite = t[std::size_t((i + 2) % 3)];  // the vertex not on e[i]
    const bool edge_free = count.at(e[std::size_t(i)]) == 1;
    if (free == 2 && !edge_free) {  // the shared edge: its opposite vertex is the ear
      step.kind = DiscShellingKind::ear;
      step.apex = opposite;
      return step;
    }
    if (free == 1 && edge_free) {
      if (boundary.count(opposite)) return std::nullopt;  // would pinch the disc at `opposite`
      step.kind = DiscShellingKind::free_edge;
      step.apex = opposite;
      step.free_edge = e[std::size_t(i)];
      return step;
    }
  }
  return std::nullopt;
}

std::string input_problem(std::span<const Triangle> disc, VertexId w) {
  std::set<std::array<VertexId, 3>> seen;
  bool has_w = false;
  std::vector<char> all(disc.size(), 1);
  for (const Triangle& t : disc) {
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return "a triangle repeats a vertex";
    std::array<VertexId, 3> key = t;
    std::sort(key.begin(), key.end());
    if (!seen.insert(key).second) return "a triangle is listed twice";
    has_w = has_w || contains(t, w);
  }
  for (const auto& [e, n] : edge_counts(disc, all))
    if (n > 2) return "edge (" + std::to_string(e[0]) + ", " + std::to_string(e[1]) + ") is in " + std::to_string(n) +
                      " triangles";
  if (!has_w) return "the witness " + std::to_string(w) + " is not a vertex of the disc";
  return {};
}

// Whether the graph of `edges` joins every vertex of `vertices`.
bool connected(const std::set<VertexId>& vertices, const EdgeCount& edges) {
  std::map<VertexId, VertexId> parent;
  for (VertexId v : vertices) parent[v] = v;
  const auto find = [&parent](VertexId v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const auto& [e, n] : edges) parent[find(e[0])] = find(e[1]);
  const VertexId root = find(*vertices.begin());
  return std::all_of(vertices.begin(), vertices.end(), [&](VertexId v) { return find(v) == root; });
}

}  // namespace

DiscShelling shell_disc_onto_star(std::span<const Triangle> disc, VertexId w) {
  DiscShelling out;
  out.message = input_problem(disc, w);
  if (!out.message.empty()) {
    out.left.assign(disc.begin(), disc.end());
    return out;
  }
  std::vector<char> live(disc.size(), 1);
  std::size_t outside = 0;  // live triangles without w
  for (const Triangle& t : disc) outside += !contains(t, w);
  while (outside > 0) {
    const EdgeCount count = edge_counts(disc, live);
    const std::set<VertexId> boundary = boundary_vertices(count);
    std::optional<DiscShellingStep> step;
    std::size_t i = 0;
    for (; i < disc.size() && !step; ++i)
      if (live[i] && !contains(disc[i], w)) step = removal(disc[i], count, boundary);
    if (!step) {
      out.message = "no triangle outside the star of " + std::to_string(w) + " is removable (" +
                    std::to_string(outside) + " left outside it)";
      break;
    }
    live[i - 1] = 0;
    --outside;
    out.steps.push_back(*step);
  }
  for (std::size_t i = 0; i < disc.size(); ++i)
    if (live[i]) out.left.push_back(disc[i]);
  out.complete = outside == 0;
  return out;
}

bool is_disc(std::span<const Triangle> triangles) {
  if (triangles.empty()) return false;
  const std::vector<char> all(triangles.size(), 1);
  const EdgeCount count = edge_counts(triangles, all);
  std::set<VertexId> vertices;
  for (const Triangle& t : triangles) vertices.insert(t.begin(), t.end());
  std::map<VertexId, std::vector<VertexId>> boundary_next;  // boundary edges as adjacency
  for (const auto& [e, n] : count) {
    if (n > 2) return false;
    if (n == 1) {
      boundary_next[e[0]].push_back(e[1]);
      boundary_next[e[1]].push_back(e[0]);
    }
  }
  const auto chi = std::int64_t(vertices.size()) - std::int64_t(count.size()) + std::int64_t(triangles.size());
  if (chi != 1 || boundary_next.empty()) return false;
  // One boundary cycle through distinct vertices: every boundary vertex has two boundary edges,
  // and walking from one comes back after visiting all of them.
  for (const auto& [v, next] : boundary_next)
    if (next.size() != 2) return false;
  VertexId prev = boundary_next.begin()->first, at = boundary_next.begin()->second[0];
  std::size_t steps = 1;
  while (at != boundary_next.begin()->first && steps <= boundary_next.size()) {
    const std::vector<VertexId>& n = boundary_next[at];
    const VertexId next = n[0] == prev ? n[1] : n[0];
    prev = at, at = next, ++steps;
  }
  if (steps != boundary_next.size()) return false;
  // Connected, and every vertex's triangles one fan (its link a path or a cycle): with chi = 1 and
  // one boundary cycle that leaves a disc, not a disc and a sphere pinched together.
  if (!connected(vertices, count)) return false;
  std::map<VertexId, EdgeCount> links;
  for (const Triangle& t : triangles)
    for (int i = 0; i < 3; ++i) ++links[t[std::size_t(i)]][edge_of(t[std::size_t((i + 1) % 3)], t[std::size_t((i + 2) % 3)])];
  for (const auto& [v, link] : links) {
    std::set<VertexId> around;
    for (const auto& [e, n] : link) around.insert({e[0], e[1]});
    const std::size_t surplus = around.size() - link.size();  // 1: a path, 0: a cycle
    if (surplus > 1 || !connected(around, link)) return false;
  }
  return true;
}

}  // namespace cmx::topology
