// Flip collapses (algorithm/collapse/flip_collapse.hpp): flips of an added vertex's star, each keeping
// every tet positive, until the vertex collapses into a neighbour; the map stays valid, no
// vertex moves, and a refused search leaves the mesh as it was.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "algorithm/collapse/flip_collapse.hpp"
#include "algorithm/map.hpp"
#include "algorithm/collapse/merge_pass.hpp"
#include "map_test_util.hpp"
#include "topology/consistency.hpp"

using namespace cmx;
using namespace cmx::algorithm;
using namespace cmx::generators;
using namespace cmx::test;

namespace {

// The live tets in a canonical order (a refused search may put tets back under new handles).
// Undone flips put tets back under new handles: compare as sets.
std::vector<topology::Tet> sorted_tets(const Embedding& e) {
  std::vector<topology::Tet> out = live_tet_tuples(e);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_CASE("a flip collapse removes an added vertex without moving any and keeps every tet positive") {
  std::size_t made = 0, refused = 0, flips = 0, asked = 0;
  // A remover that removes nothing: asked only once flips are made, and then all are undone.
  const Remover nothing = [&]() -> std::optional<Removal> {
    ++asked;
    return std::nullopt;
  };
  for (const std::string shape : collapse_test_shapes) {
    CAPTURE(shape);
    // Without merges more added vertices are left for the flips to try.
    MapOptions o;
    o.merge = false;
    const MapResult r = map_checked(problem_from(thin_slab(12, 9, 2, 1), shape), o);
    Embedding e = embedding_of(r);
    const std::size_t input = r.stats.input_vertices;
    for (VertexId gone = VertexId(input); gone < e.num_vertices(); ++gone) {
      if (e.mesh.tets_of(gone).empty()) continue;
      const Embedding before = e;
      const std::optional<FlipCollapse> c = try_flip_collapse(e, gone, nothing);
      CHECK(e.source == before.source);
      CHECK(e.target == before.target);
      CHECK(topology::check_incidences(e.mesh).ok);
      if (!c) {
        ++refused;
        CHECK(sorted_tets(e) == sorted_tets(before));
        continue;
      }
      ++made;
      flips += c->flips;
      CHECK(e.mesh.tets_of(gone).empty());
      CHECK(c->keep != gone);
      CHECK(c->flips <= flip_collapse_max_flips);
      CHECK(std::is_sorted(c->touched.begin(), c->touched.end()));
      // Only gone left the mesh (a 2-3 flip adds a tet, so the tet count may even grow).
      for (VertexId v{0}; v < e.num_vertices(); ++v)
        if (v != gone) CHECK(e.mesh.tets_of(v).empty() == before.mesh.tets_of(v).empty());
      CHECK(every_tet_positive(e));
    }
  }
  CHECK(made > 0);
  CHECK(flips > 0);
  CHECK(refused > 0);
  CHECK(asked > 0);
}

TEST_CASE("the merge pass hands every changed star to its after-step hook") {
  MapOptions o;
  o.merge = false;
  const MapResult r = map_checked(problem_from(thin_slab(12, 9, 2, 1), "star:3"), o);
  Embedding e = embedding_of(r);
  const std::size_t input = r.stats.input_vertices;
  std::size_t steps = 0;
  const auto hook = [&](const std::vector<VertexId>& changed) {
    ++steps;
    REQUIRE(!changed.empty());
    for (VertexId v : changed) {
      CHECK(!e.mesh.tets_of(v).empty());
      for (TetId t : e.mesh.tets_of(v)) {
        CHECK(e.orient_source(e.mesh.tet(t)) == Sign::positive);
        CHECK(e.orient_target(e.mesh.tet(t)) == Sign::positive);
      }
    }
  };
  MergeSettings settings;
  settings.after_step = hook;
  const MergeResult m = merge_added_vertices(e, input, {}, settings);
  CHECK(m.removed > 0);
  CHECK(steps == m.removed);
  CHECK(m.flipping > 0);
  CHECK(every_tet_positive(e));
}
