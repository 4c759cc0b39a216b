#pragma once
// The removability rule of topology/shelling.hpp once, for both ways of answering its questions
// (the star walks of is_shelling_removable, the counts of ShellingCounts).
#include <algorithm>
#include <array>

namespace cmx::topology::detail {

// `shared[i]`: face i of t (every vertex but its i-th) lies in another remaining tet.
// `on_boundary(k, l)`: t's vertex k (l < 0) or edge (k, l) lies in a free face of the remaining
// complex; `in_other(k, l)`: it lies in a remaining tet other than t. True when t may go: one to
// three shared faces, and every vertex and edge of t on the boundary (in another tet) only through
// t's own free (shared) faces.
template <class OnBoundary, class InOther>
bool shelling_rule(const std::array<bool, 4>& shared, OnBoundary on_boundary, InOther in_other) {
  const auto j = std::count(shared.begin(), shared.end(), true);
  if (j == 0 || j == 4) return false;
  // A vertex k lies in a free (shared) face of t iff some such face has i != k; an edge (k, l)
  // iff some such face has i != k, l.
  for (int k = 0; k < 4; ++k) {
    bool in_free = false, in_shared = false;
    for (int i = 0; i < 4; ++i)
      if (i != k) (shared[i] ? in_shared : in_free) = true;
    if ((!in_free && on_boundary(k, -1)) || (!in_shared && in_other(k, -1))) return false;
    for (int l = k + 1; l < 4; ++l) {
      bool e_free = false, e_shared = false;
      for (int i = 0; i < 4; ++i)
        if (i != k && i != l) (shared[i] ? e_shared : e_free) = true;
      if ((!e_free && on_boundary(k, l)) || (!e_shared && in_other(k, l))) return false;
    }
  }
  return true;
}

}  // namespace cmx::topology::detail
