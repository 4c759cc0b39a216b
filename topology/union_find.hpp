#pragma once
// Disjoint sets over dense indices 0..n-1 (path halving, no ranks): the connected components of
// vertex or tet graphs in b0 counts, the ball check and `cmx info`. topology/ uses the standard
// library only, so this is not Boost's disjoint_sets.
#include <cstdint>
#include <numeric>
#include <vector>

namespace cmx::topology {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n = 0) { reset(n); }
  // n singletons again, keeping the storage (for callers that run many small unions).
  void reset(std::size_t n) {
    parent_.resize(n);
    std::iota(parent_.begin(), parent_.end(), 0u);
  }
  // The representative of x's set. Amortised near-constant time.
  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  // Joins the sets of a and b; false when they were one set already.
  bool unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    parent_[a] = b;
    return true;
  }

 private:
  std::vector<std::uint32_t> parent_;
};

}  // namespace cmx::topology
