// cmx._cmx.map_doubles / map_exact: cmx::map_to_domain with the GIL released, options from a
// dict, the progress callback and Ctrl-C served on the calling thread, and the result object.
#include "cmx/map.hpp"

#include <atomic>
#include <chrono>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string_view>
#include <thread>
#include <utility>

#include "python/src/common.hpp"

namespace cmx::python {
namespace {

// MapProgress with its phase copied (the string_view lives only during the callback).
struct Progress {
  std::string phase;
  std::size_t done = 0, total = 0, expanded = 0, remaining = 0, added_vertices = 0, max_bits = 0;
  double seconds = 0;
};

template <class T>
T option_value(const char* name, py::handle value, const char* expected) {
  try {
    return value.cast<T>();
  } catch (const py::cast_error&) {
    throw InvalidOptionsError(std::string("option ") + name + ": expected " + expected + ", got " +
                              py::repr(value).cast<std::string>());
  }
}

std::size_t count_option(const char* name, py::handle value) {
  if (py::isinstance<py::bool_>(value) || !py::isinstance<py::int_>(value) ||
      value.cast<py::int_>() < py::int_(0))
    throw InvalidOptionsError(std::string("option ") + name + ": expected a non-negative integer, got " +
                              py::repr(value).cast<std::string>());
  return option_value<std::size_t>(name, value, "a non-negative integer");
}

bool bool_option(const char* name, py::handle value) {
  if (!py::isinstance<py::bool_>(value))
    throw InvalidOptionsError(std::string("option ") + name + ": expected True or False, got " +
                              py::repr(value).cast<std::string>());
  return value.cast<bool>();
}

std::string text_option(const char* name, py::handle value) {
  if (!py::isinstance<py::str>(value))
    throw InvalidOptionsError(std::string("option ") + name + ": expected a str, got " +
                              py::repr(value).cast<std::string>());
  return value.cast<std::string>();
}

InitialMap init_option(py::handle value) {
  const std::string s = text_option("init", value);
  if (s == "auto" || s == "automatic") return InitialMap::automatic;
  if (s == "shrink") return InitialMap::shrink;
  if (s == "tutte") return InitialMap::tutte;
  if (s == "given") return InitialMap::given;
  throw InvalidOptionsError("option init: '" + s + "' is not an initial map (auto, shrink, tutte, given)");
}

// The keywords that set one MapOptions field of a plain type, by the field's type.
template <class T>
using Fields = std::initializer_list<std::pair<std::string_view, T MapOptions::*>>;
const Fields<std::size_t> count_fields = {{"threads", &MapOptions::threads},
                                          {"subclusters", &MapOptions::subclusters},
                                          {"smooth", &MapOptions::smooth}};
const Fields<bool> bool_fields = {
    {"collapse", &MapOptions::collapse}, {"check", &MapOptions::check}, {"combinatorial", &MapOptions::combinatorial}};
const Fields<std::string> text_fields = {{"snap", &MapOptions::snap},
                                         {"order", &MapOptions::order},
                                         {"filter", &MapOptions::filter},
                                         {"lp", &MapOptions::lp},
                                         {"norm", &MapOptions::norm},
                                         {"precision", &MapOptions::precision},
                                         {"arith", &MapOptions::arith},
                                         {"shelled", &MapOptions::shelled},
                                         {"replay_shelling", &MapOptions::replay_shelling}};

template <class T, class Parse>
bool set_field(const Fields<T>& fields, MapOptions& o, const std::string& name, py::handle value,
               Parse parse) {
  for (const auto& [keyword, field] : fields)
    if (keyword == name) {
      o.*field = parse(name.c_str(), value);
      return true;
    }
  return false;
}

// Sets the plain field `name`; false when no such keyword.
bool set_named_field(MapOptions& o, const std::string& name, py::handle value) {
  return set_field(count_fields, o, name, value, count_option) ||
         set_field(bool_fields, o, name, value, bool_option) ||
         set_field(text_fields, o, name, value, text_option);
}

// The MapOptions fields named by the keywords of `options`; an unknown keyword is a TypeError.
MapOptions map_options(const py::dict& options) {
  MapOptions o;
  for (const auto& [key, value] : options) {
    const std::string name = py::str(key);
    const char* n = name.c_str();
    if (name == "init") {
      o.init = init_option(value);
    } else if (name == "initial_target") {
      o.initial_target = option_value<std::vector<ExactPoint3>>(n, value, "exact points as text");
    } else if (name == "initial_target_doubles") {
      o.initial_target_doubles =
          points_of(option_value<DoubleArray>(n, value, "an (n, 3) array"), "initial_target");
    } else if (name == "time_limit" || name == "time_limit_seconds") {
      if (py::isinstance<py::bool_>(value) ||
          !(py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value)))
        throw InvalidOptionsError("option time_limit: expected a number of seconds, got " +
                                  py::repr(value).cast<std::string>());
      o.time_limit_seconds = value.cast<double>();
      if (!(o.time_limit_seconds >= 0))
        throw InvalidOptionsError("option time_limit: " + py::repr(value).cast<std::string>() +
                                  " is negative or NaN (0: no limit)");
    } else if (!set_named_field(o, name, value)) {
      throw py::type_error("map() got an unexpected keyword argument '" + name + "'");
    }
  }
  return o;
}

// What the run's callbacks share. The run itself holds no GIL; the callbacks take it only on
// the thread that called map (Python signal handlers run there) and only now and then: the
// progress callback (about 5 Hz) always, stop() at most every `signal_period`.
class RunHooks {
 public:
  explicit RunHooks(py::object progress) : progress_(std::move(progress)) {}

