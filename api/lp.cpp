// cmx/lp.hpp: the Chebyshev centre over lp::chebyshev_center.
#include "cmx/lp.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "arith/rational.hpp"
#include "arith/rounding.hpp"
#include "lp/backend_registry.hpp"
#include "lp/chebyshev_center.hpp"
#include "lp/row_weights.hpp"

namespace cmx {
namespace {

constexpr const char* column_names[] = {"a", "b", "c", "d"};

std::string where(std::size_t row, std::size_t column) {
  return "chebyshev_centre: row " + std::to_string(row) + ", " + column_names[column];
}

Rational value(double x, std::size_t row, std::size_t column) {
  if (!std::isfinite(x)) throw Error(where(row, column) + " is " + (std::isnan(x) ? "NaN" : "infinite"));
  return rational_from_double(x);
}

Rational value(const std::string& text, std::size_t row, std::size_t column) {
  std::string why;
  if (auto q = parse_rational(text, &why)) return *q;
  throw Error(where(row, column) + " '" + text + "' is not an exact number" +
              (why.empty() ? "" : " (" + why + ")"));
}

lp::ChebyshevOptions lp_options(const ChebyshevCentreOptions& options) {
  lp::ChebyshevOptions o;
  if (!lp::find_backend(options.lp))
    throw Error("chebyshev_centre: unknown lp '" + options.lp + "' (certified or exact)");
  o.backend = options.lp;
  const auto norm = lp::parse_norm(options.norm);
  if (!norm) throw Error("chebyshev_centre: unknown norm '" + options.norm + "' (l2-upper or l1)");
  o.norm = *norm;
  if (options.weight_bits < 2 || options.weight_bits > 53)
    throw Error("chebyshev_centre: weight_bits " + std::to_string(options.weight_bits) + " is outside 2..53");
  o.weight_bits = options.weight_bits;
  return o;
}

CentreStatus status_of(lp::ChebyshevStatus s) {
  switch (s) {
    case lp::ChebyshevStatus::interior:
      return CentreStatus::interior;
    case lp::ChebyshevStatus::empty_interior:
      return CentreStatus::empty_interior;
    case lp::ChebyshevStatus::unbounded:
      return CentreStatus::unbounded;
    case lp::ChebyshevStatus::infeasible:
      break;
  }
  return CentreStatus::infeasible;
}

template <class Row>
ChebyshevCentre solve(std::span<const Row> rows, const ChebyshevCentreOptions& options) {
  const lp::ChebyshevOptions o = lp_options(options);
  std::vector<lp::HalfSpace> halfspaces;
  halfspaces.reserve(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i)
    halfspaces.push_back(
        {value(rows[i][0], i, 0), value(rows[i][1], i, 1), value(rows[i][2], i, 2), value(rows[i][3], i, 3)});
  lp::ChebyshevResult r;
  try {
    r = lp::chebyshev_center(halfspaces, o);
  } catch (const std::invalid_argument& e) {
    throw Error(std::string("chebyshev_centre: ") + e.what());
  } catch (const lp::UnsupportedProblem& e) {  // a reference backend registered by the caller
    throw Error(std::string("chebyshev_centre: ") + e.what());
  }
  ChebyshevCentre out;
  out.status = status_of(r.status);
  if (out.status == CentreStatus::interior || out.status == CentreStatus::empty_interior) {
    for (std::size_t k = 0; k < 3; ++k) {
      out.centre_exact[k] = to_string(r.center[k]);
      out.centre[k] = to_double(r.center[k]);
    }
    out.radius_exact = to_string(r.radius);
    out.radius = to_double(r.radius);
  }
  return out;
}

}  // namespace

const char* to_string(CentreStatus status) {
  switch (status) {
    case CentreStatus::interior:
      return "interior";
    case CentreStatus::empty_interior:
      return "empty_interior";
    case CentreStatus::unbounded:
      return "unbounded";
    case CentreStatus::infeasible:
      break;
  }
  return "infeasible";
}

ChebyshevCentre chebyshev_centre(std::span<const std::array<double, 4>> halfspaces,
                                 const ChebyshevCentreOptions& options) {
  return solve(halfspaces, options);
}

ChebyshevCentre chebyshev_centre(std::span<const std::array<std::string, 4>> halfspaces,
                                 const ChebyshevCentreOptions& options) {
  return solve(halfspaces, options);
}

}  // namespace cmx
