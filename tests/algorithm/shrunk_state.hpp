#pragma once
// The method's state right after the shrink, built by its own validation and preprocessing, for
// tests of single steps (cones, placements, subclusters).
#include <doctest/doctest.h>

#include <vector>

#include "algorithm/verify/invariants.hpp"
#include "algorithm/problem/preprocess.hpp"
#include "algorithm/problem/validate_problem.hpp"

namespace cmx::test {

struct Shrunk {
  algorithm::Embedding e;
  std::vector<HPoint> prescribed;  // per vertex (meaningful for boundary vertices)
};

inline Shrunk shrunk(const algorithm::MapProblem& problem) {
  const algorithm::MapOptions options;
  const algorithm::ValidatedProblem v =
      algorithm::validate_problem(problem, options.filter, options.placement.lp);
  Shrunk s;
  s.e = algorithm::initial_embedding(v, options.filter, options.placement.arith);
  algorithm::preprocess_and_shrink(s.e, v, options.placement);
  s.prescribed = v.prescribed;
  s.prescribed.resize(s.e.num_vertices());
  REQUIRE(algorithm::check_invariants(s.e, s.prescribed).empty());
  return s;
}

}  // namespace cmx::test
