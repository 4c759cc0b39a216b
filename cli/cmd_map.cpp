// cmx map: the product. A ball-topology tet mesh and prescribed star-shaped boundary positions in,
// a refined mesh whose image has no inverted or degenerate tet out, verified exactly.
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "algorithm/map.hpp"
#include "arith/rational.hpp"
#include "arith/rounding.hpp"
#include "cli/command.hpp"
#include "cli/json.hpp"
#include "cli/map_input.hpp"
#include "io/atomic_file.hpp"
#include "io/io_error.hpp"
#include "io/tmap.hpp"
#include "io/write_mesh.hpp"
#include "kernel/coordinate_arith.hpp"
#include "kernel/filter_policy.hpp"
#include "lp/backend_registry.hpp"
#ifdef CMX_HAVE_GLPK
#include "lp/glpk/glpk_backend.hpp"
#endif

namespace cmx::cli {
namespace {

constexpr const char* usage =
    "usage: cmx map DOMAIN (--boundary B.txt | --codomain MESH | --shape SHAPE) [-o OUT]\n"
    "               [--format tmap,vtu,ovm,vtk,mesh] [--report R.json] [--time-limit S] [--check]\n"
    "               [--no-collapse] [--no-merge] [--no-flip-collapse] [--order priority|index|random:SEED] [--seed N] [--precision dyadic|shift|segment|none]\n"
    "               [--filter cascade|interval|exact|mpfr:BITS] [--lp certified|exact|glpk] [--norm l2-upper|l1]\n"
    "               [--snap repair|chebyshev-pass|nearest|none] [--trace T.csv] [--smooth N]\n"
    "               [--arith rational|double|mpfr:BITS] [--no-collapse-refinement] [--subclusters N]\n"
    "               [--quiet]\n"
    "Maps the ball-topology tet mesh DOMAIN bijectively onto the star-shaped domain bounded by the\n"
    "prescribed boundary positions (Cluster-Mesh Expansion), verifies the result exactly and prints\n"
    "the verdict.\n"
    "  --boundary B.txt  lines 'index x y z' (exact numbers) for exactly the boundary vertices\n"
    "  --codomain MESH   a mesh with DOMAIN's connectivity whose boundary vertices give the positions\n"
    "  --shape SHAPE     generated boundary: tet, stiff-tet, sphere, star[:SEED]\n"
    "  -o OUT            output path; OUT's extension (if one of the formats) selects that format,\n"
    "                    otherwise OUT is a stem. The exact map OUT.tmap is always written.\n"
    "  --format LIST     more formats, comma-separated: tmap, vtu, ovm, vtk, mesh (display formats\n"
    "                    carry the doubles chosen by --snap; the report says whether they are valid)\n"
    "  --report R.json   statistics and verdicts as JSON\n"
    "  --time-limit S    stop the expansion after S seconds (exit 6); once the exact map is complete,\n"
    "                    the double output stops at the limit too (the map is still written)\n"
    "  --check           assert every invariant after every step (slow; for testing)\n"
    "  --no-collapse     keep every added vertex (by default added vertices are collapsed away at\n"
    "                    the end wherever the map stays valid)\n"
    "  --no-merge        collapse added vertices only where the vertex kept can stay in place (by\n"
    "                    default an added vertex is also merged into an interior neighbour that\n"
    "                    moves into its new star's kernel: in source and target if it was added\n"
    "                    too, in the target only if it is an input vertex; or collapsed into a\n"
    "                    neighbour that stays while up to three other added vertices move, or\n"
    "                    after flips of its star that keep every tet positive)\n"
    "  --no-flip-collapse  merges as above but without the flips (faster on inputs without interior\n"
    "                    vertices, which then keep more added vertices)\n"
    "  --no-collapse-refinement  do not collapse, right after each star-shapification, the\n"
    "                    vertices it added (by default they are collapsed wherever every invariant\n"
    "                    survives: paper Sec. 4.2.2)\n"
    "  --subclusters N   when no single vertex is simply expandable, try expanding N = 2..4\n"
    "                    cluster vertices together before refining (paper Sec. 4.2.5; default 4;\n"
    "                    0 or 1: off)\n"
    "  --order ORDER     expansion order (default priority: paper Sec. 4.1.2)\n"
    "  --seed N          seed of random orders and of generated shapes (default 1234)\n"
    "  --precision P     precision reduction of new positions (default dyadic)\n"
    "  --filter F        predicate arithmetic (default cascade; all but naive are exact)\n"
    "  --lp NAME         LP backend (default certified)\n"
    "  --norm NAME       Chebyshev row weights (default l2-upper)\n"
    "  --snap POLICY     double output (default repair): repair = the nearest doubles if they are\n"
    "                    valid, else chebyshev-pass, then open the crowds of vertices around the\n"
    "                    shrink point (exact), then re-centre the vertices of tets the doubles\n"
    "                    invert among their neighbours' doubles; a boundary vertex of an\n"
    "                    all-boundary tet that rounding breaks may take another double within 1 ulp;\n"
    "                    chebyshev-pass = move every interior vertex to the Chebyshev centre of its\n"
    "                    star (exact map stays valid), then round; nearest = round and check;\n"
    "                    none = round, no check\n"
    "  --smooth N        every N expansions, move the cluster's expanded neighbours near the last\n"
    "                    expansions toward their neighbours' centroid where every tet keeps its\n"
    "                    state (paper Sec. 4.2.4; default 0: off)\n"
    "  --arith A         coordinate arithmetic (default rational: exact). double or mpfr:BITS (2..65536\n"
    "                    significant bits) round the input on entry (the report counts what moved)\n"
    "                    and every coordinate the method creates; predicates stay exact on the\n"
    "                    rounded values. Such a run stops where rounding first makes a tet inverted\n"
    "                    or degenerate (exit 8) and reports the step, vertex and tet; --snap is then\n"
    "                    nearest\n"
    "  --trace T.csv     one CSV row per expansion (kind, cone size, LP outcome, bits of the new\n"
    "                    position, largest and mean bits so far, added vertices, degenerate tets\n"
    "                    and cluster vertices left, seconds); written also when the run stops\n"
    "                    early; draw it with `cmx plot T.csv -o T.svg`. Slows the run down.\n"
    "  --quiet           no progress line, no verdict on stdout\n"
    "Exit codes: 0 mapped and verified; 2 bad command line; 3 unreadable or malformed input;\n"
    "4 not a valid problem (not a ball, boundary mismatch, degenerate or mirrored boundary);\n"
    "5 boundary not star-shaped; 6 time limit; 7 stuck; 8 precision lost (--arith double|mpfr:BITS);\n"
    "9 an output file cannot be written (checked before computing); 10 internal error (please report).\n"
    "On any failure no output file is written (an existing one is left untouched).\n"
    "Stuck on a NOBUENOSS (no cluster vertex satisfies Eq. (1)), the run then searches for a shelling\n"
    "of the input (8 greedy attempts), which the paper's fallback needs, and says whether it found one;\n"
    "replaying a shelling is not built, so the exit code stays 7.\n";

struct Args {
  std::string domain, boundary, codomain, shape, out, report, trace;
  std::vector<std::string> formats;
  double time_limit = 0;
  bool check = false, quiet = false;
  std::uint64_t seed = 1234;
  algorithm::MapOptions options;
};

std::vector<std::string> split_list(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

bool known_format(const std::string& f) { return f == "tmap" || f == "vtu" || f == "ovm" || f == "vtk" || f == "mesh"; }

// Returns "" or the usage error.
std::string parse_args(const std::vector<std::string>& args, Args& a) {
  std::string order_text;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& x = args[i];
    auto value = [&](std::string& into) {
      if (i + 1 >= args.size()) return false;
      into = args[++i];
      return true;
    };
    std::string v;
    if (x == "--boundary") {
      if (!value(a.boundary)) return "--boundary needs a file";
    } else if (x == "--codomain") {
      if (!value(a.codomain)) return "--codomain needs a mesh";
    } else if (x == "--shape") {
      if (!value(a.shape)) return "--shape needs a name";
    } else if (x == "-o" || x == "--output") {
      if (!value(a.out)) return "-o needs a path";
    } else if (x == "--report") {
      if (!value(a.report)) return "--report needs a path";
    } else if (x == "--smooth") {
      if (!value(v)) return "--smooth needs a number of expansions";
      char* end = nullptr;
      const unsigned long long n = std::strtoull(v.c_str(), &end, 10);
      if (end == v.c_str() || *end || v[0] == '-' || n > 1000000) return "--smooth needs an integer from 0 to 1000000";
      a.options.smooth_every = std::size_t(n);
    } else if (x == "--subclusters") {
      if (!value(v)) return "--subclusters needs a size";
      if (v.size() != 1 || v[0] < '0' || v[0] > '4') return "--subclusters needs an integer from 0 to 4";
      a.options.subclusters = std::size_t(v[0] - '0');
    } else if (x == "--trace") {
      if (!value(a.trace)) return "--trace needs a path";
    } else if (x == "--format") {
      if (!value(v)) return "--format needs a list";
      for (const auto& f : split_list(v)) {
        if (!known_format(f)) return "unknown format '" + f + "' (tmap, vtu, ovm, vtk, mesh)";
        a.formats.push_back(f);
      }
    } else if (x == "--time-limit") {
      if (!value(v)) return "--time-limit needs seconds";
      char* end = nullptr;
      a.time_limit = std::strtod(v.c_str(), &end);
      if (end == v.c_str() || *end || !(a.time_limit > 0)) return "--time-limit needs a positive number of seconds";
    } else if (x == "--seed") {
      if (!value(v)) return "--seed needs a number";
      char* end = nullptr;
      a.seed = std::strtoull(v.c_str(), &end, 10);
      if (end == v.c_str() || *end) return "--seed needs a non-negative integer";
    } else if (x == "--order") {
      if (!value(order_text)) return "--order needs a name";
      const auto o = topology::parse_expansion_order(order_text);
      if (!o) return "unknown order '" + order_text + "' (priority, index, random:SEED)";
      a.options.order = *o;
    } else if (x == "--precision") {
      if (!value(v)) return "--precision needs a name";
      const auto p = algorithm::parse_precision_policy(v);
      if (!p) return "unknown precision policy '" + v + "' (dyadic, shift, segment, none)";
      a.options.placement.precision = *p;
    } else if (x == "--filter") {
      if (!value(v)) return "--filter needs a name";
      std::string why;
      const auto f = parse_filter_policy(v, &why);
      if (!f) return why;
      if (f->kind == FilterPolicy::Kind::naive) return "--filter naive gives wrong signs; cmx map needs an exact policy";
      a.options.filter = *f;
    } else if (x == "--arith") {
      if (!value(v)) return "--arith needs a name";
      std::string why;
      const auto c = parse_coordinate_arith(v, &why);
      if (!c) return why;
      a.options.placement.arith = *c;
    } else if (x == "--snap") {
      if (!value(v)) return "--snap needs a name";
      const auto p = algorithm::parse_snap_policy(v);
      if (!p) return "unknown snap policy '" + v + "' (repair, chebyshev-pass, nearest, none)";
      a.options.snap = *p;
    } else if (x == "--lp") {
      if (!value(v)) return "--lp needs a name";
      if (!lp::find_backend(v)) return "unknown or unavailable LP backend '" + v + "'";
      a.options.placement.lp.backend = v;
    } else if (x == "--norm") {
      if (!value(v)) return "--norm needs a name";
      const auto n = lp::parse_norm(v);
      if (!n) return "unknown norm '" + v + "' (l2-upper, l1)";
      a.options.placement.lp.norm = *n;
    } else if (x == "--no-collapse-refinement") {
      a.options.collapse_refinement = false;
    } else if (x == "--no-collapse") {
      a.options.collapse = false;
    } else if (x == "--no-merge") {
      a.options.merge = false;
    } else if (x == "--no-flip-collapse") {
      a.options.flip_collapse = false;
    } else if (x == "--check") {
      a.check = true;
    } else if (x == "--quiet" || x == "-q") {
      a.quiet = true;
    } else if (!x.empty() && x[0] == '-') {
      return "unknown option '" + x + "'";
    } else if (a.domain.empty()) {
      a.domain = x;
    } else {
      return "more than one DOMAIN given ('" + a.domain + "' and '" + x + "')";
    }
  }
  if (a.domain.empty()) return "no DOMAIN mesh given";
  const int sources = !a.boundary.empty() + !a.codomain.empty() + !a.shape.empty();
  if (sources != 1) return "give exactly one of --boundary, --codomain, --shape";
  a.options.check = a.check;
  a.options.time_limit_seconds = a.time_limit;
  return {};
}

// OUT's stem and the formats to write (tmap always).
void output_plan(const Args& a, std::string& stem, std::vector<std::string>& formats) {
  stem = a.out;
  formats = a.formats;
  const auto dot = a.out.find_last_of('.');
  const auto slash = a.out.find_last_of('/');
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) {
    const std::string ext = a.out.substr(dot + 1);
    if (known_format(ext)) {
      stem = a.out.substr(0, dot);
      formats.push_back(ext);
    }
  }
  formats.push_back("tmap");
  std::sort(formats.begin(), formats.end());
  formats.erase(std::unique(formats.begin(), formats.end()), formats.end());
}

// "" when every file the run may write can be created, else why not.
std::string outputs_unwritable(const Args& a) {
  std::vector<std::string> paths = {a.report, a.trace};
  if (!a.out.empty()) {
    std::string stem;
    std::vector<std::string> formats;
    output_plan(a, stem, formats);
    for (const std::string& f : formats) paths.push_back(stem + "." + f);
  }
  for (const std::string& p : paths)
    if (!p.empty())
      if (std::string why = unwritable_reason(p); !why.empty()) return why;
  return {};
}

// The snap policy the run applies: a non-exact --arith's doubles are the plain rounding.
algorithm::SnapPolicy snap_used(const Args& a) {
  return a.options.placement.arith.exact() ? a.options.snap : algorithm::SnapPolicy::nearest;
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

JsonObject loss_json(const algorithm::PrecisionLoss& l) {
  JsonObject j;
  j.str("phase", l.phase).num("step", std::uint64_t(l.step)).num("vertex", std::uint64_t(l.vertex)).str("what", l.what);
  if (l.tet) {
    const auto& t = *l.tet;
    std::string ids;
    for (const auto w : t) ids.append(ids.empty() ? "[" : ", ").append(std::to_string(w));
    j.raw("tet", ids.append("]"));
    j.str("space", l.in_source ? "source" : "target");
    j.str("orientation", l.orientation == Sign::zero ? "degenerate" : "inverted");
  }
  j.num("exact_bits", std::uint64_t(l.exact_bits));
  return j;
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

std::vector<io::Point3> exact(const std::vector<HPoint>& points) {
  std::vector<io::Point3> out;
  out.reserve(points.size());
  for (const HPoint& p : points) out.push_back({p.coordinate(0), p.coordinate(1), p.coordinate(2)});
  return out;
}

void write_outputs(const std::string& stem, const std::vector<std::string>& formats, const algorithm::MapResult& r,
                   const std::vector<std::array<double, 3>>& doubles) {
  for (const std::string& f : formats) {
    const std::string path = stem + "." + f;
    if (f == "tmap") {
      io::TetMap m{exact(r.source), exact(r.target), r.tets};
      io::write_tmap(path, m);
    } else if (f == "ovm") {
      const std::vector<io::Point3> ex = exact(r.target);
      io::write_ovm(path, doubles, r.tets, &ex);
    } else if (f == "vtu") {
      io::write_vtu(path, doubles, r.tets);
    } else if (f == "vtk") {
      io::write_vtk(path, doubles, r.tets);
    } else if (f == "mesh") {
      io::write_medit(path, doubles, r.tets);
    }
  }
}

JsonObject report_json(const Args& a, const algorithm::MapResult* r, const std::string& status, const std::string& message) {
  JsonObject j;
  j.str("domain", a.domain);
  j.str("status", status);
  j.str("message", message);
  JsonObject opt;
  opt.str("order", topology::to_string(a.options.order));
  opt.str("precision", std::string(algorithm::to_string(a.options.placement.precision)));
  opt.str("filter", to_string(a.options.filter));
  opt.str("lp", a.options.placement.lp.backend);
  opt.str("norm", std::string(lp::to_string(a.options.placement.lp.norm)));
  opt.str("arith", to_string(a.options.placement.arith));
  opt.str("snap", std::string(algorithm::to_string(snap_used(a))));
  opt.num("smooth", std::uint64_t(a.options.smooth_every));
  opt.flag("collapse_refinement", a.options.collapse_refinement);
  opt.flag("collapse", a.options.collapse);
  opt.flag("merge", a.options.collapse && a.options.merge);
  opt.flag("flip_collapse", a.options.collapse && a.options.merge && a.options.flip_collapse);
  opt.num("subclusters", std::uint64_t(a.options.subclusters < 2 ? 0 : a.options.subclusters));
  opt.num("time_limit", a.time_limit);
  j.obj("options", opt);
  if (!r) return j;
  const algorithm::MapStatistics& s = r->stats;
  JsonObject in, pre, ex, out, bits, times, verdict, filter;
  in.num("vertices", std::uint64_t(s.input_vertices)).num("tets", std::uint64_t(s.input_tets));
  in.num("boundary_vertices", std::uint64_t(s.input_boundary_vertices)).num("interior_vertices", std::uint64_t(s.input_interior_vertices));
  in.num("rounded_coordinates", std::uint64_t(s.input_rounded));
  pre.num("splits_topology", std::uint64_t(s.split_topology));
  pre.num("splits_all_boundary_tet", std::uint64_t(s.split_all_boundary_tet));
  pre.num("splits_no_shrink_point", std::uint64_t(s.split_no_shrink_point));
  pre.num("splits_fallback", std::uint64_t(s.split_fallback));
  pre.num("vertices", std::uint64_t(s.vertices_after_preprocess)).num("tets", std::uint64_t(s.tets_after_preprocess));
  pre.num("degenerate_tets_after_shrink", std::uint64_t(s.degenerate_after_shrink));
  pre.num("shrink_radius", s.shrink_radius).num("boundary_extent", s.boundary_extent);
  pre.str("shrink_point", to_string(r->center.coordinate(0)) + " " + to_string(r->center.coordinate(1)) + " " +
                              to_string(r->center.coordinate(2)));
  ex.num("simple", std::uint64_t(s.expansions_simple)).num("star_shapified", std::uint64_t(s.expansions_star_shapified));
  ex.num("inflated", std::uint64_t(s.expansions_inflated)).num("automatic", std::uint64_t(s.expansions_automatic));
  ex.num("subcluster", std::uint64_t(s.expansions_subcluster)).num("subclusters_expanded", std::uint64_t(s.subcluster_expansions));
  ex.num("subcluster_candidates", std::uint64_t(s.subcluster_candidates));
  JsonObject km;
  km.num("1", std::uint64_t(s.k_manifold[1])).num("2", std::uint64_t(s.k_manifold[2])).num("3", std::uint64_t(s.k_manifold[3]));
  km.num("other", std::uint64_t(s.k_manifold[0]));
  ex.obj("k_manifold", km);
  ex.num("smoothing_moves", std::uint64_t(s.smoothing_moves));
  ex.num("bends", std::uint64_t(s.bends)).num("relaxations", std::uint64_t(s.relaxations)).num("pushes", std::uint64_t(s.pushes)).num("inflation_splits", std::uint64_t(s.inflation_splits));
  ex.num("collapsed", std::uint64_t(s.collapsed));
  ex.num("merged", std::uint64_t(s.merged));
  ex.num("relocating_collapses", std::uint64_t(s.relocating_collapses));
  ex.num("flip_collapses", std::uint64_t(s.flip_collapses));
  ex.flag("merge_stopped_at_time_limit", s.merge_stopped_at_time_limit);
  ex.flag("nobuenoss", s.nobuenoss);
  if (s.nobuenoss) {
    JsonObject shell;
    shell.flag("found", s.shelling_found).num("attempts", std::uint64_t(s.shelling_attempts));
    shell.num("best_removed", std::uint64_t(s.shelling_best_removed)).num("tets", std::uint64_t(s.input_tets));
    ex.obj("input_shelling", shell);
  }
  ex.num("refinement_collapses", std::uint64_t(s.refinement_collapses));
  ex.num("lps", std::uint64_t(s.lps)).num("lps_certified", std::uint64_t(s.lps_certified));
  ex.num("lps_exact_fallback", std::uint64_t(s.lps_fell_back));
  ex.num("lp_float_guesses", std::uint64_t(s.lp_float_guesses));
  ex.num("placements_float_centre", std::uint64_t(s.placements_float_centre));
  ex.num("closed_by_support", std::uint64_t(s.closed_by_support));
  out.num("vertices", std::uint64_t(s.output_vertices)).num("tets", std::uint64_t(s.output_tets));
  out.num("growth_ratio", s.growth_ratio);
  bits.num("max", std::uint64_t(s.max_bits)).num("mean", s.mean_bits);
  times.num("validate", s.seconds_validate).num("preprocess", s.seconds_preprocess).num("expand", s.seconds_expand);
  times.num("subcluster_search", s.seconds_subcluster_search);
  times.num("shelling_search", s.seconds_shelling_search);
  times.num("collapse", s.seconds_collapse).num("double", s.seconds_double);
  times.num("verify", s.seconds_verify).num("total", s.seconds_total);
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) == 0) j.num("peak_rss_kb", std::uint64_t(usage.ru_maxrss));  // Linux: KiB
  filter.num("semi_static", std::uint64_t(s.filter.semi_static));
  filter.num("adaptive", std::uint64_t(s.filter.adaptive[0] + s.filter.adaptive[1] + s.filter.adaptive[2] + s.filter.adaptive[3]));
  filter.num("interval", std::uint64_t(s.filter.interval)).num("mpfr", std::uint64_t(s.filter.mpfr));
  filter.num("exact", std::uint64_t(s.filter.exact));
  const algorithm::MapVerification& v = r->verification;
  const bool success = r->outcome == algorithm::MapOutcome::success;
  verdict.flag("exact_valid", success && v.ok()).flag("target_positive", v.target_positive);
  verdict.flag("source_positive", v.source_positive).flag("input_kept", v.input_kept).flag("ball", v.ball);
  verdict.flag("boundary_refines", v.boundary_refines);
  const algorithm::DoubleMap& d = r->doubles;
  const bool checked = success && d.checked;
  verdict.flag("double_checked", checked).flag("double_valid", checked && d.check.valid());
  verdict.num("double_inverted", std::uint64_t(d.check.inverted)).num("double_degenerate", std::uint64_t(d.check.degenerate));
  JsonObject dbl;
  dbl.num("chebyshev_moves", std::uint64_t(s.chebyshev_moves)).num("repaired", std::uint64_t(s.snap_repaired));
  dbl.num("crowd_scalings", std::uint64_t(s.snap_crowd_scalings)).num("crowd_sweeps", std::uint64_t(s.snap_crowd_sweeps));
  dbl.num("exact_repair_rounds", std::uint64_t(s.snap_exact_rounds)).num("double_repair_rounds", std::uint64_t(s.snap_rounds));
  dbl.num("boundary_rerounded", std::uint64_t(s.snap_boundary_rerounded));
  dbl.flag("stopped_at_time_limit", r->doubles.stopped_at_deadline);
  j.obj("input", in).obj("preprocess", pre).obj("expansion", ex).obj("double_output", dbl).obj("output", out).obj("bits", bits);
  j.obj("seconds", times).obj("predicates", filter).obj("verdict", verdict);
  if (r->loss) j.obj("precision_loss", loss_json(*r->loss));
  return j;
}

void write_report(const std::string& path, const JsonObject& j) {
  if (path.empty()) return;
  io::write_file_atomically(path, [&](std::ostream& os) { os << j.text() << '\n'; });
}

constexpr const char* trace_header =
    "step,kind,vertex,cone_rows,lp,bits,max_bits,mean_bits,added_vertices,degenerate_left,cluster_left,seconds\n";

std::string trace_line(const algorithm::TraceRow& r) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "%zu,%s,%u,%zu,%s,%zu,%zu,%.2f,%zu,%zu,%zu,%.4f\n", r.step, r.kind, r.vertex, r.cone_rows,
                r.lp, r.bits, r.max_bits, r.mean_bits, r.added_vertices, r.degenerate_left, r.cluster_left, r.seconds);
  return buf;
}

