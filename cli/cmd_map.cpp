// cmx map: the product. A ball-topology tet mesh and prescribed star-shaped boundary positions in,
// a refined mesh whose image has no inverted or degenerate tet out, verified exactly. The files
// are read and written here; the map itself is the public call cmx::map_to_domain (cmx/map.hpp),
// on the problem as exact text, its options the canonical names of what the command line parsed.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "algorithm/map.hpp"
#include "arith/rational.hpp"
#include "cmx/map.hpp"
#include "cli/command.hpp"
#include "cli/files.hpp"
#include "cli/map_args.hpp"
#include "cli/map_input.hpp"
#include "cli/map_report.hpp"
#include "cli/mesh_input.hpp"
#include "cli/messages.hpp"
#include "cli/progress_line.hpp"
#include "cli/reference_backends/reference_backends.hpp"
#include "io/atomic_file.hpp"
#include "io/io_error.hpp"
#include "io/map_fields.hpp"
#include "io/tmap.hpp"
#include "io/write_mesh.hpp"

namespace cmx::cli::map_command {
namespace {

// Where the map goes: OUT's stem and the formats to write (tmap always).
struct OutputPlan {
  std::string stem;
  std::vector<std::string> formats;
  std::string path(const std::string& format) const { return stem + "." + format; }
};

OutputPlan output_plan(const MapArgs& a) {
  OutputPlan plan{a.out, a.formats};
  const auto dot = a.out.find_last_of('.');
  const auto slash = a.out.find_last_of('/');
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) {
    const std::string ext = a.out.substr(dot + 1);
    const auto& known = map_formats();
    if (std::find(known.begin(), known.end(), ext) != known.end()) {
      plan.stem = a.out.substr(0, dot);
      plan.formats.push_back(ext);
    }
  }
  plan.formats.push_back("tmap");
  std::sort(plan.formats.begin(), plan.formats.end());
  plan.formats.erase(std::unique(plan.formats.begin(), plan.formats.end()), plan.formats.end());
  return plan;
}

// Every file the run may write.
std::vector<std::string> output_paths(const MapArgs& a) {
  std::vector<std::string> paths;
  if (!a.out.empty()) {
    const OutputPlan plan = output_plan(a);
    for (const std::string& f : plan.formats) paths.push_back(plan.path(f));
  }
  for (const std::string* p : {&a.report, &a.trace})
    if (!p->empty()) paths.push_back(*p);
  return paths;
}

std::vector<std::string> input_paths(const MapArgs& a) {
  std::vector<std::string> paths = mesh_files(a.domain);
  if (!a.boundary.empty()) paths.push_back(a.boundary);
  if (!a.init_file.empty()) paths.push_back(a.init_file);
  for (const std::string& p : a.codomain.empty() ? std::vector<std::string>{} : mesh_files(a.codomain)) paths.push_back(p);
  return paths;
}

// Before any work: no output over an input (exit 2), every output writable (9).
void check_outputs(const MapArgs& a) {
  const std::vector<std::string> outputs = output_paths(a);
  check_outputs_apart(outputs, input_paths(a));
  check_writable(outputs);
}

// The exact points of the public result's text, read back (canonical "p/q": exact round trip).
std::vector<cmx::Point3> exact(const std::vector<ExactPoint3>& points) {
  std::vector<cmx::Point3> out;
  out.reserve(points.size());
  for (const ExactPoint3& p : points) {
    cmx::Point3 q;
    for (std::size_t k = 0; k < 3; ++k) {
      const auto value = parse_rational(p[k]);
      if (!value) throw std::logic_error("cmx map: the library returned '" + p[k] + "', not a rational");
      q[k] = *value;
    }
    out.push_back(std::move(q));
  }
  return out;
}

// One output file of the map; `doubles` are the target positions chosen by --snap, `fields` what
// display formats carry besides (io/map_fields.hpp: source positions, added, volumes, angles).
void write_map_file(const std::string& format, const std::string& path, const io::TetMap& m,
                    const std::vector<std::array<double, 3>>& doubles, const io::DisplayFields& fields) {
  if (format == "tmap") {
    io::write_tmap(path, m);
  } else if (format == "ovm") {
    io::write_ovm(path, doubles, m.tets, &m.target);
  } else {
    io::write_display_mesh(path, doubles, m.tets, io::carries_display_fields(path) ? fields : io::DisplayFields{});
  }
}

void write_outputs(const MapArgs& a, const cmx::MapResult& r) {
  if (a.out.empty()) return;
  const OutputPlan plan = output_plan(a);
  const io::TetMap m{exact(r.source_exact), exact(r.target_exact), r.tets};
  const bool display = std::any_of(plan.formats.begin(), plan.formats.end(),
                                   [](const std::string& f) { return f != "tmap" && f != "ovm"; });
  const io::DisplayFields fields =
      display ? io::map_display_fields(r.source, r.target, m.tets, r.input_vertices)  // r.source: nearest doubles
              : io::DisplayFields{};
  for (const std::string& f : plan.formats) write_map_file(f, plan.path(f), m, r.target, fields);
}

constexpr const char* trace_header =
    "step,kind,vertex,cone_rows,lp,bits,max_bits,mean_bits,added_vertices,degenerate_left,cluster_left,seconds,star\n";

std::string trace_line(const MapTraceRow& r) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "%zu,%.*s,%u,%zu,%.*s,%zu,%zu,%.2f,%zu,%zu,%zu,%.4f,%zu\n", r.step, int(r.kind.size()),
                r.kind.data(), r.vertex, r.cone_rows, int(r.lp.size()), r.lp.data(), r.bits, r.max_bits, r.mean_bits, r.added_vertices, r.degenerate_left, r.cluster_left,
                r.seconds, r.star);
  return buf;
}

