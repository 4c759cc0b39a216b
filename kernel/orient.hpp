#pragma once
// The orientation predicates of the compiled kernel: exact signs through the filtered-predicate
// template (kernel/filtered_predicate.hpp), the tiers chosen by context.policy and the deciding
// tier counted into context.stats (kernel/filter_policy.hpp). There is no default context: a
// caller inside a run passes the run's, a caller that checks a result passes
// PredicateContext::certain().
//
// Sign convention: orient3d(a, b, c, d) is the sign of det[b-a, c-a, d-a]; it is positive for the
// unit tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1). This is the OPPOSITE of Shewchuk's and
// TetGen's orient3d(a, b, c, d). orient2d(a, b, c) is the sign of det[b-a, c-a] (positive when
// a, b, c turn counterclockwise); on HPoints it uses x and y only.
//
// Every policy but `naive` returns the exact sign for all inputs. Cascade on HPoints:
//   all points doubles (HPoint::is_double) -> semi-static filter -> adaptive stages A-D
//     (-> exact, only when a coordinate is outside [2^-250, 2^250]);
//   otherwise -> double interval on the cached enclosures -> [MPFR interval] -> exact.
// The double path never touches GMP.
//
// Raw-double overloads read 3 (orient3d) or 2 (orient2d) doubles per point and throw
// std::domain_error if any coordinate is NaN or infinite (no sign is ever returned for them).
// The same determinants on a number type of your choice: kernel/orient_predicates.hpp.
#include "arith/sign.hpp"
#include "kernel/filter_policy.hpp"
#include "kernel/homogeneous_point.hpp"

namespace cmx {

Sign orient3d(const HPoint& a, const HPoint& b, const HPoint& c, const HPoint& d, PredicateContext context);
Sign orient3d(const double* a, const double* b, const double* c, const double* d, PredicateContext context);

Sign orient2d(const HPoint& a, const HPoint& b, const HPoint& c, PredicateContext context);
Sign orient2d(const double* a, const double* b, const double* c, PredicateContext context);

}  // namespace cmx
