#include "api/map_report.hpp"

#include <sys/resource.h>

#include "arith/rational.hpp"

namespace cmx::api {
namespace {

std::uint64_t n(std::size_t x) {
  return std::uint64_t(x);
}

// The local repair: which initial map ran (or why the global method ran instead), the stars.
JsonObject local_json(const algorithm::LocalRepairStatistics& l) {
  JsonObject local;
  local.str("init", l.init).str("fallback", l.fallback);
  local.num("inverted", n(l.inverted)).num("flat", n(l.flat)).num("stars", n(l.stars));
  local.num("star_tets_max", n(l.star_tets_max)).num("star_tets_mean", l.star_tets_mean);
  local.num("tets_in_stars", n(l.tets_in_stars)).num("share", l.share).num("threads", n(l.threads));
  JsonObject times;
  times.num("initial_map", l.seconds_init).num("classify_and_grow", l.seconds_classify_grow);
  times.num("map_stars", l.seconds_map_stars).num("stitch", l.seconds_stitch);
  local.obj("seconds", times);
  return local;
}

JsonObject preprocess_json(const algorithm::MapResult& r) {
  const algorithm::MapStatistics& s = r.stats;
  JsonObject pre;
  pre.num("splits_topology", n(s.split_topology));
  pre.num("splits_all_boundary_tet", n(s.split_all_boundary_tet));
  pre.num("splits_no_shrink_point", n(s.split_no_shrink_point));
  pre.num("splits_fallback", n(s.split_fallback));
  pre.num("vertices", n(s.vertices_after_preprocess)).num("tets", n(s.tets_after_preprocess));
  pre.num("degenerate_tets_after_shrink", n(s.degenerate_after_shrink));
  pre.num("shrink_radius", s.shrink_radius).num("boundary_extent", s.boundary_extent);
  pre.str("shrink_point", to_string(r.center.coordinate(0)) + " " + to_string(r.center.coordinate(1)) + " " +
                              to_string(r.center.coordinate(2)));
  return pre;
}

void add_collapse_counts(JsonObject& ex, const algorithm::MapStatistics& s) {
  ex.num("collapsed", n(s.collapsed)).num("merged", n(s.merged));
  ex.num("relocating_collapses", n(s.relocating_collapses)).num("flip_collapses", n(s.flip_collapses));
  ex.flag("merge_stopped_at_time_limit", s.merge_stopped_at_time_limit);
  ex.flag("nobuenoss", s.nobuenoss);
  if (s.nobuenoss) {
    JsonObject shell;
    shell.flag("found", s.shelling_found).num("attempts", n(s.shelling_attempts));
    shell.num("best_removed", n(s.shelling_best_removed)).num("tets", n(s.shelling_tets));
    shell.num("split_chords", n(s.shelling_split_chords));
    shell.flag("replay_completed", s.shelling_replay_completed)
        .num("replay_expansions", n(s.shelling_replay_expansions));
    shell.num("replay_empty_cone_steps", n(s.shelling_replay_empty_cone_steps));
    ex.obj("input_shelling", shell);
  }
  ex.num("refinement_collapses", n(s.refinement_collapses));
  ex.num("restarts", n(s.expansion_restarts));  // runaway restarts (expansion/cluster_expansion.hpp)
}

JsonObject expansion_json(const algorithm::MapStatistics& s) {
  JsonObject ex, km;
  ex.num("simple", n(s.expansions_simple)).num("star_shapified", n(s.expansions_star_shapified));
  ex.num("inflated", n(s.expansions_inflated)).num("automatic", n(s.expansions_automatic));
  ex.num("subcluster", n(s.expansions_subcluster)).num("subclusters_expanded", n(s.subcluster_expansions));
  ex.num("subcluster_candidates", n(s.subcluster_candidates));
  km.num("1", n(s.k_manifold[1]))
      .num("2", n(s.k_manifold[2]))
      .num("3", n(s.k_manifold[3]))
      .num("other", n(s.k_manifold[0]));
  ex.obj("k_manifold", km);
  ex.num("smoothing_moves", n(s.smoothing_moves));
  ex.num("bends", n(s.bends)).num("relaxations", n(s.relaxations)).num("pushes", n(s.pushes));
  ex.num("inflation_splits", n(s.inflation_splits)).num("isolated_inflations", n(s.isolated_inflations));
  ex.num("shelled", n(s.shelled_star_shapifications)).num("base_edge_splits", n(s.base_edge_splits));
  ex.num("shelled_pushes", n(s.shelled_pushes)).num("shelled_pushes_left", n(s.shelled_pushes_left));
  if (s.replay.ran) {
    JsonObject rp;
    rp.flag("after_nobuenoss", s.replay.after_nobuenoss)
        .str("shelled", std::string(to_string(s.replay.shelled)));
    rp.num("shelled_retries", n(s.replay.shelled_retries));
    rp.flag("handed_over", s.replay.handed_over).num("chord_splits", n(s.replay.chord_splits));
    rp.num("shelling_attempts", n(s.replay.shelling_attempts)).num("steps", n(s.replay.steps));
    rp.num("plans", n(s.replay.plans)).num("plans_tried", n(s.replay.plans_tried));
    rp.num("splits", n(s.replay.splits)).num("expansions", n(s.replay.expansions));
    rp.num("plan_handover", n(s.replay.plan_handover));
    rp.num("drained", n(s.replay.drained));
    rp.num("drains_left", n(s.replay.drains_left)).num("replans", n(s.replay.replans));
    std::string ids = "[";
    for (std::size_t i = 0; i < s.replay.input_vertices.size(); ++i)
      ids += (i ? ", " : "") + std::to_string(s.replay.input_vertices[i]);
    rp.raw("input_vertices", ids + "]");
    ex.obj("replay", rp);
  }
  add_collapse_counts(ex, s);
  ex.num("lps", n(s.lps))
      .num("lps_certified", n(s.lps_certified))
      .num("lps_exact_fallback", n(s.lps_fell_back));
  ex.num("lp_float_guesses", n(s.lp_float_guesses))
      .num("placements_float_centre", n(s.placements_float_centre));
  ex.num("closed_by_support", n(s.closed_by_support));
  return ex;
}

JsonObject double_output_json(const algorithm::MapResult& r) {
  const algorithm::MapStatistics& s = r.stats;
  JsonObject dbl;
  dbl.num("chebyshev_moves", n(s.chebyshev_moves)).num("repaired", n(s.snap_repaired));
  dbl.num("crowd_scalings", n(s.snap_crowd_scalings)).num("crowd_sweeps", n(s.snap_crowd_sweeps));
  dbl.num("exact_repair_rounds", n(s.snap_exact_rounds)).num("double_repair_rounds", n(s.snap_rounds));
  dbl.num("boundary_rerounded", n(s.snap_boundary_rerounded));
  dbl.flag("stopped_at_time_limit", r.doubles.stopped_at_deadline);
  return dbl;
}

JsonObject seconds_json(const algorithm::MapStatistics& s) {
  JsonObject times;
  times.num("validate", s.seconds_validate)
      .num("preprocess", s.seconds_preprocess)
      .num("expand", s.seconds_expand);
  times.num("subcluster_search", s.seconds_subcluster_search)
      .num("shelling_search", s.seconds_shelling_search);
  times.num("collapse", s.seconds_collapse).num("double", s.seconds_double);
  times.num("verify", s.seconds_verify).num("total", s.seconds_total);
  return times;
}

JsonObject predicates_json(const algorithm::MapStatistics& s) {
  JsonObject filter;
  filter.num("semi_static", n(s.filter.semi_static));
  filter.num("adaptive",
             n(s.filter.adaptive[0] + s.filter.adaptive[1] + s.filter.adaptive[2] + s.filter.adaptive[3]));
  filter.num("interval", n(s.filter.interval)).num("mpfr", n(s.filter.mpfr)).num("exact", n(s.filter.exact));
  return filter;
}

JsonObject verdict_json(const algorithm::MapResult& r) {
  const algorithm::MapVerification& v = r.verification;
  const bool success = r.outcome == algorithm::MapOutcome::success;
  JsonObject verdict;
  verdict.flag("exact_valid", success && v.ok()).flag("target_positive", v.target_positive);
  verdict.flag("source_positive", v.source_positive).flag("input_kept", v.input_kept).flag("ball", v.ball);
  verdict.flag("boundary_refines", v.boundary_refines);
  const algorithm::DoubleMap& d = r.doubles;
  const bool checked = success && d.checked;
  verdict.flag("double_checked", checked).flag("double_valid", checked && d.check.valid());
  verdict.num("double_inverted", n(d.check.inverted)).num("double_degenerate", n(d.check.degenerate));
  return verdict;
}

JsonObject loss_json(const algorithm::PrecisionLoss& l) {
  JsonObject j;
  j.str("phase", l.phase).num("step", n(l.step)).num("vertex", std::uint64_t(l.vertex)).str("what", l.what);
  if (l.tet) {
    std::string ids;
    for (const auto w : *l.tet) ids.append(ids.empty() ? "[" : ", ").append(std::to_string(w));
    j.raw("tet", ids.append("]"));
    j.str("space", l.in_source ? "source" : "target");
    j.str("orientation", l.orientation == Sign::zero ? "degenerate" : "inverted");
  }
  j.num("exact_bits", n(l.exact_bits));
  return j;
}

}  // namespace

std::vector<ReportField> result_fields(const algorithm::MapResult& r) {
  const algorithm::MapStatistics& s = r.stats;
  JsonObject in, out, bits;
  in.num("vertices", n(s.input_vertices)).num("tets", n(s.input_tets));
  in.num("boundary_vertices", n(s.input_boundary_vertices))
      .num("interior_vertices", n(s.input_interior_vertices));
  in.num("rounded_coordinates", n(s.input_rounded));
  // A ball given by its tets alone: verdict.source_positive then says that the output subdivides
  // the input complex (exact barycentric check), the source geometry being absent.
  in.flag("combinatorial", s.combinatorial);
  out.num("vertices", n(s.output_vertices)).num("tets", n(s.output_tets)).num("growth_ratio", s.growth_ratio);
  bits.num("max", n(s.max_bits)).num("mean", s.mean_bits);
  std::vector<ReportField> f;
  const auto add = [&f](const char* key, const JsonObject& value) { f.push_back({key, value.text()}); };
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) == 0)
    f.push_back({"peak_rss_kb", std::to_string(std::uint64_t(usage.ru_maxrss))});  // Linux: KiB
  add("input", in);
  add("local", local_json(s.local));
  add("preprocess", preprocess_json(r));
  add("expansion", expansion_json(s));
  add("double_output", double_output_json(r));
  add("output", out);
  add("bits", bits);
  add("seconds", seconds_json(s));
  add("predicates", predicates_json(s));
  add("verdict", verdict_json(r));
  if (r.loss) add("precision_loss", loss_json(*r.loss));
  return f;
}

void add_result_fields(JsonObject& j, const std::vector<ReportField>& fields) {
  for (const ReportField& f : fields) j.raw(f.key, f.json);
}

}  // namespace cmx::api