  void install(MapOptions& o) {
    o.stop = [this] { return stop(); };
    o.progress = [this](const MapProgress& p) { on_progress(p); };
  }

  // After the run, with the GIL held: raises what a callback or a signal handler raised.
  void rethrow() {
    if (error_) {
      std::unique_ptr<py::error_already_set> e = std::move(error_);
      throw py::error_already_set(std::move(*e));
    }
  }

 private:
  static constexpr auto signal_period = std::chrono::milliseconds(20);

  bool stop() {
    if (stopped_.load(std::memory_order_relaxed)) return true;
    if (std::this_thread::get_id() != caller_) return false;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_check_ < signal_period) return false;
    last_check_ = now;
    py::gil_scoped_acquire gil;
    check_signals();
    return stopped_.load(std::memory_order_relaxed);
  }

  void on_progress(const MapProgress& p) {
    if (stopped_.load(std::memory_order_relaxed) || std::this_thread::get_id() != caller_) return;
    py::gil_scoped_acquire gil;
    last_check_ = std::chrono::steady_clock::now();
    if (check_signals() || progress_.is_none()) return;
    Progress copy{std::string(p.phase), p.done,           p.total,    p.expanded,
                  p.remaining,          p.added_vertices, p.max_bits, p.seconds};
    try {
      if (py::object answer = progress_(copy); answer.ptr() == Py_True) stopped_ = true;
    } catch (py::error_already_set& e) {
      error_ = std::make_unique<py::error_already_set>(std::move(e));
      stopped_ = true;
    }
  }

  // With the GIL held: runs the pending Python signal handlers; if one raised (Ctrl-C:
  // KeyboardInterrupt), keeps its exception for rethrow() and stops the run. True when stopped.
  bool check_signals() {
    if (PyErr_CheckSignals() != 0) {
      error_ = std::make_unique<py::error_already_set>();  // fetches (and clears) the exception
      stopped_ = true;
    }
    return stopped_.load(std::memory_order_relaxed);
  }

  py::object progress_;
  const std::thread::id caller_ = std::this_thread::get_id();
  std::chrono::steady_clock::time_point last_check_ = std::chrono::steady_clock::now();
  std::atomic<bool> stopped_{false};
  std::unique_ptr<py::error_already_set> error_;
};

template <class Run>
MapResult run_map(const py::dict& options, py::object progress, Run run) {
  MapOptions o = map_options(options);
  RunHooks hooks(std::move(progress));
  hooks.install(o);
  MapResult r;
  {
    py::gil_scoped_release release;
    r = run(o);
  }
  hooks.rethrow();
  return r;
}

