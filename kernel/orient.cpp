// The orientation predicates: instantiations of the filtered-predicate template.
#include "kernel/orient.hpp"

#include "kernel/filtered_predicate.hpp"
#include "kernel/orient_predicates.hpp"

namespace cmx {

Sign orient3d(const double* a, const double* b, const double* c, const double* d, PredicateContext context) {
  return filtered<Orient3d>(DoubleArgs<4>{{a, b, c, d}}, context);
}

Sign orient3d(const HPoint& a, const HPoint& b, const HPoint& c, const HPoint& d, PredicateContext context) {
  return filtered<Orient3d>(PointArgs<4>{{&a, &b, &c, &d}}, context);
}

Sign orient2d(const double* a, const double* b, const double* c, PredicateContext context) {
  return filtered<Orient2d>(DoubleArgs<3>{{a, b, c}}, context);
}

Sign orient2d(const HPoint& a, const HPoint& b, const HPoint& c, PredicateContext context) {
  return filtered<Orient2d>(PointArgs<3>{{&a, &b, &c}}, context);
}

}  // namespace cmx
