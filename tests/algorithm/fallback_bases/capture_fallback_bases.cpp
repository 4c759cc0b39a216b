// Makes the test data of tests/algorithm/test_fallback_bases.cpp: maps Furch's knotted hole
// (generators::knotted_hole, perturbation seed 1, scale 1) onto the four generated boundary shapes
// (corners farthest, as `cmx boundary --corners farthest`) with the shelling star-shapification wherever
// bends and pushes fail (MapOptions::shelled after-pushes), cuts the state out around each vertex handed to
// it (fallback_base.hpp) and keeps the cuts on which, replayed on their own, bends and pushes fail again, the
// fallback expands the vertex, and every invariant holds before and after. Usage: capture_fallback_bases
// OUTDIR [PER_SHAPE=3]. Deterministic: the same binary writes the same files.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "algorithm/expansion/cluster_expansion.hpp"
#include "algorithm/map.hpp"
#include "algorithm/verify/invariants.hpp"
#include "arith/rounding.hpp"
#include "fallback_base.hpp"
#include "generators/boundary_shapes.hpp"
#include "generators/domain_generators.hpp"
#include "topology/cluster_links.hpp"

namespace {

namespace alg = cmx::algorithm;

alg::MapProblem knotted_hole_onto(const std::string& shape) {
  const cmx::generators::GeneratedDomain d = cmx::generators::knotted_hole(1);
  auto spec = cmx::generators::parse_boundary_shape(shape);
  spec->corners = cmx::generators::CornerChoice::farthest;  // drawn corners find no boundary here
  const cmx::generators::GeneratedBoundary b =
      cmx::generators::generate_boundary(d.mesh, d.double_positions(), *spec);
  if (!b.ok) throw std::runtime_error(b.message);
  alg::MapProblem p;
  for (cmx::topology::TetId t : d.mesh.live_tets()) p.tets.push_back(d.mesh.tet(t));
  p.source = d.positions;
  p.boundary_vertices = b.vertices;
  for (const auto& q : b.positions)
    p.boundary_positions.push_back(
        {cmx::rational_from_double(q[0]), cmx::rational_from_double(q[1]), cmx::rational_from_double(q[2])});
  return p;
}

// Replays the three steps on copies of the cut: why it is not kept, or "".
std::string replay(const cmx::test::FallbackBase& b) {
  const std::vector<cmx::HPoint> prescribed = cmx::test::prescribed_of(b.state);
  if (std::string why = alg::check_invariants(b.state, prescribed); !why.empty())
    return "cut invalid: " + why;
  // The refinement tried before (inflation, the pushes) may have changed v's link since v was
  // classified: the fallback needs a v that satisfies Eq. (1), and such a call is no test of it.
  cmx::topology::ClusterLinkWorkspace ws;
  if (!cmx::topology::classify_cluster_vertex(b.state.mesh, b.v, b.state.unexpanded, ws).expandable)
    return "v no longer satisfies Eq. (1)";
  alg::ExpansionSettings s;
  alg::MapStatistics stats;
  for (alg::RefinementStep step : {alg::RefinementStep::bends, alg::RefinementStep::pushes}) {
    alg::Embedding copy = b.state;
    if (alg::refine_by(copy, b.v, step, s, stats)) return "bends or pushes expand it on the cut";
  }
  alg::Embedding copy = b.state;
  if (!alg::refine_by(copy, b.v, alg::RefinementStep::shelling, s, stats))
    return "the fallback fails on the cut";
  if (copy.unexpanded[b.v]) return "the fallback did not expand the vertex";
  if (std::string why = alg::check_invariants(copy, cmx::test::prescribed_of(copy)); !why.empty())
    return "after the fallback: " + why;
  return "";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: capture_fallback_bases OUTDIR [PER_SHAPE=3]\n");
    return 2;
  }
  const std::string dir = argv[1];
  const int per_shape = argc > 2 ? std::atoi(argv[2]) : 3;
  for (const std::string shape : {"tet", "stiff-tet", "sphere", "star"}) {
    int kept = 0, failed = 0, seen = 0;
    alg::MapOptions o;
    o.shelled = alg::ShelledMode::after_pushes;
    o.time_limit_seconds = 300;
    o.before_fallback = [&](const alg::Embedding& e, cmx::topology::VertexId v) {
      ++seen;
      if (kept >= per_shape && failed >= 1) return;
      const cmx::test::FallbackBase b = cmx::test::cut_around(e, v);
      const std::string why = replay(b);
      std::printf("%s #%d: vertex %u, cut %zu vertices %zu tets: %s\n", shape.c_str(), seen, v.idx(),
                  b.state.num_vertices(), b.state.mesh.num_tets(), why.empty() ? "kept" : why.c_str());
      const bool fails = why == "the fallback fails on the cut";
      if ((!why.empty() && !fails) || (fails ? failed >= 1 : kept >= per_shape)) return;
      std::string path = dir + "/knotted_hole_" + shape;
      path += fails ? "_fails_" : "_";
      path += std::to_string(fails ? failed : kept);
      path += ".base";
      cmx::test::write_fallback_base(
          path, b,
          "Furch's knotted hole (generators::knotted_hole, seed 1, scale 1) onto the generated '" + shape +
              "' boundary\n(corners farthest), mapped with MapOptions::shelled = after-pushes: the vertex of "
              "call " +
              std::to_string(seen) +
              " of\nMapOptions::before_fallback (bends and pushes failed on it; run vertex " +
              std::to_string(v.idx()) +
              ").\nWritten by tests/algorithm/fallback_bases/capture_fallback_bases.cpp.");
      ++(fails ? failed : kept);
    };
    const alg::MapResult r = alg::map_to_domain(knotted_hole_onto(shape), o);
    std::printf("%s: %s; %d fallback calls, %d kept\n", shape.c_str(), r.message.c_str(), seen, kept);
  }
  return 0;
}
