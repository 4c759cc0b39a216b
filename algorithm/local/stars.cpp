#include "algorithm/local/stars.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "algorithm/local/stars_rule.hpp"
#include "algorithm/local/stars_topology.hpp"
#include "kernel/orient.hpp"

namespace cmx::algorithm {

namespace {

using topology::TetId;
using topology::VertexId;

void classify(const topology::TetMesh& mesh, const std::vector<HPoint>& target, StarSet& out) {
  out.states.assign(mesh.tet_capacity(), TetState::positive);
  for (TetId t : mesh.live_tets()) {
    const topology::Tet& x = mesh.tet(t);
    // Exact whatever --filter says: the stars of the local initial map are classified, not counted.
    const Sign s =
        orient3d(target[x[0]], target[x[1]], target[x[2]], target[x[3]], PredicateContext::certain());
    if (s == Sign::negative) {
      out.states[t] = TetState::inverted;
      ++out.inverted;
    } else if (s == Sign::zero) {
      out.states[t] = TetState::flat;
      ++out.flat;
    }
  }
}

std::vector<VertexId> interior_vertices(const topology::TetMesh& mesh, const stars::StarGrowth& g, std::int32_t id,
                                        const Star& s, const std::vector<char>& boundary_vertex) {
  std::vector<VertexId> on_boundary, interior;
  for (const topology::Triangle& f : s.boundary) on_boundary.insert(on_boundary.end(), f.begin(), f.end());
  std::sort(on_boundary.begin(), on_boundary.end());
  for (VertexId v : s.vertices) {
    const auto around = mesh.tets_of(v);
    const bool all_in = std::all_of(around.begin(), around.end(), [&](TetId t) { return g.owner(t) == id; });
    if (all_in && !boundary_vertex[v] && !std::binary_search(on_boundary.begin(), on_boundary.end(), v))
      interior.push_back(v);
  }
  return interior;
}

Star make_star(const topology::TetMesh& mesh, const stars::StarGrowth& g, std::vector<TetId> tets,
               const std::vector<char>& boundary_vertex, const std::vector<TetState>& states) {
  Star s;
  std::sort(tets.begin(), tets.end());
  const std::int32_t id = g.owner(tets.front());
  for (TetId t : tets) {
    const topology::Tet& x = mesh.tet(t);
    s.vertices.insert(s.vertices.end(), x.begin(), x.end());
    s.defects += states[t] != TetState::positive ? 1 : 0;
    for (int i = 0; i < 4; ++i) {
      const TetId nb = g.adjacency().neighbor[t][std::size_t(i)];
      if (nb == topology::invalid_index || g.owner(nb) != id) s.boundary.push_back(topology::tet_face(x, i));
    }
  }
  std::sort(s.vertices.begin(), s.vertices.end());
  s.vertices.erase(std::unique(s.vertices.begin(), s.vertices.end()), s.vertices.end());
  std::sort(s.boundary.begin(), s.boundary.end());
  s.interior = interior_vertices(mesh, g, id, s, boundary_vertex);
  s.tets = std::move(tets);
  return s;
}

void check_sizes(const topology::TetMesh& mesh, const std::vector<HPoint>& target, const std::vector<char>& boundary_vertex) {
  if (target.size() != mesh.num_vertices())
    throw std::invalid_argument("grow_stars: " + std::to_string(target.size()) + " target positions for " +
                                std::to_string(mesh.num_vertices()) + " vertices");
  if (boundary_vertex.size() != mesh.num_vertices())
    throw std::invalid_argument("grow_stars: " + std::to_string(boundary_vertex.size()) + " boundary flags for " +
                                std::to_string(mesh.num_vertices()) + " vertices");
}

// Counts for a growth cut short: how far the stars got.
void record_failure(const stars::StarGrowth& g, StarSet& out) {
  out.tets_in_stars = g.held();
  std::size_t defects_held = 0;
  for (std::size_t t = 0; t < out.states.size(); ++t)
    defects_held += g.owned(TetId(t)) && out.states[t] != TetState::positive ? 1 : 0;
  out.growth_steps = out.tets_in_stars - defects_held;
}

}  // namespace

StarSet grow_stars(const topology::TetMesh& mesh, const std::vector<HPoint>& target,
                   const std::vector<char>& boundary_vertex, const StarOptions& options) {
  check_sizes(mesh, target, boundary_vertex);
  StarSet out;
  classify(mesh, target, out);
  if (out.inverted + out.flat == 0) {
    out.ok = true;
    return out;
  }
  if (double(out.inverted + out.flat) > options.max_defect_share * double(mesh.num_tets())) {
    out.message = std::to_string(out.inverted + out.flat) + " of " + std::to_string(mesh.num_tets()) +
                  " tets of the initial map are inverted or flat, more than " +
                  std::to_string(int(100 * options.max_defect_share + 0.5)) + " %";
    return out;
  }
  stars::StarGrowth g(mesh, target, boundary_vertex, options, out);
  for (TetId t : mesh.live_tets())
    if (out.states[t] != TetState::positive && !g.owned(t) && !g.grow_from(t)) {
      record_failure(g, out);
      return out;
    }
  for (const std::vector<TetId>& tets : g.finished()) {
    if (tets.empty()) continue;
    // The incremental tests kept the star a ball; the topology layer confirms it once per star.
    ++out.ball_checks;
    const topology::BallVerdict verdict = stars::check_ball_of(mesh, tets);
    if (!verdict.ok)
      throw std::logic_error(std::string("grow_stars: a grown star is not a ball (") + topology::to_string(verdict.failure) + ")");
    out.stars.push_back(make_star(mesh, g, tets, boundary_vertex, out.states));
  }
  std::sort(out.stars.begin(), out.stars.end(), [](const Star& a, const Star& b) { return a.tets.front() < b.tets.front(); });
  out.tets_in_stars = 0;
  for (const Star& s : out.stars) out.tets_in_stars += s.tets.size();
  out.growth_steps = out.tets_in_stars - (out.inverted + out.flat);
  out.ok = true;
  return out;
}

}  // namespace cmx::algorithm
