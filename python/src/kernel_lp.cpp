// cmx._cmx.orient3d / orient2d (cmx/kernel.hpp) and chebyshev_centre (cmx/lp.hpp).
#include <string>

#include "cmx/kernel.hpp"
#include "cmx/lp.hpp"
#include "python/src/common.hpp"

namespace cmx::python {
namespace {

PredicateArithmetic arithmetic_of(const std::string& name) {
  if (name == "cascade") return PredicateArithmetic::cascade;
  if (name == "interval") return PredicateArithmetic::interval;
  if (name == "exact") return PredicateArithmetic::exact;
  throw InvalidOptionsError("arithmetic: '" + name + "' is not a predicate arithmetic (cascade, interval, exact)");
}

py::dict centre_dict(const ChebyshevCentre& c) {
  py::dict d;
  d["status"] = std::string(to_string(c.status));
  d["centre_exact"] = py::make_tuple(c.centre_exact[0], c.centre_exact[1], c.centre_exact[2]);
  d["centre"] = py::make_tuple(c.centre[0], c.centre[1], c.centre[2]);
  d["radius_exact"] = c.radius_exact;
  d["radius"] = c.radius;
  return d;
}

ChebyshevCentreOptions centre_options(const std::string& lp, const std::string& norm, unsigned weight_bits) {
  ChebyshevCentreOptions o;
  o.lp = lp;
  o.norm = norm;
  o.weight_bits = weight_bits;
  return o;
}

}  // namespace

void bind_kernel_lp(py::module_& m) {
  m.def(
      "orient3d_doubles",
      [](const Point3d& a, const Point3d& b, const Point3d& c, const Point3d& d, const std::string& arithmetic) {
        return orient3d(a, b, c, d, arithmetic_of(arithmetic));
      },
      py::arg("a"), py::arg("b"), py::arg("c"), py::arg("d"), py::arg("arithmetic"));
  m.def(
      "orient3d_exact",
      [](const ExactPoint3& a, const ExactPoint3& b, const ExactPoint3& c, const ExactPoint3& d,
         const std::string& arithmetic) { return orient3d(a, b, c, d, arithmetic_of(arithmetic)); },
      py::arg("a"), py::arg("b"), py::arg("c"), py::arg("d"), py::arg("arithmetic"));
  m.def(
      "orient2d_doubles",
      [](const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& c,
         const std::string& arithmetic) { return orient2d(a, b, c, arithmetic_of(arithmetic)); },
      py::arg("a"), py::arg("b"), py::arg("c"), py::arg("arithmetic"));
  m.def(
      "chebyshev_centre_doubles",
      [](const DoubleArray& rows, const std::string& lp, const std::string& norm, unsigned weight_bits) {
        const py::buffer_info info = rows.request();
        if (info.ndim != 2 || info.shape[1] != 4)
          throw InvalidInputError("halfspaces: expected an array of shape (k, 4) of rows (a, b, c, d): a x + b y + c z <= d");
        std::vector<std::array<double, 4>> h(static_cast<std::size_t>(info.shape[0]));
        const double* p = rows.data();
        for (std::size_t i = 0; i < h.size(); ++i) h[i] = {p[4 * i], p[4 * i + 1], p[4 * i + 2], p[4 * i + 3]};
        ChebyshevCentre c;
        {
          py::gil_scoped_release release;
          c = chebyshev_centre(h, centre_options(lp, norm, weight_bits));
        }
        return centre_dict(c);
      },
      py::arg("halfspaces"), py::arg("lp"), py::arg("norm"), py::arg("weight_bits"));
  m.def(
      "chebyshev_centre_exact",
      [](const std::vector<std::array<std::string, 4>>& h, const std::string& lp, const std::string& norm,
         unsigned weight_bits) {
        ChebyshevCentre c;
        {
          py::gil_scoped_release release;
          c = chebyshev_centre(h, centre_options(lp, norm, weight_bits));
        }
        return centre_dict(c);
      },
      py::arg("halfspaces"), py::arg("lp"), py::arg("norm"), py::arg("weight_bits"));
}

}  // namespace cmx::python
