// The extension module cmx._cmx: exception classes, array conversions, and the module itself.
// What each function does is documented in python/cmx/__init__.py, which wraps them.
#include <exception>

#include "python/src/common.hpp"

#ifndef CMX_PYTHON_VERSION
#error "CMX_PYTHON_VERSION (the project version) is set by python/CMakeLists.txt"
#endif

namespace cmx::python {

ExceptionClasses& exception_classes() {
  static ExceptionClasses classes;
  return classes;
}

namespace {

// A new exception class cmx.<name> with the given bases, added to the module; a new reference
// kept for the interpreter's life.
PyObject* new_exception(py::module_& m, const char* name, const char* doc, py::tuple bases) {
  const std::string qualified = std::string("cmx.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
  if (!type) throw py::error_already_set();
  m.attr(name) = py::handle(type);
  return type;
}

void check_rows(const py::buffer_info& info, py::ssize_t columns, const char* what) {
  if (info.ndim != 2 || info.shape[1] != columns)
    throw InvalidInputError(std::string(what) + ": expected an array of shape (n, " + std::to_string(columns) + ")");
}

}  // namespace

std::vector<Point3d> points_of(const DoubleArray& a, const char* what) {
  const py::buffer_info info = a.request();
  if (info.ndim == 1 && info.shape[0] == 0) return {};
  check_rows(info, 3, what);
  const double* p = a.data();
  std::vector<Point3d> out(static_cast<std::size_t>(info.shape[0]));
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = {p[3 * i], p[3 * i + 1], p[3 * i + 2]};
  return out;
}

std::vector<Tet> tets_of(const IndexArray& a, const char* what) {
  const py::buffer_info info = a.request();
  if (info.ndim == 1 && info.shape[0] == 0) return {};
  check_rows(info, 4, what);
  const std::uint32_t* p = a.data();
  std::vector<Tet> out(static_cast<std::size_t>(info.shape[0]));
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = {p[4 * i], p[4 * i + 1], p[4 * i + 2], p[4 * i + 3]};
  return out;
}

std::vector<std::uint32_t> indices_of(const IndexArray& a, const char* what) {
  const py::buffer_info info = a.request();
  if (info.ndim != 1) throw InvalidInputError(std::string(what) + ": expected a 1-dimensional array of indices");
  return std::vector<std::uint32_t>(a.data(), a.data() + info.shape[0]);
}

py::array_t<double> array_of(const std::vector<Point3d>& points) {
  py::array_t<double> out({static_cast<py::ssize_t>(points.size()), py::ssize_t{3}});
  double* p = out.mutable_data();
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k) p[3 * i + k] = points[i][k];
  return out;
}

py::array_t<std::uint32_t> array_of(const std::vector<Tet>& tets) {
  py::array_t<std::uint32_t> out({static_cast<py::ssize_t>(tets.size()), py::ssize_t{4}});
  std::uint32_t* p = out.mutable_data();
  for (std::size_t i = 0; i < tets.size(); ++i)
    for (std::size_t k = 0; k < 4; ++k) p[4 * i + k] = tets[i][k];
  return out;
}

py::array_t<std::uint32_t> array_of(const std::vector<std::uint32_t>& ids) {
  py::array_t<std::uint32_t> out(static_cast<py::ssize_t>(ids.size()));
  std::copy(ids.begin(), ids.end(), out.mutable_data());
  return out;
}

}  // namespace cmx::python

PYBIND11_MODULE(_cmx, m) {
  namespace py = pybind11;
  using namespace cmx::python;
  m.doc() = "cmx's compiled core (use the package cmx, which wraps it)";
  m.attr("__version__") = CMX_PYTHON_VERSION;

  ExceptionClasses& e = exception_classes();
  const py::handle exception(PyExc_Exception), value_error(PyExc_ValueError), timeout_error(PyExc_TimeoutError);
  e.error = new_exception(m, "Error", "Base class of cmx's errors (a C++ cmx::Error arrives as this class).",
                          py::make_tuple(exception));
  const py::handle error(e.error);
  e.invalid_input = new_exception(m, "InvalidInput",
                                  "Bad input: not a ball, a bad index, NaN, a boundary that is not star-shaped, "
                                  "... (the message says which; .reason is a stable name).",
                                  py::make_tuple(error, value_error));
  e.invalid_options = new_exception(m, "InvalidOptions", "An option value that does not parse or is out of range.",
                                    py::make_tuple(error, value_error));
  e.time_limit = new_exception(m, "TimeLimit", "The run reached its time_limit.", py::make_tuple(error, timeout_error));
  e.cancelled = new_exception(m, "Cancelled", "The run was cancelled (the progress callback returned True).",
                              py::make_tuple(error));
  e.stuck = new_exception(m, "Stuck", "No cluster vertex could be expanded (the message says which case).",
                          py::make_tuple(error));
  e.precision_lost = new_exception(m, "PrecisionLost", "A non-exact arith lost validity (the message says where).",
                                   py::make_tuple(error));

  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InvalidOptionsError& x) {
      PyErr_SetString(exception_classes().invalid_options, x.what());
    } catch (const InvalidInputError& x) {
      PyErr_SetString(exception_classes().invalid_input, x.what());
    } catch (const cmx::Error& x) {
      PyErr_SetString(exception_classes().error, x.what());
    }
  });

  bind_map(m);
  bind_kernel_lp(m);
  bind_topology_io(m);
}
