#pragma once
// The orientation determinants, written once for every number type T (see arith/number_traits.hpp).
//
// orient3d_det(a, b, c, d) = det[b - a, c - a, d - a] with rows u = b - a, v = c - a, w = d - a:
//   det = u_x (v_y w_z - v_z w_y) + u_y (v_z w_x - v_x w_z) + u_z (v_x w_y - v_y w_x).
// orient2d_det(a, b, c) = det[b - a, c - a] = u_x v_y - u_y v_x.
// The evaluation order is fixed (it is the order the error analysis in orient_semistatic.hpp
// assumes for T = double). Inputs are arrays of 3 (or 2) coordinates.
namespace cmx {

template <class T>
T orient3d_det(const T* a, const T* b, const T* c, const T* d) {
  const T ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const T vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const T wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
  const T mx = vy * wz - vz * wy;
  const T my = vz * wx - vx * wz;
  const T mz = vx * wy - vy * wx;
  return ux * mx + uy * my + uz * mz;
}

template <class T>
T orient2d_det(const T* a, const T* b, const T* c) {
  const T ux = b[0] - a[0], uy = b[1] - a[1];
  const T vx = c[0] - a[0], vy = c[1] - a[1];
  return ux * vy - uy * vx;
}

}  // namespace cmx
