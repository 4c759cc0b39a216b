#include "algorithm/problem/preprocess.hpp"

#include <algorithm>
#include <deque>
#include <numeric>
#include <set>

#include "algorithm/map_error.hpp"
#include "algorithm/precision_loss.hpp"
#include "algorithm/tuning.hpp"
#include "arith/rounding.hpp"
#include "lp/few_bit_point.hpp"
#include "topology/chords.hpp"
#include "topology/cluster_links.hpp"
#include "topology/complex_queries.hpp"

namespace cmx::algorithm {

namespace {

using topology::Triangle;

lp::HalfSpace to_lp(const InnerHalfSpace& h) {
  return {Rational(h.u[0]), Rational(h.u[1]), Rational(h.u[2]), Rational(h.w)};
}

class Preprocessor {
 public:
  Preprocessor(Embedding& e, const ValidatedProblem& p, const PlacementOptions& o)
      : e_(e), problem_(p), options_(o) {}

  PreprocessResult run() {
    // Topology and geometry alternate: a geometric split can open a loop in the cluster mesh
    // (both sides of a split face interior), which the next topological pass closes. Each round
    // splits only interior simplices whose vertices are all on the boundary, so rounds end; the
    // predecessor's split-everything configuration ends them for sure.
    choose_centre();
    for (int round = 0;; ++round) {
      connect_cluster();
      fill_cluster_holes();
      const std::size_t splits = geometry_pass();
      if (cluster_simply_connected() && splits == 0) break;
      if (round == tuning::preprocess_rounds_before_split_all ||
          (splits == 0 && !cluster_simply_connected())) {
        split_all_chords();
        geometry_pass();
        break;
      }
    }
    if (!cluster_simply_connected())
      throw MapError(MapErrorKind::internal,
                     "the cluster mesh is not simply connected after splitting every chord");
    finish();
    return result_;
  }

  // --- combinatorial helpers (the chord machinery lives in topology/chords.hpp) ---------------

  bool is_boundary_face(const Triangle& f) const {
    return topology::tets_around_face(e_.mesh, f[0], f[1], f[2]).size() == 1;
  }
  bool is_chord_edge(VertexId a, VertexId b) const {
    return topology::is_chord_edge(e_.mesh, e_.boundary, a, b);
  }
  int interior_runs(VertexId a, VertexId b, bool& all_interior) const {
    return topology::interior_runs(e_.mesh, e_.unexpanded, a, b, all_interior);
  }
  VertexId split_face(const Triangle& f) { return e_.split_face(f[0], f[1], f[2], HPoint(), true); }
  VertexId split_edge(VertexId a, VertexId b) { return e_.split_edge(a, b, HPoint(), true); }

  topology::ChordContext chords() {
    return {e_.mesh, e_.boundary, e_.unexpanded, [this](VertexId a, VertexId b, VertexId c) {
              return c == topology::invalid_index ? split_edge(a, b) : split_face({a, b, c});
            }};
  }
  bool cluster_simply_connected() const {
    return topology::interior_simply_connected(e_.mesh, e_.unexpanded);
  }
  void connect_cluster() {
    auto c = chords();
    result_.split_topology += topology::connect_interior(c);
  }
  void fill_cluster_holes() {
    auto c = chords();
    result_.split_topology += topology::fill_interior_handles(c);
  }
  void split_all_chords() {
    auto c = chords();
    result_.split_fallback += topology::split_all_chords(c);
  }

  // --- geometry: the shrink point ----------------------------------------------------------

