// The candidates of Alg. 1 line 5 (algorithm/expansion/candidate_queue.hpp): class first, then the
// order of paper Sec. 4.1.2; stale and expanded entries are never returned; marks are counted once.
#include <doctest/doctest.h>

#include <algorithm>
#include <vector>

#include "algorithm/expansion/candidate_queue.hpp"

using namespace cmx;
using namespace cmx::algorithm;
using namespace cmx::algorithm::detail;
using namespace cmx::topology::literals;

namespace {

// Two tets sharing a face, every vertex in the cluster.
Embedding two_tets() {
  Embedding e;
  e.mesh = topology::TetMesh(5, topology::make_tets({{0, 1, 2, 3}, {1, 2, 3, 4}}));
  e.source.assign(5, HPoint(0, 0, 0));
  e.target = e.source;
  e.unexpanded.assign(5, 1);
  e.boundary.assign(5, 0);
  return e;
}

std::vector<VertexId> drain(CandidateQueue& q) {
  std::vector<VertexId> out;
  while (const auto entry = q.pop()) out.push_back(entry->v);
  return out;
}

}  // namespace

TEST_CASE("candidates come out by class, then lower k, then expanded neighbours, then handle") {
  Embedding e = two_tets();
  CandidateQueue q(e, topology::ExpansionOrder{});
  q.push(0_v, Kind::inflate, 1, 0);
  q.push(1_v, Kind::simple, 2, 1);
  q.push(2_v, Kind::simple, 2, 3);       // more expanded neighbours first among simple ones
  q.push(3_v, Kind::simple, 1, 0);       // lower k first
  q.push(4_v, Kind::star_shapify, 0, 0);
  CHECK(drain(q) == std::vector<VertexId>{3_v, 2_v, 1_v, 4_v, 0_v});
}

TEST_CASE("the index order keeps the class first and then takes handles in increasing order") {
  Embedding e = two_tets();
  CandidateQueue q(e, topology::ExpansionOrder{topology::ExpansionOrderKind::index, 0});
  q.push(4_v, Kind::simple, 3, 0);
  q.push(1_v, Kind::star_shapify, 1, 9);
  q.push(2_v, Kind::simple, 1, 9);
  CHECK(drain(q) == std::vector<VertexId>{2_v, 4_v, 1_v});
}

TEST_CASE("an invalidated entry and the entry of an expanded vertex are skipped") {
  Embedding e = two_tets();
  CandidateQueue q(e, topology::ExpansionOrder{});
  q.push(0_v, Kind::simple, 1, 0);
  q.push(1_v, Kind::simple, 1, 0);
  q.push(2_v, Kind::simple, 1, 0);
  q.invalidate(0_v);  // queued before: stale
  e.unexpanded[1] = 0;
  q.push(0_v, Kind::inflate, 1, 0);  // queued again under the new version
  CHECK(drain(q) == std::vector<VertexId>{2_v, 0_v});
}

TEST_CASE("a vertex marked twice is taken once, and marking a star marks its cluster vertices") {
  Embedding e = two_tets();
  CandidateQueue q(e, topology::ExpansionOrder{});
  q.mark(3_v);
  q.mark(3_v);
  REQUIRE(q.take_marked() == 3_v);
  CHECK_FALSE(q.take_marked());
  e.unexpanded[2] = 0;
  q.mark_star(0_v);  // the tet (0, 1, 2, 3): 2 is expanded
  std::vector<VertexId> taken;
  while (const auto v = q.take_marked()) taken.push_back(*v);
  std::sort(taken.begin(), taken.end());
  CHECK(taken == std::vector<VertexId>{0_v, 1_v, 3_v});
}

TEST_CASE("the queue's per-vertex state grows with the mesh") {
  Embedding e = two_tets();
  CandidateQueue q(e, topology::ExpansionOrder{});
  const VertexId m = e.split_edge(1_v, 4_v, HPoint(0, 0, 0), true);
  q.mark(m);
  q.push(m, Kind::simple, 1, 0);
  CHECK(q.take_marked() == m);
  const auto entry = q.pop();
  REQUIRE(entry);
  CHECK(entry->v == m);
}
