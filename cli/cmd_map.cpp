// cmx map: the product. A ball-topology tet mesh and prescribed star-shaped boundary positions in,
// a refined mesh whose image has no inverted or degenerate tet out, verified exactly.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "algorithm/map.hpp"
#include "cli/command.hpp"
#include "cli/common_options.hpp"
#include "cli/files.hpp"
#include "cli/map_args.hpp"
#include "cli/map_input.hpp"
#include "cli/map_report.hpp"
#include "cli/mesh_input.hpp"
#include "cli/messages.hpp"
#include "cli/progress_line.hpp"
#include "io/atomic_file.hpp"
#include "io/io_error.hpp"
#include "io/map_fields.hpp"
#include "io/tmap.hpp"
#include "io/write_mesh.hpp"

namespace cmx::cli {
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

std::vector<io::Point3> exact(const std::vector<HPoint>& points) {
  std::vector<io::Point3> out;
  out.reserve(points.size());
  for (const HPoint& p : points) out.push_back({p.coordinate(0), p.coordinate(1), p.coordinate(2)});
  return out;
}

// One output file of the map; `doubles` are the target positions chosen by --snap, `fields` what
// display formats carry besides (io/map_fields.hpp: source positions, added, volumes, angles).
void write_map_file(const std::string& format, const std::string& path, const algorithm::MapResult& r,
                    const std::vector<std::array<double, 3>>& doubles, const io::DisplayFields& fields) {
  if (format == "tmap") {
    io::write_tmap(path, io::TetMap{exact(r.source), exact(r.target), r.tets});
  } else if (format == "ovm") {
    const std::vector<io::Point3> ex = exact(r.target);
    io::write_ovm(path, doubles, r.tets, &ex);
  } else {
    io::write_display_mesh(path, doubles, r.tets, io::carries_display_fields(path) ? fields : io::DisplayFields{});
  }
}

void write_outputs(const MapArgs& a, const algorithm::MapResult& r) {
  if (a.out.empty()) return;
  const OutputPlan plan = output_plan(a);
  const bool display = std::any_of(plan.formats.begin(), plan.formats.end(),
                                   [](const std::string& f) { return f != "tmap" && f != "ovm"; });
  const io::DisplayFields fields =
      display ? io::map_display_fields(io::nearest_doubles(exact(r.source)), r.doubles.target, r.tets, r.stats.input_vertices)
              : io::DisplayFields{};
  for (const std::string& f : plan.formats) write_map_file(f, plan.path(f), r, r.doubles.target, fields);
}

constexpr const char* trace_header =
    "step,kind,vertex,cone_rows,lp,bits,max_bits,mean_bits,added_vertices,degenerate_left,cluster_left,seconds,star\n";

std::string trace_line(const algorithm::TraceRow& r) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "%zu,%s,%u,%zu,%s,%zu,%zu,%.2f,%zu,%zu,%zu,%.4f,%zu\n", r.step, r.kind, r.vertex,
                r.cone_rows, r.lp, r.bits, r.max_bits, r.mean_bits, r.added_vertices, r.degenerate_left, r.cluster_left,
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

int exit_code_of(algorithm::MapOutcome outcome) {
  switch (outcome) {
    case algorithm::MapOutcome::success: return exit_ok;
    case algorithm::MapOutcome::time_limit: return exit_time_limit;
    case algorithm::MapOutcome::precision_lost: return exit_precision_lost;
    case algorithm::MapOutcome::stuck: break;
  }
  return exit_stuck;
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
std::string culprit_message(const MapArgs& a, const algorithm::MapError& e) {
  using K = algorithm::MapErrorKind;
  const std::string positions = !a.boundary.empty() ? a.boundary : a.codomain;
  switch (e.kind()) {
    case K::not_ball: return a.domain + " is not a ball: " + e.what();
    case K::source_not_positive: return a.domain + ": " + e.what();
    case K::boundary_mismatch: return positions.empty() ? e.what() : positions + ": " + e.what();
    default: return e.what();
  }
}

// Reports a run that ends without a map; `r` is null when no result exists. The report carries
// `detail` (the message without the status that it states apart).
int fail(const MapArgs& a, int code, const std::string& status, const std::string& text, const algorithm::MapResult* r,
         const std::string& detail) {
  message(text);
  write_report(a, report_json(a, r, status, detail), true);
  return code;
}

// exit_ok with the problem read, or the exit code of a failure it has reported.
int load_problem(const MapArgs& a, algorithm::MapProblem& problem) {
  try {
    for (const std::string& p : input_paths(a)) check_readable(p);
    problem = load_map_problem(a.domain, a.boundary, a.codomain, a.shape, a.seed);
    if (a.options.init == algorithm::InitialMapKind::given) load_initial_map(problem, a.init_file, a.codomain);
    return exit_ok;
  } catch (const io::IoError& e) {
    const bool mismatch = e.kind() == io::ErrorKind::mismatch;  // two inputs that do not fit together
    const int code = mismatch ? exit_invalid_problem : mesh_error_code(e, a.domain);
    const char* status = mismatch ? "boundary_mismatch" : code == exit_invalid_problem ? "source_not_positive" : "bad_input";
    return fail(a, code, status, e.what(), nullptr, e.what());
  } catch (const algorithm::MapError& e) {
    const std::string text = culprit_message(a, e);
    return fail(a, exit_code_of(e.kind()), algorithm::kind_name(e.kind()), text, nullptr, text);
  } catch (const Failure& e) {  // an input that cannot be opened
    return fail(a, e.code(), "bad_input", e.what(), nullptr, e.what());
  }
}

void print_verdict(const MapArgs& a, const algorithm::MapResult& r) {
  const auto& s = r.stats;
  const algorithm::DoubleMap& dm = r.doubles;
  const std::string arith = to_string(a.options.placement.arith);
  std::printf("map: success, verified exactly (every tet positive in source and target, boundary as prescribed)%s\n",
              a.options.placement.arith.exact() ? "" : (", coordinates in " + arith).c_str());
  if (s.input_rounded)
    std::printf("  input read in %s: %zu coordinates rounded; the map is verified for the rounded input\n", arith.c_str(),
                s.input_rounded);
  std::printf("  %zu vertices / %zu tets in, %zu / %zu out (growth %.4f), %zu splits in preprocessing\n", s.input_vertices,
              s.input_tets, s.output_vertices, s.output_tets, s.growth_ratio,
              s.split_topology + s.split_all_boundary_tet + s.split_no_shrink_point + s.split_fallback);
  std::printf("  expansions: %zu simple, %zu in %zu subclusters, %zu star-shapified (%zu pushes), %zu inflated, "
              "%zu automatic\n",
              s.expansions_simple, s.expansions_subcluster, s.subcluster_expansions, s.expansions_star_shapified, s.pushes,
              s.expansions_inflated, s.expansions_automatic);
  if (dm.checked)
    std::printf("  largest coordinate: %zu bits; doubles (--snap %s) %s (%zu inverted, %zu degenerate)\n", s.max_bits,
                std::string(algorithm::to_string(snap_used(a))).c_str(), dm.check.valid() ? "valid" : "NOT valid",
                dm.check.inverted, dm.check.degenerate);
  else
    std::printf("  largest coordinate: %zu bits; doubles not checked (--snap none)\n", s.max_bits);
  if (dm.stopped_at_deadline)
    std::printf("  the double repair stopped at the time limit; the exact map is complete and verified\n");
  std::printf("  %.3f s\n", s.seconds_total);
}

int map_and_write(MapArgs& a, const algorithm::MapProblem& problem) {
  const bool show_progress = !quiet() && isatty(2);
  if (show_progress)
    a.options.progress = [](const algorithm::MapProgress& p) {
      std::fputs(progress_line(p).c_str(), stderr);
      std::fflush(stderr);
    };
  std::string trace_rows;
  if (!a.trace.empty()) a.options.trace = [&](const algorithm::TraceRow& row) { trace_rows += trace_line(row); };
  algorithm::MapResult r;
  try {
    r = algorithm::map_to_domain(problem, a.options);
  } catch (const algorithm::MapError& e) {
    if (show_progress) std::fputc('\n', stderr);
    const std::string text = culprit_message(a, e);
    return fail(a, exit_code_of(e.kind()), algorithm::kind_name(e.kind()), text, nullptr, text);
  }
  if (show_progress) std::fputc('\n', stderr);
  const bool failed = r.outcome != algorithm::MapOutcome::success;
  write_trace(a, trace_rows, failed);
  if (failed)
    return fail(a, exit_code_of(r.outcome), algorithm::to_string(r.outcome),
                std::string(algorithm::to_string(r.outcome)) + ": " + r.message, &r, r.message);
  write_outputs(a, r);
  write_report(a, report_json(a, &r, "success", ""), false);
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
}  // namespace cmx::cli
