// Relocating collapses (algorithm/collapse/relocating_collapse.hpp): an added vertex is collapsed into a
// neighbour that stays put while other added vertices move out of the way; the map stays valid,
// and a refused collapse changes nothing.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "algorithm/map.hpp"
#include "algorithm/collapse/relocating_collapse.hpp"
#include "map_test_util.hpp"

using namespace cmx;
using namespace cmx::algorithm;
using namespace cmx::generators;
using namespace cmx::test;

TEST_CASE("a relocating collapse removes an added vertex by moving others and keeps every tet positive") {
  std::size_t made = 0, refused = 0;
  for (const std::string shape : collapse_test_shapes) {
    CAPTURE(shape);
    // Without merges the plain collapses leave added vertices that only moving others can remove.
    MapOptions o;
    o.merge = false;
    const MapResult r = map_checked(problem_from(thin_slab(8, 6, 2, 1), shape), o);
    Embedding e = embedding_of(r);
    const std::size_t input = r.stats.input_vertices;
    for (VertexId gone = VertexId(input); gone < e.num_vertices(); ++gone) {
      if (e.mesh.tets_of(gone).empty()) continue;
      const Embedding before = e;
      const std::optional<RelocatingCollapse> c = try_relocating_collapse(e, gone, input, {});
      if (!c) {
        ++refused;
        CHECK(e.source == before.source);
        CHECK(e.target == before.target);
        CHECK(live_tet_tuples(e) == live_tet_tuples(before));
        continue;
      }
      ++made;
      CHECK(e.mesh.tets_of(gone).empty());
      CHECK(!c->movers.empty());
      CHECK(c->movers.size() <= 3);
      for (VertexId u : c->movers) {
        CHECK(u >= input);
        CHECK(!e.boundary[u]);
        CHECK(u != gone);
        CHECK((e.source[u] != before.source[u] || e.target[u] != before.target[u]));
      }
      // Nothing but the movers moved.
      for (VertexId v{0}; v < e.num_vertices(); ++v)
        if (std::find(c->movers.begin(), c->movers.end(), v) == c->movers.end()) {
          CHECK(e.source[v] == before.source[v]);
          CHECK(e.target[v] == before.target[v]);
        }
      CHECK(e.mesh.num_tets() < before.mesh.num_tets());
      CHECK(every_tet_positive(e));
    }
  }
  CHECK(made > 0);
  CHECK(refused > 0);
}

TEST_CASE("the merge pass makes relocating and flip collapses on slabs without interior vertices") {
  std::size_t relocating = 0, flipping = 0;
  for (const std::string shape : collapse_test_shapes)
    for (const GeneratedDomain& slab : {thin_slab(8, 6, 2, 1), thin_slab(12, 9, 2, 1)}) {
      CAPTURE(shape);
      const MapResult r = map_checked(problem_from(slab, shape));
      CHECK(r.stats.relocating_collapses + r.stats.flip_collapses <= r.stats.merged);
      relocating += r.stats.relocating_collapses;
      flipping += r.stats.flip_collapses;
      // Deterministic: the same map again.
      const MapResult again = map_to_domain(problem_from(slab, shape));
      CHECK(again.target == r.target);
      CHECK(again.tets == r.tets);
    }
  CHECK(relocating > 0);
  CHECK(flipping > 0);
}
