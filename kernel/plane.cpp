#include "kernel/plane.hpp"

namespace cmx {

namespace {

// det of the 3x3 matrix whose rows are (p_i, p_j, p_k) restricted to homogeneous columns i, j, k.
Integer det3(const HPoint& p, const HPoint& q, const HPoint& r, int i, int j, int k) {
  const Integer m1 = q.h(j) * r.h(k) - q.h(k) * r.h(j);
  const Integer m2 = q.h(i) * r.h(k) - q.h(k) * r.h(i);
  const Integer m3 = q.h(i) * r.h(j) - q.h(j) * r.h(i);
  return p.h(i) * m1 - p.h(j) * m2 + p.h(k) * m3;
}

}  // namespace

InnerHalfSpace inner_halfspace(const HPoint& p, const HPoint& q, const HPoint& r) {
  // Cofactors of det4[p; q; r; x] along the last row: a = -det[Y Z W], b = +det[X Z W],
  // c = -det[X Y W], d = +det[X Y Z]. Inner side: L(x) > 0, i.e. -a x - b y - c z < d.
  InnerHalfSpace h;
  h.u[0] = det3(p, q, r, 1, 2, 3);   // -a
  h.u[1] = -det3(p, q, r, 0, 2, 3);  // -b
  h.u[2] = det3(p, q, r, 0, 1, 3);   // -c
  h.w = det3(p, q, r, 0, 1, 2);      // d
  return h;
}

Sign side_of(const InnerHalfSpace& h, const HPoint& x) {
  // u . (X/W) - w has the sign of u . (X, Y, Z) - w W since W > 0.
  const Integer s = h.u[0] * x.X() + h.u[1] * x.Y() + h.u[2] * x.Z() - h.w * x.W();
  return Sign(sgn(s));
}

}  // namespace cmx
