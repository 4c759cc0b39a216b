#include "algorithm/collapse/relocating_collapse.hpp"

#include <algorithm>
#include <string>
#include <tuple>
#include <utility>

#include "algorithm/collapse/merge_pass.hpp"
#include "algorithm/expansion/expansion_cone.hpp"
#include "algorithm/map_error.hpp"
#include "topology/complex_queries.hpp"
#include "topology/mesh_edits.hpp"

namespace cmx::algorithm {

namespace {

constexpr std::size_t max_movers = 3;

// gone's tets without keep, gone replaced by keep: the tets the collapse rewrites.
std::vector<topology::Tet> rewritten(const Embedding& e, VertexId keep, VertexId gone) {
  std::vector<topology::Tet> out;
  for (TetId t : e.mesh.tets_of(gone)) {
    topology::Tet x = e.mesh.tet(t);
    if (topology::contains(x, keep)) continue;
    x[std::size_t(topology::local_index(x, gone))] = keep;
    out.push_back(x);
  }
  return out;
}

// u's star once gone is collapsed into keep: tets with gone and keep vanish, gone becomes keep.
std::vector<topology::Tet> star_after(const Embedding& e, VertexId u, VertexId keep, VertexId gone) {
  std::vector<topology::Tet> out;
  for (TetId t : e.mesh.tets_of(u)) {
    topology::Tet x = e.mesh.tet(t);
    const int g = topology::local_index(x, gone);
    if (g >= 0) {
      if (topology::contains(x, keep)) continue;
      x[std::size_t(g)] = keep;
    }
    out.push_back(x);
  }
  return out;
}

bool positive(const Embedding& e, const topology::Tet& x) {
  return e.orient_source(x) == Sign::positive && e.orient_target(x) == Sign::positive;
}

bool all_positive(const Embedding& e, const std::vector<topology::Tet>& tets, bool source) {
  return std::all_of(tets.begin(), tets.end(), [&](const topology::Tet& x) {
    return (source ? e.orient_source(x) : e.orient_target(x)) == Sign::positive;
  });
}

// Moves u (in the source or the target) strictly inside the kernel of `star` (u's tets after the
// collapse) unless every tet there is positive already; false when no such point is found.
bool place_mover(Embedding& e, VertexId u, const std::vector<topology::Tet>& star, bool source,
                 const PlacementOptions& options) {
  if (all_positive(e, star, source)) return true;
  const std::vector<HPoint>& points = source ? e.source : e.target;
  std::vector<topology::Triangle> faces;
  for (const topology::Tet& x : star) faces.push_back(topology::tet_face(x, topology::local_index(x, u)));
  // The float screen first: exact half-spaces on long coordinates are only built for a kernel
  // that the float LP finds open.
  std::vector<std::array<double, 4>> rows;
  for (const topology::Triangle& f : faces)
    rows.push_back(float_inner_row(points[f[0]], points[f[1]], points[f[2]]));
  const lp::FloatChebyshev guess = lp::float_chebyshev(rows);
  if (!guess.optimal || !(guess.radius > merge_min_float_radius * guess.scale)) return false;
  ExpansionCone cone;
  cone.apex = u;
  for (const topology::Triangle& f : faces) {
    InnerHalfSpace h = inner_halfspace(points[f[0]], points[f[1]], points[f[2]]);
    if (h.is_degenerate()) return false;
    cone.halfspaces.push_back(std::move(h));
  }
  const Placement p = place_in_cone(cone, options);
  if (!p.ok() || !strictly_inside(cone, p.position)) return false;
  (source ? e.source : e.target)[u] = p.position;
  return true;
}

class Relocator {
 public:
  Relocator(Embedding& e, std::size_t input_vertices, const PlacementOptions& options)
      : e_(e), input_(input_vertices), options_(options) {}

  bool movable(VertexId u) const { return u >= input_ && !e_.boundary[u] && !e_.unexpanded[u]; }

