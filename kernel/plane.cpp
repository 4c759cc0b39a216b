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

namespace {

using Vec = std::array<Integer, 3>;

Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Integer dot(const Vec& a, const Vec& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
bool is_zero(const Vec& a) {
  return sgn(a[0]) == 0 && sgn(a[1]) == 0 && sgn(a[2]) == 0;
}

// A vector of the normals' nullspace (possibly zero when none is found this way).
std::vector<Integer> nullspace_candidate(const std::vector<InnerHalfSpace>& hs) {
  const std::size_t k = hs.size();
  std::vector<Integer> y(k);
  if (k == 2) {
    y[0] = dot(hs[1].u, hs[1].u);
    y[1] = -dot(hs[0].u, hs[1].u);
  } else if (k == 3) {
    // d.(b x c) a + d.(c x a) b + d.(a x b) c = det(a, b, c) d = 0 for coplanar a, b, c.
    const Vec bc = cross(hs[1].u, hs[2].u), ca = cross(hs[2].u, hs[0].u), ab = cross(hs[0].u, hs[1].u);
    const Vec& d = !is_zero(ab) ? ab : !is_zero(bc) ? bc : ca;
    y = {dot(d, bc), dot(d, ca), dot(d, ab)};
  } else if (k == 4) {
    // Cofactors: y_i = (-1)^i det of the other three normals.
    for (std::size_t i = 0; i < 4; ++i) {
      Vec m[3];
      for (std::size_t j = 0, r = 0; j < 4; ++j)
        if (j != i) m[r++] = hs[j].u;
      y[i] = dot(m[0], cross(m[1], m[2]));
      if (i % 2) y[i] = -y[i];
    }
  }
  return y;
}

}  // namespace

bool proves_no_common_point(const std::vector<InnerHalfSpace>& hs) {
  if (hs.size() < 2 || hs.size() > 4) return false;
  std::vector<Integer> y = nullspace_candidate(hs);
  int sign = 0;
  for (const Integer& v : y)
    if (sgn(v) != 0) {
      sign = sgn(v);
      break;
    }
  if (sign == 0) return false;
  Vec sum{0, 0, 0};
  Integer offset = 0;
  for (std::size_t i = 0; i < hs.size(); ++i) {
    if (sign < 0) y[i] = -y[i];
    if (sgn(y[i]) < 0) return false;
    for (int c = 0; c < 3; ++c) sum[std::size_t(c)] += y[i] * hs[i].u[std::size_t(c)];
    offset += y[i] * hs[i].w;
  }
  return is_zero(sum) && sgn(offset) <= 0;
}

}  // namespace cmx
