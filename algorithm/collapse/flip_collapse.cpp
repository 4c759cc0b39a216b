#include "algorithm/collapse/flip_collapse.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <unordered_map>

#include "algorithm/collapse/collapse_pass.hpp"
#include "algorithm/map_error.hpp"
#include "topology/mesh_edits.hpp"

namespace cmx::algorithm {

namespace {

using topology::Tet;

struct TetHash {
  std::size_t operator()(const Tet& t) const {
    std::size_t h = 0;
    for (VertexId v : t) h = h * 0x9E3779B97F4A7C15ull + v;
    return h;
  }
};

class FlipSearch {
 public:
  FlipSearch(Embedding& e, VertexId gone, const Remover& remover) : e_(e), gone_(gone), remover_(remover) {}

  std::optional<FlipCollapse> run(std::size_t max_flips) {
    std::size_t best = count_failures();
    if (best > flip_collapse_max_failures) return std::nullopt;
    for (std::size_t step = 0; step < max_flips && best > 0; ++step) {
      std::optional<Choice> c = best_flip();
      if (!c || c->score > best) break;
      failures_ = std::move(c->failures);
      made_.push_back(e_.apply_flip(c->plan));
      seen_.insert(key(c->plan.fresh));
      seen_.insert(key(made_.back().removed));  // never undone by a later flip
      best = smallest(failures_);
    }
    if (best == 0)
      if (std::optional<VertexId> keep = try_collapse(e_, gone_)) return success(*keep, {});
    if (!made_.empty() && remover_)
      if (std::optional<Removal> r = remover_()) return success(r->keep, r->moved);
    for (auto f = made_.rbegin(); f != made_.rend(); ++f) e_.undo_flip(*f);
    return std::nullopt;
  }

 private:
  struct Choice {
    topology::FlipPlan plan;
    std::map<VertexId, std::size_t> failures;  // after(plan), kept for when the plan is made
    std::size_t score = 0;
  };

  // Strictly positive in the source and the target; cached, since the search asks again.
  bool positive(const Tet& x) {
    auto [it, fresh] = positive_.try_emplace(x, false);
    if (fresh) it->second = e_.orient_source(x) == Sign::positive && e_.orient_target(x) == Sign::positive;
    return it->second;
  }

  // Whether the collapse gone -> k turns star tet x into a tet that is not positive (x must not
  // contain k: such tets vanish).
  bool fails(Tet x, VertexId k) {
    x[std::size_t(topology::local_index(x, gone_))] = k;
    return !positive(x);
  }

  // failures_[k] for every neighbour k; returns the smallest.
  std::size_t count_failures() {
    failures_.clear();
    std::vector<Tet> star;
    for (TetId t : e_.mesh.tets_of(gone_)) star.push_back(e_.mesh.tet(t));
    for (const Tet& x : star)
      for (VertexId v : x)
        if (v != gone_) failures_[v] = 0;
    for (auto& [k, n] : failures_)
      for (const Tet& x : star)
        if (!topology::contains(x, k) && fails(x, k)) ++n;
    return smallest(failures_);
  }

  static std::size_t smallest(const std::map<VertexId, std::size_t>& m) {
    std::size_t s = std::numeric_limits<std::size_t>::max();
    for (const auto& [k, n] : m) s = std::min(s, n);
    return s;
  }

  // The neighbour a plan takes out of gone's link: for a 3-2 flip, the far end of the flipped
  // edge (in the new tet without gone, not in the one with it); none for a 2-3 flip.
  VertexId leaving(const topology::FlipPlan& plan) const {
    if (plan.fresh.size() != 2) return topology::invalid_vertex;
    const bool first_has_gone = topology::contains(plan.fresh[0], gone_);
    const Tet& with = plan.fresh[first_has_gone ? 0 : 1];
    for (VertexId v : plan.fresh[first_has_gone ? 1 : 0])
      if (!topology::contains(with, v)) return v;
    return topology::invalid_vertex;
  }

