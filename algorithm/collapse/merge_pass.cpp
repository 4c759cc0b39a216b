#include "algorithm/collapse/merge_pass.hpp"

#include <array>
#include <optional>
#include <set>
#include <vector>

#include "algorithm/collapse/collapse_pass.hpp"
#include "algorithm/collapse/flip_collapse.hpp"
#include "algorithm/collapse/relocating_collapse.hpp"
#include "algorithm/expansion/expansion_cone.hpp"
#include "algorithm/map_error.hpp"
#include "topology/complex_queries.hpp"
#include "topology/mesh_edits.hpp"

namespace cmx::algorithm {

namespace {

using Approx = std::array<double, 3>;

class Merger {
 public:
  Merger(Embedding& e, std::size_t input_vertices, const PlacementOptions& options)
      : e_(e), input_(input_vertices), options_(options) {
    for (const HPoint& p : e_.source) source_approx_.push_back(p.approx());
    for (const HPoint& p : e_.target) target_approx_.push_back(p.approx());
  }

  std::optional<VertexId> try_merge(VertexId gone) {
    if (gone < input_ || e_.boundary[gone]) return std::nullopt;
    for (VertexId keep : topology::vertex_neighbors(e_.mesh, gone)) {
      if (e_.boundary[keep] || e_.unexpanded[keep]) continue;
      // An input vertex keeps its source position; only its target may move.
      const std::optional<HPoint> from = keep < input_ ? own_source(keep, gone) : position(true, keep, gone);
      if (!from) continue;
      if (!topology::satisfies_link_condition(e_.mesh, keep, gone)) continue;
      const std::optional<HPoint> at = position(false, keep, gone);
      if (!at) continue;
      if (!e_.collapse_edge(keep, gone).ok) continue;
      move(keep, *from, *at);
      return keep;
    }
    return std::nullopt;
  }

  // The float copies of vertices moved by someone else (a relocating collapse).
  void refresh(const std::vector<VertexId>& moved) {
    for (VertexId v : moved) {
      source_approx_[v] = e_.source[v].approx();
      target_approx_[v] = e_.target[v].approx();
    }
  }

 private:
  // The tets of keep's star once gone is collapsed into it, each as (tet, the vertex replaced by
  // keep): gone's tets without keep, and keep's tets without gone.
  template <class F>
  void for_each_merged_face(VertexId keep, VertexId gone, F&& f) const {
    for (const auto& [apex, other] : {std::pair{gone, keep}, std::pair{keep, gone}})
      for (TetId t : e_.mesh.tets_of(apex)) {
        const topology::Tet& tet = e_.mesh.tet(t);
        if (!topology::contains(tet, other)) f(topology::tet_face(tet, topology::local_index(tet, apex)));
      }
  }

  ExpansionCone exact_cone(const std::vector<HPoint>& points, VertexId keep, VertexId gone) const {
    ExpansionCone cone;
    cone.apex = keep;
    for_each_merged_face(keep, gone, [&](const topology::Triangle& f) {
      InnerHalfSpace h = inner_halfspace(points[f[0]], points[f[1]], points[f[2]]);
      if (h.is_degenerate()) cone.degenerate = true;
      cone.halfspaces.push_back(std::move(h));
    });
    return cone;
  }

  std::vector<std::array<double, 4>> float_rows(const std::vector<Approx>& approx, VertexId keep,
                                                VertexId gone) const {
    std::vector<std::array<double, 4>> rows;
    for_each_merged_face(keep, gone, [&](const topology::Triangle& f) {
      rows.push_back(float_inner_row(approx[f[0]], approx[f[1]], approx[f[2]]));
    });
    return rows;
  }

  // Every tet of the merged star strictly positive with keep at c (filtered exact predicates,
  // much cheaper than the exact half-spaces on long coordinates). The star's two halves: gone's
  // tets rewritten with keep, and keep's own tets. A half whose geometry c leaves as it is
  // (gone's at gone's position, keep's at keep's) is positive already, the map being valid, and
  // is not tested again.
  bool positive_at(std::vector<HPoint>& points, bool source, VertexId keep, VertexId gone, const HPoint& c) {
    const HPoint saved = points[keep];
    points[keep] = c;
    bool ok = true;
    for (const auto& [apex, other] : {std::pair{gone, keep}, std::pair{keep, gone}}) {
      if (c == saved ? apex == keep : c == points[gone] && apex == gone) continue;
      for (TetId t : e_.mesh.tets_of(apex)) {
        topology::Tet x = e_.mesh.tet(t);
        if (topology::contains(x, other)) continue;
        x[topology::local_index(x, apex)] = keep;
        ok = (source ? e_.orient_source(x) : e_.orient_target(x)) == Sign::positive;
        if (!ok) break;
      }
      if (!ok) break;
    }
    points[keep] = saved;
    return ok;
  }

