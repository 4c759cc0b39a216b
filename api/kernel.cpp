// cmx/kernel.hpp: the public orientation predicates, over kernel/orient.hpp.
#include "cmx/kernel.hpp"

#include <cmath>
#include <span>
#include <string>

#include "arith/rational.hpp"
#include "kernel/filter_policy.hpp"
#include "kernel/homogeneous_point.hpp"
#include "kernel/orient.hpp"

namespace cmx {
namespace {

constexpr const char* point_names[] = {"a", "b", "c", "d"};

FilterPolicy policy_of(PredicateArithmetic arithmetic) {
  switch (arithmetic) {
    case PredicateArithmetic::interval:
      return {FilterPolicy::Kind::interval};
    case PredicateArithmetic::exact:
      return {FilterPolicy::Kind::exact};
    case PredicateArithmetic::cascade:
      break;
  }
  return {FilterPolicy::Kind::cascade};
}

// Throws cmx::Error for the first coordinate of `points` (each `dims` doubles) that is not finite.
void require_finite(const char* function, std::span<const double* const> points, int dims) {
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < dims; ++k)
      if (const double x = points[i][k]; !std::isfinite(x))
        throw Error(std::string(function) + ": point " + point_names[i] + ", coordinate " + char('x' + k) +
                    " is " + (std::isnan(x) ? "NaN" : "infinite"));
}

HPoint exact_point(const ExactPoint3& p, std::size_t index) {
  Rational c[3];
  for (std::size_t k = 0; k < 3; ++k) {
    std::string why;
    const auto q = parse_rational(p[k], &why);
    if (!q)
      throw Error(std::string("orient3d: point ") + point_names[index] + ", coordinate " + char('x' + k) +
                  " '" + p[k] + "' is not an exact number" + (why.empty() ? "" : " (" + why + ")"));
    c[k] = *q;
  }
  return HPoint(c[0], c[1], c[2]);
}

}  // namespace

const char* to_string(PredicateArithmetic arithmetic) {
  switch (arithmetic) {
    case PredicateArithmetic::interval:
      return "interval";
    case PredicateArithmetic::exact:
      return "exact";
    case PredicateArithmetic::cascade:
      break;
  }
  return "cascade";
}

int orient3d(const Point3d& a, const Point3d& b, const Point3d& c, const Point3d& d,
             PredicateArithmetic arithmetic) {
  const double* const points[] = {a.data(), b.data(), c.data(), d.data()};
  require_finite("orient3d", points, 3);
  return int(
      orient3d(a.data(), b.data(), c.data(), d.data(), PredicateContext{policy_of(arithmetic), nullptr}));
}

int orient3d(const ExactPoint3& a, const ExactPoint3& b, const ExactPoint3& c, const ExactPoint3& d,
             PredicateArithmetic arithmetic) {
  return int(orient3d(exact_point(a, 0), exact_point(b, 1), exact_point(c, 2), exact_point(d, 3),
                      PredicateContext{policy_of(arithmetic), nullptr}));
}

int orient2d(const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& c,
             PredicateArithmetic arithmetic) {
  const double* const points[] = {a.data(), b.data(), c.data()};
  require_finite("orient2d", points, 2);
  return int(orient2d(a.data(), b.data(), c.data(), PredicateContext{policy_of(arithmetic), nullptr}));
}

}  // namespace cmx