  // The failure counts once the plan is made, from the counts before it (a flip of gone's star
  // brings no new neighbour in; every old tet has gone in it).
  std::map<VertexId, std::size_t> after(const topology::FlipPlan& plan) {
    std::map<VertexId, std::size_t> out = failures_;
    out.erase(leaving(plan));
    for (auto& [k, n] : out) {
      for (TetId t : plan.old)
        if (!topology::contains(e_.mesh.tet(t), k) && fails(e_.mesh.tet(t), k)) --n;
      for (const Tet& x : plan.fresh)
        if (topology::contains(x, gone_) && !topology::contains(x, k) && fails(x, k)) ++n;
    }
    return out;
  }

  std::vector<topology::FlipPlan> candidates() const {
    std::vector<topology::FlipPlan> out;
    std::set<std::pair<VertexId, VertexId>> faces;
    std::map<VertexId, int> degree;
    for (TetId t : e_.mesh.tets_of(gone_)) {
      const Tet& x = e_.mesh.tet(t);
      VertexId o[3];
      int n = 0;
      for (VertexId v : x)
        if (v != gone_) o[n++] = v;
      for (int i = 0; i < 3; ++i) {
        ++degree[o[i]];
        const VertexId b = std::min(o[i], o[(i + 1) % 3]), c = std::max(o[i], o[(i + 1) % 3]);
        if (faces.insert({b, c}).second) out.push_back(topology::plan_flip_23(e_.mesh, gone_, b, c));
      }
    }
    for (const auto& [x, n] : degree)
      if (n == 3) out.push_back(topology::plan_flip_32(e_.mesh, gone_, x));
    return out;
  }

  std::optional<Choice> best_flip() {
    std::optional<Choice> best;
    for (topology::FlipPlan& plan : candidates()) {
      if (!plan.ok || seen_.count(key(plan.fresh))) continue;
      if (!std::all_of(plan.fresh.begin(), plan.fresh.end(), [&](const Tet& x) { return positive(x); }))
        continue;
      std::map<VertexId, std::size_t> failures = after(plan);
      const std::size_t s = smallest(failures);
      if (!best || s < best->score) best = Choice{std::move(plan), std::move(failures), s};
    }
    return best;
  }

  // Order-free identity of a set of tets: a flip that would make them again is not made.
  static std::vector<Tet> key(std::vector<Tet> tets) {
    for (Tet& t : tets) std::sort(t.begin(), t.end());
    std::sort(tets.begin(), tets.end());
    return tets;
  }

  FlipCollapse success(VertexId keep, const std::vector<VertexId>& moved) const {
    FlipCollapse out;
    out.keep = keep;
    out.flips = made_.size();
    out.touched = moved;
    for (const topology::FlipResult& f : made_)
      for (TetId t : f.created)
        for (VertexId v : e_.mesh.tet(t)) out.touched.push_back(v);
    std::sort(out.touched.begin(), out.touched.end());
    out.touched.erase(std::unique(out.touched.begin(), out.touched.end()), out.touched.end());
    out.touched.erase(std::remove(out.touched.begin(), out.touched.end(), gone_),
                      out.touched.end());  // no star left
    for (TetId t : e_.mesh.tets_of(keep))
      if (e_.orient_source(e_.mesh.tet(t)) != Sign::positive ||
          e_.orient_target(e_.mesh.tet(t)) != Sign::positive)
        throw MapError(MapErrorKind::internal, "a flip collapse left a tet around vertex " +
                                                   std::to_string(keep) + " that is not positive");
    return out;
  }

  Embedding& e_;
  VertexId gone_;
  const Remover& remover_;
  std::map<VertexId, std::size_t> failures_;
  std::unordered_map<Tet, bool, TetHash> positive_;
  std::set<std::vector<Tet>> seen_;
  std::vector<topology::FlipResult> made_;
};

}  // namespace

std::optional<FlipCollapse> try_flip_collapse(Embedding& e, VertexId gone, const Remover& remover,
                                              std::size_t max_flips) {
  if (e.boundary[gone] || e.mesh.tets_of(gone).empty()) return std::nullopt;
  return FlipSearch(e, gone, remover).run(max_flips);
}

}  // namespace cmx::algorithm