void write_trace(const std::string& path, const std::string& rows) {
  if (path.empty()) return;
  io::write_file_atomically(path, [&](std::ostream& os) { os << trace_header << rows; });
}

void progress_line(const algorithm::MapProgress& p) {
  std::fprintf(stderr, "\r  expanded %zu, left %zu, added vertices %zu, max bits %zu, %.1f s   ", p.expanded, p.remaining,
               p.splits, p.max_bits, p.seconds);
  std::fflush(stderr);
}

int run(const std::vector<std::string>& argv) {
  for (const auto& x : argv)
    if (x == "--help" || x == "-h") {
      std::fputs(usage, stdout);
      return exit_ok;
    }
#ifdef CMX_HAVE_GLPK
  lp::register_glpk_backend();
#endif
  Args a;
  if (std::string why = parse_args(argv, a); !why.empty()) {
    std::fprintf(stderr, "cmx map: %s\n%s", why.c_str(), usage);
    return exit_usage;
  }
  if (std::string why = outputs_unwritable(a); !why.empty()) {  // before minutes of computing
    std::fprintf(stderr, "cmx map: %s\n", why.c_str());
    return exit_write_failed;
  }
  algorithm::MapProblem problem;
  try {
    problem = load_map_problem(a.domain, a.boundary, a.codomain, a.shape, a.seed);
  } catch (const io::IoError& e) {
    std::fprintf(stderr, "cmx map: %s\n", e.what());
    write_report(a.report, report_json(a, nullptr, "bad_input", e.what()));
    return exit_bad_input;
  } catch (const algorithm::MapError& e) {
    std::fprintf(stderr, "cmx map: %s\n", e.what());
    write_report(a.report, report_json(a, nullptr, algorithm::kind_name(e.kind()), e.what()));
    return exit_code_of(e.kind());
  }
  const bool show_progress = !a.quiet && isatty(2);
  if (show_progress) a.options.progress = progress_line;
  std::string trace_rows;
  if (!a.trace.empty()) a.options.trace = [&](const algorithm::TraceRow& row) { trace_rows += trace_line(row); };
  algorithm::MapResult r;
  try {
    r = algorithm::map_to_domain(problem, a.options);
  } catch (const algorithm::MapError& e) {
    if (show_progress) std::fputc('\n', stderr);
    std::fprintf(stderr, "cmx map: %s\n", e.what());
    write_report(a.report, report_json(a, nullptr, algorithm::kind_name(e.kind()), e.what()));
    return exit_code_of(e.kind());
  }
  if (show_progress) std::fputc('\n', stderr);
  write_trace(a.trace, trace_rows);
  if (r.outcome != algorithm::MapOutcome::success) {
    std::fprintf(stderr, "cmx map: %s: %s\n", algorithm::to_string(r.outcome), r.message.c_str());
    write_report(a.report, report_json(a, &r, algorithm::to_string(r.outcome), r.message));
    return exit_code_of(r.outcome);
  }
  const algorithm::DoubleMap& dm = r.doubles;
  if (!a.out.empty()) {
    std::string stem;
    std::vector<std::string> formats;
    output_plan(a, stem, formats);
    write_outputs(stem, formats, r, dm.target);
  }
  write_report(a.report, report_json(a, &r, "success", ""));
  if (!a.quiet) {
    const auto& s = r.stats;
    std::printf("map: success, verified exactly (every tet positive in source and target, boundary as prescribed)%s\n",
                a.options.placement.arith.exact() ? "" : (", coordinates in " + to_string(a.options.placement.arith)).c_str());
    if (s.input_rounded)
      std::printf("  input read in %s: %zu coordinates rounded; the map is verified for the rounded input\n",
                  to_string(a.options.placement.arith).c_str(), s.input_rounded);
    std::printf("  %zu vertices / %zu tets in, %zu / %zu out (growth %.4f), %zu splits in preprocessing\n",
                s.input_vertices, s.input_tets, s.output_vertices, s.output_tets, s.growth_ratio,
                s.split_topology + s.split_all_boundary_tet + s.split_no_shrink_point + s.split_fallback);
    std::printf("  expansions: %zu simple, %zu in %zu subclusters, %zu star-shapified (%zu pushes), %zu inflated, "
                "%zu automatic\n",
                s.expansions_simple, s.expansions_subcluster, s.subcluster_expansions, s.expansions_star_shapified,
                s.pushes, s.expansions_inflated, s.expansions_automatic);
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
  return exit_ok;
}

const bool registered = register_command({"map", "map a ball-topology tet mesh onto a star-shaped domain (exact)", run});

}  // namespace
}  // namespace cmx::cli
