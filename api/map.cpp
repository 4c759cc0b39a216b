// cmx::map_to_domain on plain arrays (include/cmx/map.hpp): converts to the layers' MapProblem and
// MapOptions, runs algorithm::map_to_domain and converts its result back. Every way a run can end
// becomes a MapStatus with a message; only cmx's own bugs (MapErrorKind::internal) throw.
#include "cmx/map.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <variant>

#include "generators/boundary_shapes.hpp"
#include "algorithm/map.hpp"
#include "api/map_report.hpp"
#include "arith/rational.hpp"
#include "arith/rounding.hpp"
#include "kernel/coordinate_arith.hpp"
#include "kernel/filter_policy.hpp"
#include "lp/backend_registry.hpp"
#include "lp/row_weights.hpp"
#include "topology/ball_check.hpp"
#include "topology/complex_queries.hpp"

namespace cmx {
namespace {

// The status and message of a run that did not produce a map.
struct Failure {
  MapStatus status;
  std::string message;
  std::string reason = {};  // invalid_input: the MapErrorKind's name; else to_string(status)
};

MapResult failed(const Failure& f) {
  MapResult r;
  r.status = f.status;
  r.message = f.message;
  r.reason = f.reason.empty() ? to_string(f.status) : f.reason;
  return r;
}

std::optional<algorithm::InitialMapKind> initial_map_kind(InitialMap init) {
  switch (init) {
    case InitialMap::automatic:
      return algorithm::InitialMapKind::automatic;
    case InitialMap::shrink:
      return algorithm::InitialMapKind::shrink;
    case InitialMap::tutte:
      return algorithm::InitialMapKind::tutte;
    case InitialMap::given:
      return algorithm::InitialMapKind::given;
  }
  return std::nullopt;
}

// Parses the text-valued options as `cmx map` does; the first that does not parse is the failure.
std::optional<Failure> parse_options(const MapOptions& in, algorithm::MapOptions& out) {
  const auto bad = [](const std::string& field, const std::string& value, const std::string& why) {
    return Failure{MapStatus::invalid_options, "option " + field + ": '" + value + "' " + why};
  };
  std::string why;
  const auto filter = parse_filter_policy(in.filter, &why);
  if (!filter || filter->kind == FilterPolicy::Kind::naive)
    return bad("filter", in.filter, filter ? "is not exact (naive is for benchmarks only)" : why);
  const auto order = topology::parse_expansion_order(in.order);
  if (!order)
    return bad("order", in.order,
               "is not an expansion order (" + std::string(topology::expansion_order_syntax) + ")");
  // A combinatorial run always starts shrunk (algorithm::MapOptions::combinatorial).
  if (order->defer_first < order->defer_end && in.init != InitialMap::shrink && !in.combinatorial)
    return bad("order", in.order,
               "defers input vertex ids, which only --init shrink (or --combinatorial) keeps (the local "
               "repair's stars renumber them)");
  const auto shelled = algorithm::parse_shelled_mode(in.shelled);
  if (!shelled) return bad("shelled", in.shelled, "is not a shelled star-shapification mode (when-stuck, after-pushes, first)");
  const auto replay = algorithm::parse_replay_mode(in.replay_shelling);
  if (!replay)
    return bad("replay_shelling", in.replay_shelling,
               "is not a replay mode (off, after-nobuenoss, until-greedy, full)");
  const auto snap = algorithm::parse_snap_policy(in.snap);
  if (!snap) return bad("snap", in.snap, "is not a snap policy (repair, chebyshev, nearest, none)");
  const auto precision = algorithm::parse_precision_policy(in.precision);
  if (!precision)
    return bad("precision", in.precision, "is not a precision policy (cmx map --help lists them)");
  const auto norm = lp::parse_norm(in.norm);
  if (!norm) return bad("norm", in.norm, "is not a row-weight norm (l2-upper, l1)");
  const auto arith = parse_coordinate_arith(in.arith, &why);
  if (!arith) return bad("arith", in.arith, why);
  if (!lp::find_backend(in.lp)) return bad("lp", in.lp, "is not a built LP backend (certified, exact)");
  if (!(in.time_limit_seconds >= 0))
    return bad("time_limit_seconds", std::to_string(in.time_limit_seconds), "is negative or NaN");
  if (in.subclusters > 4) return bad("subclusters", std::to_string(in.subclusters), "is above 4");
  if (in.threads > 1024) return bad("threads", std::to_string(in.threads), "is above 1024");
  const auto init = initial_map_kind(in.init);
  if (!init) return bad("init", std::to_string(int(in.init)), "is not an InitialMap value");
  out.filter = *filter;
  out.order = *order;
  out.snap = *snap;
  out.placement.precision = *precision;
  out.placement.lp.norm = *norm;
  out.placement.lp.backend = in.lp;
  out.placement.arith = *arith;
  out.time_limit_seconds = std::isinf(in.time_limit_seconds) ? 0 : in.time_limit_seconds;
  out.subclusters = in.subclusters;
  out.smooth_every = in.smooth;
  out.threads = in.threads;
  out.collapse = in.collapse;
  out.merge = in.merge;
  out.flip_collapse = in.flip_collapse;
  out.collapse_refinement = in.collapse_refinement;
  out.shelled = *shelled;
  out.replay = *replay;
  out.check = in.check;
  out.init = *init;
  out.combinatorial = in.combinatorial;
  return std::nullopt;
}

std::string axis_name(std::size_t axis) {
  return std::string(1, char('x' + axis));
}

// One exact point from doubles; a non-finite coordinate is the failure, naming `what`.
std::optional<Failure> exact_point(const Point3d& p, const std::string& what, cmx::Point3& out) {
  for (std::size_t k = 0; k < 3; ++k) {
    if (!std::isfinite(p[k]))
      return Failure{MapStatus::invalid_input, what + ": coordinate " + axis_name(k) + " is " +
                                                   (std::isnan(p[k]) ? "NaN" : "infinite")};
    out[k] = rational_from_double(p[k]);
  }
  return std::nullopt;
}

// One exact point from text; text that is not an exact number is the failure, naming `what`.
std::optional<Failure> exact_point(const ExactPoint3& p, const std::string& what, cmx::Point3& out) {
  for (std::size_t k = 0; k < 3; ++k) {
    std::string why;
    const auto q = parse_rational(p[k], &why);
    if (!q)
      return Failure{MapStatus::invalid_input, what + ": coordinate " + axis_name(k) + " '" + p[k] +
                                                   "' is not an exact number" +
                                                   (why.empty() ? "" : " (" + why + ")")};
    out[k] = *q;
  }
  return std::nullopt;
}

// `name(i)` names the i-th point in a message.
template <class P, class Name>
std::optional<Failure> exact_points(std::span<const P> points, Name name,
                                    std::vector<cmx::Point3>& out) {
  out.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    if (auto f = exact_point(points[i], name(i), out[i])) return f;
  return std::nullopt;
}

std::string vertex_name(std::size_t i) {
  return "vertex " + std::to_string(i);
}

// The initial map of InitialMap::given: exact text if any, else the doubles.
std::optional<Failure> initial_target(const MapOptions& o, std::size_t vertex_count,
                                      algorithm::MapProblem& p) {
  if (o.init != InitialMap::given) return std::nullopt;
  const std::size_t n = o.initial_target.empty() ? o.initial_target_doubles.size() : o.initial_target.size();
  if (n != vertex_count)
    return Failure{MapStatus::invalid_input, "initial target: " + std::to_string(n) + " positions for " +
                                                 std::to_string(vertex_count) +
                                                 " vertices (init = given needs one per vertex)"};
  const auto name = [](std::size_t i) { return "initial target of " + vertex_name(i); };
  if (!o.initial_target.empty())
    return exact_points(std::span<const ExactPoint3>(o.initial_target), name, p.initial_target);
  return exact_points(std::span<const Point3d>(o.initial_target_doubles), name, p.initial_target);
}

template <class P>
std::variant<algorithm::MapProblem, Failure> make_problem(std::span<const P> vertices,
                                                          std::span<const Tet> tets,
                                                          std::span<const std::uint32_t> ids,
                                                          std::span<const P> positions, const MapOptions& o) {
  if (ids.size() != positions.size())
    return Failure{MapStatus::invalid_input, std::to_string(ids.size()) + " boundary ids but " +
                                                 std::to_string(positions.size()) + " boundary positions"};
  algorithm::MapProblem p;
  if (auto f = exact_points(vertices, vertex_name, p.source)) return *f;
  const auto position_name = [&](std::size_t i) { return "boundary position of " + vertex_name(ids[i]); };
  if (auto f = exact_points(positions, position_name, p.boundary_positions)) return *f;
  p.tets.reserve(tets.size());
  for (const Tet& t : tets) p.tets.push_back(topology::make_tet(t));
  p.boundary_vertices.assign(ids.begin(), ids.end());
  if (auto f = initial_target(o, vertices.size(), p)) return *f;
  return p;
}

MapStatus status_of(algorithm::MapOutcome o, bool cancelled) {
  switch (o) {
    case algorithm::MapOutcome::success:
      return MapStatus::success;
    case algorithm::MapOutcome::time_limit:
      return cancelled ? MapStatus::cancelled : MapStatus::time_limit;
    case algorithm::MapOutcome::stuck:
      return MapStatus::stuck;
    case algorithm::MapOutcome::precision_lost:
      return MapStatus::precision_lost;
  }
  return MapStatus::stuck;
}

ExactPoint3 exact_text(const HPoint& p) {
  return {to_string(p.coordinate(0)), to_string(p.coordinate(1)), to_string(p.coordinate(2))};
}

// The output arrays and verdicts of a successful run.
void fill_output(const algorithm::MapResult& in, MapResult& out) {
  out.tets.reserve(in.tets.size());
  for (const auto& t : in.tets) out.tets.push_back(topology::indices_of(t));
  const std::size_t n = in.target.size();
  out.source_exact.reserve(n);
  out.target_exact.reserve(n);
  out.target_homogeneous.reserve(n);
  out.source.reserve(n);
  // A combinatorial run has no source geometry: its source is the realisation itself.
  const std::vector<HPoint>& source = in.stats.combinatorial ? in.target : in.source;
  for (std::size_t v = 0; v < n; ++v) {
    out.source_exact.push_back(exact_text(source[v]));
    out.target_exact.push_back(exact_text(in.target[v]));
    const HPoint& t = in.target[v];
    out.target_homogeneous.push_back(
        {to_string(t.X()), to_string(t.Y()), to_string(t.Z()), to_string(t.W())});
    out.source.push_back(
        {to_double(source[v].coordinate(0)), to_double(source[v].coordinate(1)), to_double(source[v].coordinate(2))});
  }
  out.target = in.doubles.target;
  out.exact_valid = in.verification.ok();
  out.double_valid = in.doubles.checked && in.doubles.check.valid();
  out.double_inverted = in.doubles.check.inverted;
  out.double_flat = in.doubles.check.degenerate;
}

std::string report_of(const MapResult& r) {
  api::JsonObject j;
  j.str("status", to_string(r.status)).str("reason", r.reason).str("message", r.message);
  api::add_result_fields(j, r.report_fields);
  return j.text();
}

MapStatistics statistics_of(const algorithm::MapResult& run) {
  const algorithm::MapStatistics& s = run.stats;
  MapStatistics m;
  m.input_vertices = s.input_vertices;
  m.input_tets = s.input_tets;
  m.output_vertices = s.output_vertices;
  m.output_tets = s.output_tets;
  m.growth_ratio = s.growth_ratio;
  m.rounded_coordinates = s.input_rounded;
  m.preprocess_splits = s.split_topology + s.split_all_boundary_tet + s.split_no_shrink_point + s.split_fallback;
  m.expansions_simple = s.expansions_simple;
  m.expansions_subcluster = s.expansions_subcluster;
  m.subclusters_expanded = s.subcluster_expansions;
  m.expansions_star_shapified = s.expansions_star_shapified;
  m.pushes = s.pushes;
  m.expansions_inflated = s.expansions_inflated;
  m.expansions_automatic = s.expansions_automatic;
  m.max_bits = s.max_bits;
  m.double_checked = run.doubles.checked;
  m.double_repair_stopped = run.doubles.stopped_at_deadline;
  m.seconds_total = s.seconds_total;
  return m;
}

MapTraceRow trace_row(const algorithm::TraceRow& t) {
  return MapTraceRow{t.step, t.kind ? t.kind : "", t.vertex, t.cone_rows, t.lp ? t.lp : "", t.bits, t.max_bits,
                     t.mean_bits, t.added_vertices, t.degenerate_left, t.cluster_left, t.seconds, t.star};
}

MapStatus status_of(algorithm::MapErrorKind kind) {
  switch (kind) {
    case algorithm::MapErrorKind::time_limit:
      return MapStatus::time_limit;
    case algorithm::MapErrorKind::stuck:
      return MapStatus::stuck;
    default:
      return MapStatus::invalid_input;
  }
}

MapResult run(const algorithm::MapProblem& problem, const MapOptions& options,
              algorithm::MapOptions internal) {
  bool cancelled = false;
  if (options.stop) internal.stop = [&](std::string_view) { return cancelled = cancelled || options.stop(); };
  if (options.progress)
    internal.progress = [&](const algorithm::MapProgress& p) {
      options.progress(
          MapProgress{p.phase ? p.phase : "", p.done, p.total, p.expanded, p.remaining, p.splits, p.max_bits, p.seconds});
    };
  if (options.trace) internal.trace = [&](const algorithm::TraceRow& t) { options.trace(trace_row(t)); };
  algorithm::MapResult run;
  try {
    run = algorithm::map_to_domain(problem, internal);
  } catch (const algorithm::MapError& e) {
    if (e.kind() == algorithm::MapErrorKind::internal) throw std::logic_error(e.what());
    const MapStatus status = cancelled ? MapStatus::cancelled : status_of(e.kind());
    MapResult r =
        failed({status, e.what(), status == MapStatus::invalid_input ? algorithm::kind_name(e.kind()) : ""});
    r.report_json = report_of(r);
    return r;
  }
  MapResult r;
  r.status = status_of(run.outcome, cancelled);
  r.message = run.outcome == algorithm::MapOutcome::success ? "" : run.message;
  r.reason = r.ok() ? "" : to_string(r.status);
  r.input_vertices = run.stats.input_vertices;
  if (r.ok()) fill_output(run, r);
  r.report_fields = api::result_fields(run);
  r.statistics = statistics_of(run);
  r.report_json = report_of(r);
  return r;
}

template <class P>
MapResult map_points(std::span<const P> vertices, std::span<const Tet> tets,
                     std::span<const std::uint32_t> ids, std::span<const P> positions,
                     const MapOptions& options) {
  algorithm::MapOptions internal;
  if (auto f = parse_options(options, internal)) return failed(*f);
  auto problem = make_problem(vertices, tets, ids, positions, options);
  if (auto* f = std::get_if<Failure>(&problem)) return failed(*f);
  return run(std::get<algorithm::MapProblem>(problem), options, std::move(internal));
}

}  // namespace

const char* to_string(MapStatus status) {
  switch (status) {
    case MapStatus::success:
      return "success";
    case MapStatus::invalid_input:
      return "invalid_input";
    case MapStatus::invalid_options:
      return "invalid_options";
    case MapStatus::time_limit:
      return "time_limit";
    case MapStatus::cancelled:
      return "cancelled";
    case MapStatus::stuck:
      return "stuck";
    case MapStatus::precision_lost:
      return "precision_lost";
  }
  return "unknown";
}

MapResult map_to_domain(std::span<const Point3d> vertices, std::span<const Tet> tets,
                        std::span<const std::uint32_t> boundary_ids,
                        std::span<const Point3d> boundary_positions, const MapOptions& options) {
  return map_points(vertices, tets, boundary_ids, boundary_positions, options);
}

MapResult map_to_domain(std::span<const ExactPoint3> vertices, std::span<const Tet> tets,
                        std::span<const std::uint32_t> boundary_ids,
                        std::span<const ExactPoint3> boundary_positions, const MapOptions& options) {
  return map_points(vertices, tets, boundary_ids, boundary_positions, options);
}

MapResult map_to_domain(const double* vertices, std::size_t vertex_count, const std::uint32_t* tets,
                        std::size_t tet_count, const std::uint32_t* boundary_ids,
                        const double* boundary_positions, std::size_t boundary_count,
                        const MapOptions& options) {
  // Point3d and Tet are arrays of their element type: no padding, so the raw buffers are spans.
  static_assert(sizeof(Point3d) == 3 * sizeof(double) && sizeof(Tet) == 4 * sizeof(std::uint32_t));
  const auto points = [](const double* p, std::size_t n) {
    return std::span<const Point3d>(reinterpret_cast<const Point3d*>(p), n);
  };
  return map_to_domain(points(vertices, vertex_count),
                       std::span<const Tet>(reinterpret_cast<const Tet*>(tets), tet_count),
                       std::span<const std::uint32_t>(boundary_ids, boundary_count),
                       points(boundary_positions, boundary_count), options);
}

std::vector<std::uint32_t> boundary_vertices(std::span<const Tet> tets, std::size_t vertex_count) {
  std::vector<topology::Tet> ts;
  ts.reserve(tets.size());
  for (std::size_t i = 0; i < tets.size(); ++i) {
    for (const std::uint32_t v : tets[i])
      if (v >= vertex_count)
        throw Error("tet " + std::to_string(i) + ": vertex " + std::to_string(v) + " out of range (" +
                    std::to_string(vertex_count) + " vertices)");
    ts.push_back(topology::make_tet(tets[i]));
  }
  const topology::TetMesh mesh(vertex_count, ts);
  std::vector<std::uint32_t> out;
  const std::vector<char> flags = topology::boundary_vertex_flags(mesh);
  for (std::uint32_t v = 0; v < flags.size(); ++v)
    if (flags[v]) out.push_back(v);
  return out;
}

ShapeBoundary boundary_for_shape(std::span<const Point3d> vertices, std::span<const Tet> tets,
                                 std::string_view shape, std::string_view corners) {
  auto spec = generators::parse_boundary_shape(shape);
  if (!spec) throw Error("unknown shape '" + std::string(shape) + "' (cmx map --help lists the shapes)");
  const auto choice = generators::parse_corner_choice(corners);
  if (!choice) throw Error("unknown corner choice '" + std::string(corners) + "' (random or farthest)");
  spec->corners = *choice;
  std::vector<topology::Tet> ts;
  ts.reserve(tets.size());
  for (const Tet& t : tets) {
    for (const std::uint32_t v : t)
      if (v >= vertices.size()) throw Error("tet names vertex " + std::to_string(v) + ", out of range");
    ts.push_back(topology::make_tet(t));
  }
  const topology::TetMesh mesh(vertices.size(), ts);
  if (const auto ball = topology::check_ball(mesh); !ball.ok) throw Error("not a ball: " + ball.message);
  const generators::GeneratedBoundary g = generators::generate_boundary(
      mesh, std::vector<std::array<double, 3>>(vertices.begin(), vertices.end()), *spec);
  if (!g.ok) throw Error("no valid '" + std::string(shape) + "' boundary: " + g.message);
  return ShapeBoundary{g.vertices, g.positions};
}

}  // namespace cmx