// A report or trace of a failed run replaces an existing file only with --report-on-failure: an
// earlier result is worth more than the record of a failure.
bool may_write(const MapArgs& a, const std::string& path, bool failed) {
  if (path.empty()) return false;
  std::error_code ec;
  if (!failed || a.report_on_failure || !std::filesystem::exists(path, ec)) return true;
  message("not replacing '" + path + "' with the record of a failed run (--report-on-failure would)");
  return false;
}

void write_report(const MapArgs& a, const JsonObject& j, bool failed) {
  if (may_write(a, a.report, failed))
    io::write_file_atomically(a.report, [&](std::ostream& os) { os << j.text() << '\n'; });
}

void write_trace(const MapArgs& a, const std::string& rows, bool failed) {
  if (may_write(a, a.trace, failed))
    io::write_file_atomically(a.trace, [&](std::ostream& os) { os << trace_header << rows; });
}

int exit_code_of(MapStatus status) {
  switch (status) {
    case MapStatus::success: return exit_ok;
    case MapStatus::time_limit: return exit_time_limit;
    case MapStatus::precision_lost: return exit_precision_lost;
    default: break;
  }
  return exit_stuck;
}

// The failure of a run that ended without a result (MapResult::reason: a MapErrorKind's name).
std::optional<algorithm::MapErrorKind> error_kind(const std::string& reason) {
  using K = algorithm::MapErrorKind;
  for (const K k : {K::invalid_input, K::not_ball, K::boundary_mismatch, K::source_not_positive, K::degenerate_boundary,
                    K::boundary_orientation, K::not_star_shaped, K::time_limit, K::stuck, K::internal})
    if (reason == algorithm::kind_name(k)) return k;
  return std::nullopt;
}

int exit_code_of(algorithm::MapErrorKind kind) {
  using K = algorithm::MapErrorKind;
  switch (kind) {
    case K::not_star_shaped: return exit_not_star_shaped;
    case K::time_limit: return exit_time_limit;
    case K::stuck: return exit_stuck;
    case K::internal: return exit_internal;
    default: return exit_invalid_problem;
  }
}

// The message of a map error, led by the file at fault.
std::string culprit_message(const MapArgs& a, algorithm::MapErrorKind kind, const std::string& what) {
  using K = algorithm::MapErrorKind;
  const std::string positions = !a.boundary.empty() ? a.boundary : a.codomain;
  switch (kind) {
    case K::not_ball: return a.domain + " is not a ball: " + what;
    case K::source_not_positive: return a.domain + ": " + what;
    case K::boundary_mismatch: return positions.empty() ? what : positions + ": " + what;
    default: return what;
  }
}

std::string culprit_message(const MapArgs& a, const algorithm::MapError& e) {
  return culprit_message(a, e.kind(), e.what());
}

// Reports a run that ends without a map; `fields` are empty when no result exists. The report
// carries `detail` (the message without the status that it states apart).
int fail(const MapArgs& a, int code, const std::string& status, const std::string& text,
         const std::vector<ReportField>& fields, const std::string& detail) {
  message(text);
  write_report(a, report_json(a, fields, status, detail), true);
  return code;
}