  // The centre every one-interior-vertex tet is tested against: the Chebyshev centre of the
  // kernel and all their half-spaces when that has interior (no split needed at all), else a
  // point of the kernel alone: its few-bit centre with as many coordinates zeroed as stay
  // strictly inside it, or its Chebyshev centre when none can be. The tets kept are those whose
  // half-spaces contain that point, so p_c (chosen in finish() among them, zeros first) gets the
  // same zeros. Testing the kernel's centre instead leaves p_c wherever the kept half-spaces
  // centre it, often with a coordinate along which doubles cannot resolve its crowd
  // (fingers:6,3,50 onto a tet: p_c (0, 0, 45/128), 10 tets inverted in doubles after every
  // repair; tested at the origin: valid doubles at once; docs/algorithm.md, "Shrink point").
  void choose_centre() {
    accepted_.clear();
    for (const auto& h : problem_.kernel) accepted_.push_back(to_lp(h));
    const std::size_t kernel_rows = accepted_.size();
    for (TetId t : e_.mesh.live_tets()) {
      const topology::Tet& tet = e_.mesh.tet(t);
      if (e_.unexpanded_count(tet) != 1) continue;
      int u = 0;
      while (!e_.unexpanded[tet[u]]) ++u;
      const Triangle f = topology::tet_face(tet, u);
      if (is_boundary_face(f)) continue;
      const InnerHalfSpace h = inner_halfspace(e_.target[f[0]], e_.target[f[1]], e_.target[f[2]]);
      if (!h.is_degenerate()) accepted_.push_back(to_lp(h));
    }
    if (accepted_.size() > kernel_rows) {
      solve();
      if (centre_) return;
      accepted_.resize(kernel_rows);
    }
    solve();
    if (!centre_) throw MapError(MapErrorKind::internal, "the boundary kernel lost its interior");
    const cmx::Point3 few = lp::few_bits_by_dyadics(accepted_, last_.center).point;
    const cmx::Point3 zeroed = with_zero_coordinates(few);
    if (std::any_of(zeroed.begin(), zeroed.end(), [](const Rational& c) { return c == 0; }))
      centre_ = HPoint(zeroed[0], zeroed[1], zeroed[2]);
  }

  // Splits, in tet order and then in the pieces made, whatever is invalid for the centre;
  // returns the number of splits.
  std::size_t geometry_pass() {
    std::size_t splits = 0;
    std::deque<TetId> work;
    for (TetId t : e_.mesh.live_tets()) work.push_back(t);
    while (!work.empty()) {
      const TetId t = work.front();
      work.pop_front();
      if (!e_.mesh.is_alive(t)) continue;
      VertexId m = topology::invalid_vertex;
      if (!fix_tet(t, m)) continue;
      ++splits;
      for (TetId n : e_.mesh.tets_of(m)) work.push_back(n);
    }
    return splits;
  }

  // Splits something when tet t is invalid for every acceptable shrink point; returns whether it
  // did (and the new vertex).
  bool fix_tet(TetId t, VertexId& added) {
    const topology::Tet tet = e_.mesh.tet(t);
    const int interior = e_.unexpanded_count(tet);
    if (interior >= 2) return false;
    if (interior == 0) {
      if (e_.orient_target(tet) == Sign::positive) return false;
      ++result_.split_all_boundary_tet;
      added = split_all_boundary(tet);
      return true;
    }
    int u = 0;
    while (!e_.unexpanded[tet[u]]) ++u;
    const Triangle f = topology::tet_face(tet, u);
    if (is_boundary_face(f)) return false;  // a kernel half-space
    if (accept(inner_halfspace(e_.target[f[0]], e_.target[f[1]], e_.target[f[2]]))) return false;
    ++result_.split_no_shrink_point;
    added = split_conflict(f);
    return true;
  }

  // The chord face f of a one-interior-vertex tet conflicts. A chord edge of f is split when f
  // has one (it removes every tet around the chord from the constraints at once, as the
  // predecessor's chord splits do), preferring one whose cycle has a single interior run (the
  // cluster's topology is then unchanged); else f itself.
  VertexId split_conflict(const Triangle& f) {
    int best = -1, best_runs = 0;
    for (int i = 0; i < 3; ++i) {
      const VertexId a = f[i], b = f[(i + 1) % 3];
      if (!is_chord_edge(a, b)) continue;
      bool all_interior = false;
      const int runs = interior_runs(a, b, all_interior);
      if (best < 0 || (runs == 1 && best_runs != 1)) best = i, best_runs = runs;
    }
    if (best >= 0) return split_edge(f[best], f[(best + 1) % 3]);
    return split_face(f);
  }

  // An invalid all-boundary tet: a chord edge when it has one (see split_conflict), else an
  // interior face.
  VertexId split_all_boundary(const topology::Tet& tet) {
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        if (is_chord_edge(tet[i], tet[j])) return split_edge(tet[i], tet[j]);
    return split_face(best_interior_face(tet));
  }

  // An interior face of the all-boundary tet, preferring one whose neighbour has interior
  // vertices (its pieces are then degenerate, adding no constraint, and the cluster gains a
  // vertex hanging from one neighbour).
  Triangle best_interior_face(const topology::Tet& tet) const {
    int best = -1, best_score = -1;
    for (int i = 0; i < 4; ++i) {
      const Triangle f = topology::tet_face(tet, i);
      const auto around = topology::tets_around_face(e_.mesh, f[0], f[1], f[2]);
      if (around.size() != 2) continue;
      for (TetId n : around) {
        const int score = e_.unexpanded_count(e_.mesh.tet(n));
        if (score > best_score) best_score = score, best = i;
      }
    }
    if (best < 0)
      throw MapError(MapErrorKind::internal, "an all-boundary tet without interior face is not positive");
    return topology::tet_face(tet, best);
  }

