#include "kernel/orient_exact.hpp"

namespace cmx {

// With rows (X, Y, Z, W) of the four points, det4 = -W_a W_b W_c W_d det[b-a, c-a, d-a]
// (subtract row a from the others and expand along the W column), and every W > 0, so
// orient3d = -sign(det4). det4 is expanded by 2x2 minors of rows (a, b) and (c, d): 30 products.
Sign orient3d_exact(const HPoint& a, const HPoint& b, const HPoint& c, const HPoint& d) {
  auto minor = [](const HPoint& p, const HPoint& q, int i, int j) { return Integer(p.h(i) * q.h(j) - p.h(j) * q.h(i)); };
  Integer ab01 = minor(a, b, 0, 1), ab02 = minor(a, b, 0, 2), ab03 = minor(a, b, 0, 3);
  Integer ab12 = minor(a, b, 1, 2), ab13 = minor(a, b, 1, 3), ab23 = minor(a, b, 2, 3);
  Integer cd01 = minor(c, d, 0, 1), cd02 = minor(c, d, 0, 2), cd03 = minor(c, d, 0, 3);
  Integer cd12 = minor(c, d, 1, 2), cd13 = minor(c, d, 1, 3), cd23 = minor(c, d, 2, 3);
  // Laplace expansion of a 4x4 determinant along its first two rows.
  Integer det4 = ab01 * cd23 - ab02 * cd13 + ab03 * cd12 + ab12 * cd03 - ab13 * cd02 + ab23 * cd01;
  return -Sign(sgn(det4));
}

// det3 of rows (X, Y, W): det3 = W_a W_b W_c det[b-a, c-a] (same argument as above, the W
// column is the last and the cofactor sign is +).
Sign orient2d_exact(const HPoint& a, const HPoint& b, const HPoint& c) {
  auto m = [](const HPoint& p, const HPoint& q, int i, int j) { return Integer(p.h(i) * q.h(j) - p.h(j) * q.h(i)); };
  Integer det3 = a.X() * m(b, c, 1, 3) - a.Y() * m(b, c, 0, 3) + a.W() * m(b, c, 0, 1);
  return Sign(sgn(det3));
}

}  // namespace cmx
