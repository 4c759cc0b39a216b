#include "kernel/orient_interval.hpp"

#include <cmath>

#include "arith/interval.hpp"
#include "arith/mpfr_interval.hpp"
#include "arith/number_traits.hpp"
#include "kernel/determinant.hpp"

namespace cmx {

namespace {

bool finite_box(const HPoint& p, int dims) {
  for (int k = 0; k < dims; ++k)
    if (!std::isfinite(p.enclosure(k).lo) || !std::isfinite(p.enclosure(k).hi)) return false;
  return true;
}

// Loads the enclosures as opaque intervals: must run inside the rounding scope.
void load(const HPoint& p, int dims, Interval* out) {
  for (int k = 0; k < dims; ++k) out[k] = opaque(Interval(p.enclosure(k).lo, p.enclosure(k).hi));
}
void load(const double* p, int dims, Interval* out) {
  for (int k = 0; k < dims; ++k) out[k] = opaque(Interval(p[k]));
}

bool finite(const double* p, int dims) {
  for (int k = 0; k < dims; ++k)
    if (!std::isfinite(p[k])) return false;
  return true;
}

template <class P>
UncertainSign interval_orient3d(const P& a, const P& b, const P& c, const P& d) {
  Interval det;
  {
    UpwardRoundingScope upward;
    Interval p[4][3];
    load(a, 3, p[0]);
    load(b, 3, p[1]);
    load(c, 3, p[2]);
    load(d, 3, p[3]);
    det = opaque(orient3d_det(p[0], p[1], p[2], p[3]));
  }
  return NumberTraits<Interval>::sign(det);
}

template <class P>
UncertainSign interval_orient2d(const P& a, const P& b, const P& c) {
  Interval det;
  {
    UpwardRoundingScope upward;
    Interval p[3][2];
    load(a, 2, p[0]);
    load(b, 2, p[1]);
    load(c, 2, p[2]);
    det = opaque(orient2d_det(p[0], p[1], p[2]));
  }
  return NumberTraits<Interval>::sign(det);
}

void load_mpfr(const HPoint& p, int dims, long bits, MpfrInterval* out) {
  for (int k = 0; k < dims; ++k) out[k] = NumberTraits<MpfrInterval>::from_rational(p.coordinate(k), bits);
}

}  // namespace

UncertainSign orient3d_interval(const HPoint& a, const HPoint& b, const HPoint& c, const HPoint& d) {
  if (!finite_box(a, 3) || !finite_box(b, 3) || !finite_box(c, 3) || !finite_box(d, 3)) return std::nullopt;
  return interval_orient3d(a, b, c, d);
}

UncertainSign orient2d_interval(const HPoint& a, const HPoint& b, const HPoint& c) {
  if (!finite_box(a, 2) || !finite_box(b, 2) || !finite_box(c, 2)) return std::nullopt;
  return interval_orient2d(a, b, c);
}

UncertainSign orient3d_interval(const double* a, const double* b, const double* c, const double* d) {
  if (!finite(a, 3) || !finite(b, 3) || !finite(c, 3) || !finite(d, 3)) return std::nullopt;
  return interval_orient3d(a, b, c, d);
}

UncertainSign orient2d_interval(const double* a, const double* b, const double* c) {
  if (!finite(a, 2) || !finite(b, 2) || !finite(c, 2)) return std::nullopt;
  return interval_orient2d(a, b, c);
}

UncertainSign orient3d_mpfr(const HPoint& a, const HPoint& b, const HPoint& c, const HPoint& d, long bits) {
  MpfrInterval p[4][3] = {{MpfrInterval(bits), MpfrInterval(bits), MpfrInterval(bits)},
                          {MpfrInterval(bits), MpfrInterval(bits), MpfrInterval(bits)},
                          {MpfrInterval(bits), MpfrInterval(bits), MpfrInterval(bits)},
                          {MpfrInterval(bits), MpfrInterval(bits), MpfrInterval(bits)}};
  load_mpfr(a, 3, bits, p[0]);
  load_mpfr(b, 3, bits, p[1]);
  load_mpfr(c, 3, bits, p[2]);
  load_mpfr(d, 3, bits, p[3]);
  return NumberTraits<MpfrInterval>::sign(orient3d_det(p[0], p[1], p[2], p[3]));
}

UncertainSign orient2d_mpfr(const HPoint& a, const HPoint& b, const HPoint& c, long bits) {
  MpfrInterval p[3][2] = {{MpfrInterval(bits), MpfrInterval(bits)},
                          {MpfrInterval(bits), MpfrInterval(bits)},
                          {MpfrInterval(bits), MpfrInterval(bits)}};
  load_mpfr(a, 2, bits, p[0]);
  load_mpfr(b, 2, bits, p[1]);
  load_mpfr(c, 2, bits, p[2]);
  return NumberTraits<MpfrInterval>::sign(orient2d_det(p[0], p[1], p[2]));
}

}  // namespace cmx