// exit_ok with the problem read, or the exit code of a failure it has reported.
int load_problem(const MapArgs& a, algorithm::MapProblem& problem) {
  try {
    for (const std::string& p : input_paths(a)) check_readable(p);
    problem = load_map_problem(a.domain, a.boundary, a.codomain, a.shape, a.seed, a.options.combinatorial,
                               a.corners, unsigned(a.options.threads));
    if (a.options.init == algorithm::InitialMapKind::given) load_initial_map(problem, a.init_file, a.codomain);
    return exit_ok;
  } catch (const io::IoError& e) {
    const bool mismatch = e.kind() == io::ErrorKind::mismatch;  // two inputs that do not fit together
    const int code = mismatch ? exit_invalid_problem : mesh_error_code(e, a.domain);
    const char* status = mismatch ? "boundary_mismatch" : code == exit_invalid_problem ? "source_not_positive" : "bad_input";
    return fail(a, code, status, e.what(), {}, e.what());
  } catch (const algorithm::MapError& e) {
    const std::string text = culprit_message(a, e);
    return fail(a, exit_code_of(e.kind()), algorithm::kind_name(e.kind()), text, {}, text);
  } catch (const Failure& e) {  // an input that cannot be opened
    return fail(a, e.code(), "bad_input", e.what(), {}, e.what());
  }
}

void print_verdict(const MapArgs& a, const cmx::MapResult& r) {
  const MapStatistics& s = r.statistics;
  const std::string arith = to_string(a.options.placement.arith);
  if (a.options.combinatorial)
    std::printf("map: success, a realisation verified exactly (every tet positive in the target, boundary as "
                "prescribed, a subdivision of the input complex; no source geometry to check)%s\n",
                a.options.placement.arith.exact() ? "" : (", coordinates in " + arith).c_str());
  else
    std::printf("map: success, verified exactly (every tet positive in source and target, boundary as prescribed)%s\n",
                a.options.placement.arith.exact() ? "" : (", coordinates in " + arith).c_str());
  if (s.rounded_coordinates)
    std::printf("  input read in %s: %zu coordinates rounded; the map is verified for the rounded input\n", arith.c_str(),
                s.rounded_coordinates);
  std::printf("  %zu vertices / %zu tets in, %zu / %zu out (growth %.4f), %zu splits in preprocessing\n", s.input_vertices,
              s.input_tets, s.output_vertices, s.output_tets, s.growth_ratio, s.preprocess_splits);
  std::printf("  expansions: %zu simple, %zu in %zu subclusters, %zu star-shapified (%zu pushes), %zu inflated, "
              "%zu automatic\n",
              s.expansions_simple, s.expansions_subcluster, s.subclusters_expanded, s.expansions_star_shapified, s.pushes,
              s.expansions_inflated, s.expansions_automatic);
  if (s.double_checked)
    std::printf("  largest coordinate: %zu bits; doubles (--snap %s) %s (%zu inverted, %zu degenerate)\n", s.max_bits,
                std::string(algorithm::to_string(snap_used(a))).c_str(), r.double_valid ? "valid" : "NOT valid",
                r.double_inverted, r.double_flat);
  else
    std::printf("  largest coordinate: %zu bits; doubles not checked (--snap none)\n", s.max_bits);
  if (s.double_repair_stopped)
    std::printf("  the double repair stopped at the time limit; the exact map is complete and verified\n");
  std::printf("  %.3f s\n", s.seconds_total);
}

// The problem as the public call takes it: exact text (canonical, so read back exactly).
struct ExactProblem {
  std::vector<ExactPoint3> source, boundary_positions;
  std::vector<Tet> tets;
};

std::vector<ExactPoint3> exact_text(const std::vector<cmx::Point3>& points) {
  std::vector<ExactPoint3> out;
  out.reserve(points.size());
  for (const cmx::Point3& p : points) out.push_back({to_string(p[0]), to_string(p[1]), to_string(p[2])});
  return out;
}

ExactProblem exact_problem(const algorithm::MapProblem& p) {
  ExactProblem out{exact_text(p.source), exact_text(p.boundary_positions), {}};
  out.tets.reserve(p.tets.size());
  for (const topology::Tet& t : p.tets) out.tets.push_back(topology::indices_of(t));
  return out;
}