  bool accept(const InnerHalfSpace& h) {
    if (h.is_degenerate() || side_of(h, *centre_) != Sign::negative) return false;
    accepted_.push_back(to_lp(h));
    return true;
  }

  void solve() {
    ++result_.lps;
    const lp::ChebyshevResult r = lp::chebyshev_center(accepted_, options_.lp);
    centre_.reset();
    if (r.status == lp::ChebyshevStatus::interior) {
      centre_ = HPoint(r.center[0], r.center[1], r.center[2]);
      last_ = r;
    }
  }

  // Doubles resolve a point near p_c only to within ulp(p_c): about 4e-19 next to 1/512, but
  // down to the denormals next to 0. The last vertices of an expansion crowd around p_c (thin
  // inputs: within 1e-20 to 1e-70 of it), and their doubles keep them apart only where p_c's
  // coordinates are 0. So the few-bit centre gets as many coordinates zeroed as keeps it strictly
  // inside every constraint (the origin itself when the origin is inside); measured in
  // docs/algorithm.md, "Shrink point".
  cmx::Point3 with_zero_coordinates(const cmx::Point3& centre) const {
    // Masks of the coordinates set to zero, most zeros first.
    for (const unsigned mask : {7u, 3u, 5u, 6u, 1u, 2u, 4u}) {
      cmx::Point3 q = centre;
      for (unsigned i = 0; i < 3; ++i)
        if (mask & (1u << i)) q[i] = Rational(0);
      if (q != centre && lp::strictly_inside(accepted_, q)) return q;
    }
    return centre;
  }

  // p_c: the Chebyshev centre of everything accepted, with few bits, then the shrink.
  void finish() {
    solve();
    if (!centre_) throw MapError(MapErrorKind::internal, "the shrink point constraints lost their interior");
    result_.shrink_radius = to_double(last_.radius);
    const lp::FewBitResult few = lp::few_bits_by_dyadics(accepted_, last_.center);
    const cmx::Point3 p = with_zero_coordinates(few.point);
    e_.center = e_.arith.round(HPoint(p[0], p[1], p[2]));
    if (!e_.arith.exact() &&
        !lp::strictly_inside(accepted_,
                             {e_.center.coordinate(0), e_.center.coordinate(1), e_.center.coordinate(2)})) {
      PrecisionLoss loss;
      loss.phase = "shrink";
      loss.what = "the shrink point rounded to " + to_string(e_.arith) + " is not strictly inside the kernel";
      loss.exact_bits = lp::point_bits(few.point);
      throw PrecisionLost(std::move(loss));
    }
    for (VertexId v{0}; v < e_.num_vertices(); ++v)
      if (e_.unexpanded[v]) e_.target[v] = e_.center;
  }

  Embedding& e_;
  const ValidatedProblem& problem_;
  const PlacementOptions& options_;
  std::vector<lp::HalfSpace> accepted_;  // every half-space the centre satisfies strictly
  std::optional<HPoint> centre_;
  lp::ChebyshevResult last_;
  PreprocessResult result_;
};

}  // namespace

Embedding initial_embedding(const ValidatedProblem& v, const FilterPolicy& filter,
                            const CoordinateArith& arith, FilterStats* stats) {
  Embedding e;
  e.mesh = v.mesh;
  e.source = v.source;
  e.boundary = v.boundary;
  e.filter = filter;
  e.arith = arith;
  e.stats = stats;
  e.source_free = v.combinatorial;
  const std::size_t n = v.source.size();
  if (e.source_free) {
    e.parents.assign(n, {topology::invalid_index, topology::invalid_index, topology::invalid_index});
    e.origin.resize(n);
    for (std::size_t i = 0; i < n; ++i) e.origin[i] = static_cast<std::uint32_t>(i);
  }
  e.target.resize(n);
  e.unexpanded.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (v.boundary[i])
      e.target[i] = v.prescribed[i];
    else
      e.unexpanded[i] = 1;  // every vertex is in a tet (ball check), so non-boundary = interior
  }
  return e;
}

PreprocessResult preprocess_and_shrink(Embedding& e, const ValidatedProblem& problem,
                                       const PlacementOptions& options) {
  return Preprocessor(e, problem, options).run();
}

}  // namespace cmx::algorithm
