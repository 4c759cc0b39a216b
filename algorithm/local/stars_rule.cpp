#include "algorithm/local/stars_rule.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "algorithm/local/stars_kernel.hpp"

namespace cmx::algorithm::stars {

namespace {

std::vector<std::array<double, 3>> nearest_doubles(const std::vector<HPoint>& points) {
  std::vector<std::array<double, 3>> out;
  out.reserve(points.size());
  for (const HPoint& p : points) {
    out.push_back(p.approx());
    for (double x : out.back())
      if (!std::isfinite(x)) throw std::invalid_argument("grow_stars: a target coordinate lies beyond the doubles");
  }
  return out;
}

}  // namespace

StarGrowth::StarGrowth(const topology::TetMesh& mesh, const std::vector<HPoint>& target,
                       const std::vector<char>& boundary_vertex, const StarOptions& options, StarSet& out)
    : mesh_(mesh),
      target_(target),
      fixed_(topology::boundary_vertex_flags(mesh)),
      options_(options),
      out_(out),
      adjacency_(topology::tet_adjacency(mesh)),
      approx_(nearest_doubles(target)),
      owner_(mesh.tet_capacity(), no_star),
      star_(mesh, adjacency_, approx_, owner_) {
  if (!adjacency_.manifold) throw std::invalid_argument("grow_stars: a face lies in three or more tets");
  for (std::size_t v = 0; v < fixed_.size(); ++v) fixed_[v] = fixed_[v] || boundary_vertex[v];
}

void StarGrowth::add(TetId t) {
  if (star_.contains(t)) return;
  if (owned(t)) {
    absorb(owner_[t]);
    return;
  }
  star_.add(t);
  pending_.erase(t);
  if (out_.states[t] != TetState::positive) defects_.push_back(t);
  for (TetId nb : adjacency_.neighbor[t])
    if (nb != topology::invalid_index && !owned(nb) && out_.states[nb] != TetState::positive) pending_.insert(nb);
}

void StarGrowth::absorb(std::int32_t other) {
  ++out_.merges;
  const std::vector<TetId> tets = std::exchange(finished_[std::size_t(other)], {});
  in_finished_ -= tets.size();
  for (TetId t : tets) owner_[t] = no_star;
  for (TetId t : tets) add(t);
}

void StarGrowth::finish() {
  in_finished_ += star_.tets().size();
  finished_.push_back(star_.release());
  defects_.clear();
}

bool StarGrowth::may_go_on() {
  out_.tets_in_stars = held();
  if (double(held()) > options_.max_share * double(mesh_.num_tets())) {
    std::ostringstream m;
    m << "the stars would hold more than " << 100 * options_.max_share << " % of the tets (" << held() << " of "
      << mesh_.num_tets() << ")";
    out_.message = m.str();
    return false;
  }
  if (options_.control && options_.control->step("stars", held(), mesh_.num_tets())) {
    out_.message = "stopped while growing stars";
    return false;
  }
  return true;
}

// Adds, in order, the candidates of no star with which the star stays a ball (only the first
// when `one`); when there is none, the first candidate, repaired.
bool StarGrowth::grow_step(const std::vector<TetId>& candidates, bool one) {
  bool added = false;
  for (TetId t : candidates) {
    if (owned(t) || !star_.extends_ball(t)) continue;
    add(t);
    added = true;
    if (one) break;
  }
  return added || repair(candidates.front());
}

// The tets missing around the first pinch at a vertex of `dirty` (ascending): around the edge
// whose fan is broken, or around the vertex whose link is wrong. Empty when there is none.
std::vector<TetId> StarGrowth::pinch_fixes(const std::set<VertexId>& dirty) const {
  for (VertexId v : dirty) {
    const std::optional<topology::Edge> pinch = star_.pinch_at(v);
    if (!pinch) continue;
    std::vector<TetId> fixes;
    for (TetId t : mesh_.tets_of(v))
      if (!star_.contains(t) && ((*pinch)[1] == v || topology::contains(mesh_.tet(t), (*pinch)[1]))) fixes.push_back(t);
    std::sort(fixes.begin(), fixes.end());
    return fixes;
  }
  return {};
}

std::vector<TetId> StarGrowth::outer_layer() const {
  std::set<TetId> layer;
  for (const FaceRef& f : star_.boundary()) {
    const TetId nb = star_.behind(f);
    if (nb != topology::invalid_index) layer.insert(nb);
  }
  return {layer.begin(), layer.end()};
}

// Adds t although the star may not stay a ball (or t belongs to a finished star, which comes
// with it), then the tets around each pinch at a vertex of what it added, until the star is a
// 3-manifold there, and a layer around the star while its boundary is not one sphere. Before, the
// star was a ball, so only the links of the vertices of added tets can be wrong
// (stars_manifold.cpp has why these local tests decide).
bool StarGrowth::repair(TetId t) {
  ++out_.repairs;
  std::set<VertexId> dirty;
  std::size_t seen = star_.tets().size();
  const auto note_added = [&] {
    for (; seen < star_.tets().size(); ++seen)
      for (VertexId v : mesh_.tet(star_.tets()[seen])) dirty.insert(v);
  };
  add(t);
  note_added();
  while (true) {
    std::vector<TetId> fixes = pinch_fixes(dirty);
    if (fixes.empty()) {
      if (star_.boundary_is_sphere()) return true;
      fixes = outer_layer();
    }
    if (fixes.empty()) {
      out_.message = "the whole mesh is not a ball";
      return false;
    }
    for (TetId f : fixes) add(f);
    note_added();
    if (!may_go_on()) return false;
  }
}

// The vertex of `defect` to make interior: neither flagged nor on the mesh boundary, with the most non-positive
// tets around it (the fold it sits in), then the fewest tets still outside the star, then the
// smallest handle. invalid_index when the defect has an interior vertex already or none can be.
VertexId StarGrowth::vertex_to_free(TetId defect) const {
  VertexId best = topology::invalid_vertex;
  std::size_t best_folded = 0, best_missing = 0;
  for (VertexId v : mesh_.tet(defect)) {
    if (fixed_[v]) continue;
    const std::size_t missing = mesh_.tets_of(v).size() - star_.vertex_tets(v);
    if (missing == 0) return topology::invalid_vertex;
    std::size_t folded = 0;
    for (TetId t : mesh_.tets_of(v)) folded += out_.states[t] != TetState::positive ? 1 : 0;
    const bool better = best == topology::invalid_index || folded > best_folded ||
                        (folded == best_folded && (missing < best_missing || (missing == best_missing && v < best)));
    if (better) {
      best = v;
      best_folded = folded;
      best_missing = missing;
    }
  }
  return best;
}

// The tets still outside the star around the vertex to free of its first defect without an
// interior vertex (ascending); empty when there is none.
std::vector<TetId> StarGrowth::tets_freeing_a_defect() const {
  for (TetId d : defects_) {
    const VertexId v = vertex_to_free(d);
    if (v == topology::invalid_index) continue;
    std::vector<TetId> around;
    for (TetId t : mesh_.tets_of(v))
      if (!star_.contains(t)) around.push_back(t);
    std::sort(around.begin(), around.end());
    return around;
  }
  return {};
}

bool StarGrowth::grow_from(TetId seed) {
  star_.start(std::int32_t(finished_.size()));
  add(seed);
  while (may_go_on()) {
    std::vector<TetId> candidates(pending_.begin(), pending_.end());
    if (candidates.empty() && options_.free_defects) candidates = tets_freeing_a_defect();
    if (!candidates.empty()) {
      if (!grow_step(candidates, false)) return false;
      continue;
    }
    const KernelTest k = test_kernel(star_, target_, approx_, options_.placement.lp);
    ++out_.kernel_tests;
    out_.exact_lps += k.exact_lp ? 1 : 0;
    if (k.star_shaped) {
      finish();
      return true;
    }
    if (k.grow_across.empty()) {
      out_.message = "the star grew to the whole mesh, whose boundary is not star-shaped in the target";
      return false;
    }
    for (std::size_t i : k.grow_across) candidates.push_back(star_.behind(star_.boundary()[i]));
    if (!grow_step(candidates, true)) return false;
  }
  return false;
}

}  // namespace cmx::algorithm::stars
