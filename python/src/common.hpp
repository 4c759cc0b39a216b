#pragma once
// Shared pieces of the extension module cmx._cmx (python/src/*.cpp): the exception classes, the
// conversions between numpy arrays / Python lists and the plain types of <cmx/types.hpp>.
// The module binds only the public API (<cmx/...>, target cmx::cmx); the pure-Python package
// python/cmx/__init__.py checks and shapes the arguments and builds the user-facing objects.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "cmx/types.hpp"

namespace cmx::python {

namespace py = pybind11;

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
using IndexArray = py::array_t<std::uint32_t, py::array::c_style | py::array::forcecast>;

// The module's exception classes (created in module.cpp, never freed: the module lives as long
// as the interpreter). Error derives from Exception; InvalidInput and InvalidOptions also from
// ValueError, TimeLimit also from TimeoutError; Cancelled, Stuck and PrecisionLost from Error only.
struct ExceptionClasses {
  PyObject* error = nullptr;
  PyObject* invalid_input = nullptr;
  PyObject* invalid_options = nullptr;
  PyObject* time_limit = nullptr;
  PyObject* cancelled = nullptr;
  PyObject* stuck = nullptr;
  PyObject* precision_lost = nullptr;
};
ExceptionClasses& exception_classes();

// Thrown by the bindings, raised in Python as cmx.InvalidOptions / cmx.InvalidInput.
class InvalidOptionsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};
class InvalidInputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An (n, columns) array as n rows; throws InvalidInputError naming `what` on another shape.
std::vector<Point3d> points_of(const DoubleArray& a, const char* what);
std::vector<Tet> tets_of(const IndexArray& a, const char* what);
std::vector<std::uint32_t> indices_of(const IndexArray& a, const char* what);

py::array_t<double> array_of(const std::vector<Point3d>& points);
py::array_t<std::uint32_t> array_of(const std::vector<Tet>& tets);
py::array_t<std::uint32_t> array_of(const std::vector<std::uint32_t>& ids);
// Rows of text as a list of tuples of str.
template <std::size_t N>
py::list text_rows(const std::vector<std::array<std::string, N>>& rows) {
  py::list out(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    py::tuple t(N);
    for (std::size_t k = 0; k < N; ++k) t[k] = py::str(rows[i][k]);
    out[i] = std::move(t);
  }
  return out;
}

void bind_map(py::module_& m);
void bind_kernel_lp(py::module_& m);
void bind_topology_io(py::module_& m);

}  // namespace cmx::python