  // The added vertices of the rewritten tets that are not positive, or nullopt when such a tet
  // has none (or when there are more than max_movers).
  std::optional<std::vector<VertexId>> movers(VertexId keep, VertexId gone) const {
    std::vector<VertexId> out;
    for (const topology::Tet& x : rewritten(e_, keep, gone)) {
      if (positive(e_, x)) continue;
      bool any = false;
      for (VertexId u : x)
        if (u != keep && movable(u)) {
          any = true;
          if (std::find(out.begin(), out.end(), u) == out.end()) out.push_back(u);
        }
      if (!any || out.size() > max_movers) return std::nullopt;
    }
    std::sort(out.begin(), out.end());
    return out;
  }

  // Moves the movers for the collapse of gone into keep (a mover whose star an earlier move has
  // already made positive stays), then checks every tet that changes. Returns the vertices that
  // moved, or nullopt with every position restored.
  std::optional<std::vector<VertexId>> relocate(VertexId keep, VertexId gone,
                                                const std::vector<VertexId>& movers) {
    std::vector<std::pair<HPoint, HPoint>> saved;
    for (VertexId u : movers) saved.emplace_back(e_.source[u], e_.target[u]);
    bool ok = true;
    for (VertexId u : movers) {
      const std::vector<topology::Tet> star = star_after(e_, u, keep, gone);
      ok = place_mover(e_, u, star, true, options_) && place_mover(e_, u, star, false, options_);
      if (!ok) break;
    }
    ok = ok && changed_tets_positive(keep, gone, movers);
    std::vector<VertexId> moved;
    for (std::size_t i = 0; i < movers.size(); ++i) {
      const VertexId u = movers[i];
      if (!ok)
        std::tie(e_.source[u], e_.target[u]) = saved[i];
      else if (e_.source[u] != saved[i].first || e_.target[u] != saved[i].second)
        moved.push_back(u);
    }
    if (!ok) return std::nullopt;
    return moved;
  }

 private:
  bool changed_tets_positive(VertexId keep, VertexId gone, const std::vector<VertexId>& movers) const {
    const auto ok = [&](const std::vector<topology::Tet>& tets) {
      return std::all_of(tets.begin(), tets.end(), [&](const topology::Tet& x) { return positive(e_, x); });
    };
    if (!ok(rewritten(e_, keep, gone))) return false;
    return std::all_of(movers.begin(), movers.end(),
                       [&](VertexId u) { return ok(star_after(e_, u, keep, gone)); });
  }

  Embedding& e_;
  std::size_t input_;
  const PlacementOptions& options_;
};

void check_positive_around(const Embedding& e, VertexId v) {
  for (TetId t : e.mesh.tets_of(v))
    if (!positive(e, e.mesh.tet(t)))
      throw MapError(MapErrorKind::internal, "a relocating collapse left a tet around vertex " +
                                                 std::to_string(v) + " that is not positive");
}

}  // namespace

std::optional<RelocatingCollapse> try_relocating_collapse(Embedding& e, VertexId gone,
                                                          std::size_t input_vertices,
                                                          const PlacementOptions& options) {
  Relocator r(e, input_vertices, options);
  if (!r.movable(gone)) return std::nullopt;
  // Fewest movers first (then neighbour order): fewer LPs, and fewer vertices pushed around.
  std::vector<std::pair<std::vector<VertexId>, VertexId>> candidates;
  for (VertexId keep : topology::vertex_neighbors(e.mesh, gone)) {
    if (e.unexpanded[keep]) continue;
    std::optional<std::vector<VertexId>> m = r.movers(keep, gone);
    if (m && !m->empty()) candidates.emplace_back(std::move(*m), keep);
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const auto& a, const auto& b) { return a.first.size() < b.first.size(); });
  for (const auto& [movers, keep] : candidates) {
    if (!topology::satisfies_link_condition(e.mesh, keep, gone)) continue;
    std::optional<std::vector<VertexId>> moved = r.relocate(keep, gone, movers);
    if (!moved) continue;
    // The link condition holds, so the collapse is made.
    if (!e.collapse_edge(keep, gone).ok)
      throw MapError(MapErrorKind::internal, "a collapse satisfying the link condition was refused");
    check_positive_around(e, keep);
    for (VertexId u : *moved) check_positive_around(e, u);
    return RelocatingCollapse{keep, std::move(*moved)};
  }
  return std::nullopt;
}

}  // namespace cmx::algorithm