void bind_result_types(py::module_& m) {
  py::class_<Progress>(m, "Progress",
                       "What the progress callback of cmx.map gets, about five times a second.")
      .def_readonly("phase", &Progress::phase,
                    "'expansion', 'collapse', 'doubles', 'verification' or 'shelling search'")
      .def_readonly("done", &Progress::done, "steps done of total (phases other than the expansion)")
      .def_readonly("total", &Progress::total, "total steps (0: unknown)")
      .def_readonly("expanded", &Progress::expanded, "expansion: cluster vertices expanded")
      .def_readonly("remaining", &Progress::remaining, "expansion: cluster vertices left")
      .def_readonly("added_vertices", &Progress::added_vertices, "vertices added so far")
      .def_readonly("max_bits", &Progress::max_bits, "largest coordinate bit size so far")
      .def_readonly("seconds", &Progress::seconds, "seconds since the start")
      .def("__repr__", [](const Progress& p) {
        return "Progress(phase='" + p.phase + "', done=" + std::to_string(p.done) +
               ", total=" + std::to_string(p.total) + ", expanded=" + std::to_string(p.expanded) +
               ", remaining=" + std::to_string(p.remaining) + ", seconds=" + std::to_string(p.seconds) + ")";
      });

  py::class_<MapResult>(m, "MapResult", "cmx::MapResult (wrapped by cmx.Result)")
      .def_property_readonly("status", [](const MapResult& r) { return std::string(to_string(r.status)); })
      .def_readonly("message", &MapResult::message)
      .def_readonly("reason", &MapResult::reason)
      .def_property_readonly("ok", &MapResult::ok)
      .def_readonly("exact_valid", &MapResult::exact_valid)
      .def_readonly("double_valid", &MapResult::double_valid)
      .def_readonly("double_inverted", &MapResult::double_inverted)
      .def_readonly("double_flat", &MapResult::double_flat)
      .def_readonly("input_vertices", &MapResult::input_vertices)
      .def_readonly("report_json", &MapResult::report_json)
      .def_property_readonly("tets", [](const MapResult& r) { return array_of(r.tets); })
      .def_property_readonly("source", [](const MapResult& r) { return array_of(r.source); })
      .def_property_readonly("target", [](const MapResult& r) { return array_of(r.target); })
      .def_property_readonly("source_exact", [](const MapResult& r) { return text_rows(r.source_exact); })
      .def_property_readonly("target_exact", [](const MapResult& r) { return text_rows(r.target_exact); })
      .def_property_readonly("target_homogeneous",
                             [](const MapResult& r) { return text_rows(r.target_homogeneous); });
}

void bind_map_calls(py::module_& m) {
  m.def(
      "map_doubles",
      [](const DoubleArray& vertices, const IndexArray& tets, const IndexArray& ids,
         const DoubleArray& positions, const py::dict& options, py::object progress) {
        const std::vector<Point3d> v = points_of(vertices, "V");
        const std::vector<Tet> t = tets_of(tets, "T");
        const std::vector<std::uint32_t> b = indices_of(ids, "boundary ids");
        const std::vector<Point3d> p = points_of(positions, "boundary positions");
        return run_map(options, std::move(progress),
                       [&](const MapOptions& o) { return map_to_domain(v, t, b, p, o); });
      },
      py::arg("V"), py::arg("T"), py::arg("ids"), py::arg("positions"), py::arg("options"),
      py::arg("progress"));
  m.def(
      "map_exact",
      [](const std::vector<ExactPoint3>& v, const IndexArray& tets, const IndexArray& ids,
         const std::vector<ExactPoint3>& p, const py::dict& options, py::object progress) {
        const std::vector<Tet> t = tets_of(tets, "T");
        const std::vector<std::uint32_t> b = indices_of(ids, "boundary ids");
        return run_map(options, std::move(progress),
                       [&](const MapOptions& o) { return map_to_domain(v, t, b, p, o); });
      },
      py::arg("V"), py::arg("T"), py::arg("ids"), py::arg("positions"), py::arg("options"),
      py::arg("progress"));
}

void bind_boundary_helpers(py::module_& m) {
  m.def(
      "boundary_vertices",
      [](const IndexArray& tets, std::size_t vertex_count) {
        return array_of(boundary_vertices(tets_of(tets, "T"), vertex_count));
      },
      py::arg("T"), py::arg("vertex_count"));
  m.def(
      "boundary_for_shape",
      [](const DoubleArray& vertices, const IndexArray& tets, const std::string& shape, const std::string& corners) {
        const std::vector<Point3d> v = points_of(vertices, "V");
        const std::vector<Tet> t = tets_of(tets, "T");
        ShapeBoundary b;
        {
          py::gil_scoped_release release;
          b = boundary_for_shape(v, t, shape, corners);
        }
        return py::make_tuple(array_of(b.ids), array_of(b.positions));
      },
      py::arg("V"), py::arg("T"), py::arg("shape"), py::arg("corners") = "random");
}

}  // namespace

void bind_map(py::module_& m) {
  bind_result_types(m);
  bind_map_calls(m);
  bind_boundary_helpers(m);
}

}  // namespace cmx::python