InitialMap public_init(algorithm::InitialMapKind k) {
  switch (k) {
    case algorithm::InitialMapKind::shrink: return InitialMap::shrink;
    case algorithm::InitialMapKind::tutte: return InitialMap::tutte;
    case algorithm::InitialMapKind::given: return InitialMap::given;
    case algorithm::InitialMapKind::automatic: break;
  }
  return InitialMap::automatic;
}

// The parsed command line as public options: every value by its canonical name, which
// map_to_domain parses back to the same choice.
cmx::MapOptions public_options(const MapArgs& a, const algorithm::MapProblem& problem) {
  const algorithm::MapOptions& in = a.options;
  cmx::MapOptions o;
  o.init = public_init(in.init);
  if (in.init == algorithm::InitialMapKind::given) o.initial_target = exact_text(problem.initial_target);
  o.time_limit_seconds = in.time_limit_seconds;
  o.threads = in.threads;
  o.combinatorial = in.combinatorial;
  o.collapse = in.collapse;
  o.merge = in.merge;
  o.flip_collapse = in.flip_collapse;
  o.collapse_refinement = in.collapse_refinement;
  o.shelled = std::string(algorithm::to_string(in.shelled));
  o.replay_shelling = std::string(algorithm::to_string(in.replay));
  o.check = in.check;
  o.snap = std::string(algorithm::to_string(in.snap));
  o.order = topology::to_string(in.order);
  o.filter = to_string(in.filter);
  o.lp = in.placement.lp.backend;
  o.norm = std::string(lp::to_string(in.placement.lp.norm));
  o.precision = std::string(algorithm::to_string(in.placement.precision));
  o.arith = to_string(in.placement.arith);
  o.subclusters = in.subclusters;
  o.smooth = in.smooth_every;
  return o;
}

// A run that ended without a result: the status is the failure's name, exit code as before.
int fail_without_result(const MapArgs& a, const cmx::MapResult& r) {
  const auto kind = error_kind(r.reason);
  const std::string text = kind ? culprit_message(a, *kind, r.message) : r.message;
  const int code = kind ? exit_code_of(*kind) : r.status == MapStatus::invalid_options ? exit_usage : exit_internal;
  return fail(a, code, r.reason, text, {}, text);
}

int map_and_write(const MapArgs& a, const algorithm::MapProblem& problem) {
  cmx::MapOptions options = public_options(a, problem);
  const bool show_progress = !quiet() && isatty(2);
  if (show_progress)
    options.progress = [](const MapProgress& p) {
      std::fputs(progress_line(p).c_str(), stderr);
      std::fflush(stderr);
    };
  std::string trace_rows;
  if (!a.trace.empty()) options.trace = [&](const MapTraceRow& row) { trace_rows += trace_line(row); };
  const ExactProblem in = exact_problem(problem);
  cmx::MapResult r;
  try {
    r = cmx::map_to_domain(in.source, in.tets, problem.boundary_vertices, in.boundary_positions, options);
  } catch (const std::logic_error& e) {  // cmx's own bug
    if (show_progress) std::fputc('\n', stderr);
    return fail(a, exit_internal, algorithm::kind_name(algorithm::MapErrorKind::internal), e.what(), {}, e.what());
  }
  if (show_progress) std::fputc('\n', stderr);
  if (r.report_fields.empty()) return fail_without_result(a, r);
  const bool failed = !r.ok();
  write_trace(a, trace_rows, failed);
  if (failed)
    return fail(a, exit_code_of(r.status), to_string(r.status), std::string(to_string(r.status)) + ": " + r.message,
                r.report_fields, r.message);
  write_outputs(a, r);
  write_report(a, report_json(a, r.report_fields, "success", ""), false);
  if (!quiet()) print_verdict(a, r);
  return exit_ok;
}

int run(const std::vector<std::string>& args) {
  register_reference_backends();
  MapArgs a;
  if (const auto done = parse_map_args(args, a)) return *done;
  check_outputs(a);  // before minutes of computing
  algorithm::MapProblem problem;
  if (const int code = load_problem(a, problem); code != exit_ok) return code;
  return map_and_write(a, problem);
}

const bool registered = register_command({"map", "map a ball-topology tet mesh onto a star-shaped domain (exact)", run});

}  // namespace
}  // namespace cmx::cli::map_command
