// check_stars (algorithm/local/stars.hpp): recomputes everything from the mesh, the target and
// the stars' tets, apart from the growth's incremental bookkeeping (stars_growth.hpp): faces by
// counting sorted triples, the ball by topology::check_ball, the kernel by the exact Chebyshev LP.
#include <algorithm>
#include <map>
#include <string>

#include "algorithm/local/stars.hpp"
#include "algorithm/local/stars_topology.hpp"
#include "kernel/orient.hpp"
#include "kernel/plane.hpp"
#include "lp/chebyshev_center.hpp"

namespace cmx::algorithm {

namespace {

using topology::TetId;
using topology::Triangle;
using topology::VertexId;

std::string ids(const std::vector<VertexId>& vs) {
  std::string s;
  for (VertexId v : vs) {
    if (!s.empty()) s.push_back(' ');
    s.append(std::to_string(v));
  }
  return s;
}

TetState state_of(const topology::TetMesh& mesh, const std::vector<HPoint>& target, TetId t) {
  const topology::Tet& x = mesh.tet(t);
  // Exact whatever --filter says: the stars of the local initial map are classified, not counted.
  const Sign s =
      orient3d(target[x[0]], target[x[1]], target[x[2]], target[x[3]], PredicateContext::certain());
  return s == Sign::positive ? TetState::positive : s == Sign::zero ? TetState::flat : TetState::inverted;
}

std::string check_states(const topology::TetMesh& mesh, const std::vector<HPoint>& target, const StarSet& set) {
  if (set.states.size() != mesh.tet_capacity()) return "states: " + std::to_string(set.states.size()) + " for " +
                                                       std::to_string(mesh.tet_capacity()) + " tet slots";
  std::size_t inverted = 0, flat = 0;
  for (TetId t : mesh.live_tets()) {
    const TetState s = state_of(mesh, target, t);
    if (s != set.states[t]) return "tet " + std::to_string(t) + ": state differs from its orientation in the target";
    inverted += s == TetState::inverted ? 1 : 0;
    flat += s == TetState::flat ? 1 : 0;
  }
  if (inverted != set.inverted || flat != set.flat) return "the counts of inverted and flat tets differ from the states";
  return "";
}

// The star's boundary as a rotation-normalised list: each triangle starts at its smallest vertex.
Triangle rotated(const Triangle& f) {
  const std::size_t k = std::size_t(std::min_element(f.begin(), f.end()) - f.begin());
  return {f[k], f[(k + 1) % 3], f[(k + 2) % 3]};
}

std::vector<Triangle> outward_boundary(const topology::TetMesh& mesh, const std::vector<TetId>& tets) {
  std::map<Triangle, std::pair<int, Triangle>> faces;  // sorted triple -> (count, oriented face)
  for (TetId t : tets)
    for (int i = 0; i < 4; ++i) {
      const Triangle f = topology::tet_face(mesh.tet(t), i);
      Triangle key = f;
      std::sort(key.begin(), key.end());
      auto& entry = faces[key];
      entry.first += 1;
      entry.second = f;
    }
  std::vector<Triangle> out;
  for (const auto& [key, entry] : faces)
    if (entry.first == 1) out.push_back(rotated(entry.second));
  std::sort(out.begin(), out.end());
  return out;
}

std::string check_fields(const topology::TetMesh& mesh, const Star& s, const std::vector<Triangle>& boundary,
                         const std::vector<char>& in_star, const std::vector<TetState>& states) {
  std::vector<VertexId> vertices, on_boundary, interior;
  std::size_t defects = 0;
  for (TetId t : s.tets) {
    vertices.insert(vertices.end(), mesh.tet(t).begin(), mesh.tet(t).end());
    defects += states[t] != TetState::positive ? 1 : 0;
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  if (vertices != s.vertices) return "its vertices are not those of its tets";
  for (const Triangle& f : boundary) on_boundary.insert(on_boundary.end(), f.begin(), f.end());
  std::sort(on_boundary.begin(), on_boundary.end());
  for (VertexId v : vertices) {
    const auto around = mesh.tets_of(v);
    if (!std::binary_search(on_boundary.begin(), on_boundary.end(), v) &&
        std::all_of(around.begin(), around.end(), [&](TetId t) { return in_star[t] != 0; }))
      interior.push_back(v);
  }
  if (interior != s.interior) return "its interior vertices are not those off its boundary with every tet in it";
  std::vector<Triangle> given;
  for (const Triangle& f : s.boundary) given.push_back(rotated(f));
  std::sort(given.begin(), given.end());
  if (given != boundary) return "its boundary triangles are not the outward faces of its tets in one tet of it";
  if (defects != s.defects) return "its count of non-positive tets is wrong";
  return "";
}

std::string check_kernel(const std::vector<HPoint>& target, const std::vector<Triangle>& boundary) {
  std::vector<lp::HalfSpace> hs;
  for (const Triangle& f : boundary) {
    const InnerHalfSpace h = inner_halfspace(target[f[0]], target[f[1]], target[f[2]]);
    if (h.is_degenerate()) return "boundary triangle " + ids({f[0], f[1], f[2]}) + " is degenerate in the target";
    hs.push_back({Rational(h.u[0]), Rational(h.u[1]), Rational(h.u[2]), Rational(h.w)});
  }
  const lp::ChebyshevResult r = lp::chebyshev_center(hs);
  if (r.status != lp::ChebyshevStatus::interior)
    return "its boundary is not star-shaped in the target (kernel " + std::string(lp::to_string(r.status)) + ")";
  return "";
}

// `earlier[t]`: t is in an earlier star; `in_star` is scratch (one flag per tet slot).
std::string check_star(const topology::TetMesh& mesh, const std::vector<HPoint>& target, const Star& s,
                       const std::vector<char>& earlier, std::vector<char>& in_star, const std::vector<TetState>& states) {
  if (s.tets.empty()) return "it has no tet";
  for (std::size_t i = 0; i < s.tets.size(); ++i) {
    const TetId t = s.tets[i];
    if (!mesh.is_alive(t)) return "tet " + std::to_string(t) + " is not a live tet";
    if (i > 0 && s.tets[i - 1] >= t) return "its tets are not sorted and distinct";
    if (earlier[t]) return "tet " + std::to_string(t) + " is in an earlier star too";
  }
  std::fill(in_star.begin(), in_star.end(), 0);
  for (TetId t : s.tets) in_star[t] = 1;
  const topology::BallVerdict ball = stars::check_ball_of(mesh, s.tets);
  if (!ball.ok) return "it is not a ball: " + std::string(topology::to_string(ball.failure)) + " at vertices " + ids(ball.simplex);
  const std::vector<Triangle> boundary = outward_boundary(mesh, s.tets);
  if (std::string e = check_fields(mesh, s, boundary, in_star, states); !e.empty()) return e;
  return check_kernel(target, boundary);
}

}  // namespace

std::string check_stars(const topology::TetMesh& mesh, const std::vector<HPoint>& target, const StarSet& set) {
  if (!set.ok) return "the star set is not ok: " + set.message;
  if (target.size() != mesh.num_vertices()) return "target: " + std::to_string(target.size()) + " positions for " +
                                                   std::to_string(mesh.num_vertices()) + " vertices";
  if (std::string e = check_states(mesh, target, set); !e.empty()) return e;
  std::vector<char> in_any(mesh.tet_capacity(), 0), in_star(mesh.tet_capacity(), 0);
  std::size_t held = 0;
  for (std::size_t k = 0; k < set.stars.size(); ++k) {
    const Star& s = set.stars[k];
    if (std::string e = check_star(mesh, target, s, in_any, in_star, set.states); !e.empty())
      return "star " + std::to_string(k) + ": " + e;
    if (k > 0 && set.stars[k - 1].tets.front() >= s.tets.front()) return "stars are not ordered by their smallest tet";
    for (TetId t : s.tets) in_any[t] = 1;
    held += s.tets.size();
  }
  if (held != set.tets_in_stars) return "tets_in_stars differs from the stars' sizes";
  for (TetId t : mesh.live_tets())
    if (!in_any[t] && set.states[t] != TetState::positive)
      return "tet " + std::to_string(t) + " is not positive in the target and in no star";
  if (held != set.growth_steps + set.inverted + set.flat) return "growth_steps is not the tets in stars beyond the defects";
  return "";
}

}  // namespace cmx::algorithm
