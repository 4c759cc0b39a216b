#pragma once
// The method's invariants (paper Sec. 3 and 4), checked from scratch: what `--check` asserts
// after every step, and what the shrink asserts once.
//   1. every cluster vertex sits at p_c;
//   2. a tet with two or more cluster vertices is degenerate (automatic by 1); every other tet is
//      strictly positive in the target;
//   3. the cluster mesh is simply connected (b0 = 1, chi = 1) while it is not empty;
//   4. boundary vertices sit at their prescribed positions;
//   5. every tet is strictly positive in the source.
#include <optional>
#include <string>
#include <vector>

#include "algorithm/embedding.hpp"
#include "algorithm/precision_loss.hpp"

namespace cmx::algorithm {

// "" when every invariant holds, else a description of the first violation.
std::string check_invariants(const Embedding& e, const std::vector<HPoint>& prescribed);

// A tet breaking invariant 2 (target; skipped when `source_only`) or 5 (source), with the
// orientation found (negative or zero).
struct InvalidTet {
  topology::Tet tet;
  bool in_source = false;
  Sign orientation = Sign::zero;
};
std::optional<InvalidTet> invalid_tet(const Embedding& e, const topology::Tet& t, bool source_only = false);
std::optional<InvalidTet> first_invalid_tet_around(const Embedding& e, VertexId v, bool source_only = false);

// The loss record of a non-exact run: `bad` found around vertex v, corners from the positions.
PrecisionLoss precision_loss_at(const Embedding& e, VertexId v, const InvalidTet& bad, std::string phase,
                                std::string what);

// Invariant 2 on the tets around one vertex only (cheap; used after every expansion).
std::string check_local_invariant(const Embedding& e, VertexId v);

}  // namespace cmx::algorithm