  // keep's own source position when it works (an input vertex keeps it), or nullopt.
  std::optional<HPoint> own_source(VertexId keep, VertexId gone) {
    const HPoint here = e_.source[keep];
    if (positive_at(e_.source, true, keep, gone, here)) return here;
    return std::nullopt;
  }

  // A point strictly inside the merged star's kernel on `points` (see the header), or nullopt.
  std::optional<HPoint> position(bool source, VertexId keep, VertexId gone) {
    std::vector<HPoint>& points = source ? e_.source : e_.target;
    const std::vector<Approx>& approx = source ? source_approx_ : target_approx_;
    // Copies: positive_at moves points[keep] while it tests.
    const std::array<HPoint, 3> candidates{points[keep], points[gone], midpoint(points[keep], points[gone])};
    for (const HPoint& c : candidates)
      if (positive_at(points, source, keep, gone, c)) return c;
    const lp::FloatChebyshev f = lp::float_chebyshev(float_rows(approx, keep, gone));
    if (!f.optimal || !(f.radius > merge_min_float_radius * f.scale)) return std::nullopt;
    const ExpansionCone cone = exact_cone(points, keep, gone);
    if (cone.degenerate) return std::nullopt;
    const Placement p = place_in_cone(cone, options_);
    if (!p.ok() || !strictly_inside(cone, p.position)) return std::nullopt;
    return p.position;
  }

  void move(VertexId keep, const HPoint& from, const HPoint& at) {
    e_.source[keep] = from;
    e_.target[keep] = at;
    source_approx_[keep] = from.approx();
    target_approx_[keep] = at.approx();
    for (TetId t : e_.mesh.tets_of(keep))
      if (e_.orient_target(e_.mesh.tet(t)) != Sign::positive ||
          e_.orient_source(e_.mesh.tet(t)) != Sign::positive)
        throw MapError(MapErrorKind::internal,
                       "a merge left a tet around vertex " + std::to_string(keep) + " that is not positive");
  }

  Embedding& e_;
  std::size_t input_;
  const PlacementOptions& options_;
  std::vector<Approx> source_approx_, target_approx_;
};

}  // namespace

MergeResult merge_added_vertices(Embedding& e, std::size_t input_vertices, const PlacementOptions& options,
                                 const MergeSettings& settings) {
  Merger merger(e, input_vertices, options);
  std::set<VertexId> work;
  for (std::size_t v = input_vertices; v < e.num_vertices(); ++v)
    if (!e.mesh.tets_of(VertexId(v)).empty()) work.insert(VertexId(v));
  MergeResult out;
  std::size_t& removed = out.removed;
  while (!work.empty()) {
    if (settings.control && settings.control->step("collapse", removed)) {
      out.stopped = true;
      return out;
    }
    const VertexId v = *work.rbegin();
    work.erase(v);
    if (e.mesh.tets_of(v).empty()) continue;
    std::optional<VertexId> keep = try_collapse(e, v);
    if (!keep) keep = merger.try_merge(v);
    std::vector<VertexId> moved;
    if (!keep)
      if (std::optional<RelocatingCollapse> r = try_relocating_collapse(e, v, input_vertices, options)) {
        keep = r->keep;
        moved = std::move(r->movers);
        merger.refresh(moved);
        ++out.relocating;
      }
    if (!keep && settings.flip_collapses) {
      // Once flips are made: the two ways above that move vertices, tried again on the new cut.
      const Remover moving_removal = [&]() -> std::optional<Removal> {
        if (std::optional<VertexId> k = merger.try_merge(v)) return Removal{*k, {}};
        if (std::optional<RelocatingCollapse> r = try_relocating_collapse(e, v, input_vertices, options)) {
          merger.refresh(r->movers);
          return Removal{r->keep, r->movers};
        }
        return std::nullopt;
      };
      if (std::optional<FlipCollapse> f = try_flip_collapse(e, v, moving_removal)) {
        keep = f->keep;
        moved = std::move(f->touched);  // their stars changed, nothing moved
        ++out.flipping;
      }
    }
    if (!keep) continue;
    ++removed;
    moved.push_back(*keep);
    if (settings.after_step) settings.after_step(moved);
    for (VertexId m : moved) {
      for (VertexId w : topology::vertex_neighbors(e.mesh, m))
        if (w >= input_vertices) work.insert(w);
      if (m >= input_vertices) work.insert(m);
    }
  }
  return out;
}

}  // namespace cmx::algorithm
