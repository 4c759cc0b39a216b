#include "cli/map_report.hpp"

#include "api/map_report.hpp"
#include "arith/rational.hpp"
#include "cmx_version.hpp"

namespace cmx::cli {
namespace {

std::uint64_t n(std::size_t x) { return std::uint64_t(x); }

JsonObject options_json(const MapArgs& a) {
  const algorithm::MapOptions& o = a.options;
  JsonObject opt;
  opt.str("order", topology::to_string(o.order));
  opt.str("precision", std::string(algorithm::to_string(o.placement.precision)));
  opt.str("filter", to_string(o.filter));
  opt.str("lp", o.placement.lp.backend);
  opt.str("norm", std::string(lp::to_string(o.placement.lp.norm)));
  opt.str("arith", to_string(o.placement.arith));
  opt.str("snap", std::string(algorithm::to_string(snap_used(a))));
  opt.num("smooth", n(o.smooth_every));
  opt.flag("collapse_refinement", o.collapse_refinement);
  opt.str("shelled", std::string(algorithm::to_string(o.shelled)));
  opt.str("replay_shelling", std::string(algorithm::to_string(o.replay)));
  opt.flag("collapse", o.collapse);
  opt.flag("merge", o.collapse && o.merge);
  opt.flag("flip_collapse", o.collapse && o.merge && o.flip_collapse);
  opt.num("subclusters", n(o.subclusters < 2 ? 0 : o.subclusters));
  opt.str("init", a.init_file.empty() ? algorithm::to_string(o.init) : a.init_file);
  opt.num("threads", n(o.threads));
  opt.num("time_limit", o.time_limit_seconds);  // 0: none (parse_time_limit makes inf 0)
  return opt;
}

}  // namespace

algorithm::SnapPolicy snap_used(const MapArgs& a) {
  return algorithm::applied_snap_policy(a.options);
}

JsonObject report_json(const MapArgs& a, const std::vector<ReportField>& fields, const std::string& status,
                       const std::string& message) {
  JsonObject j;
  j.str("cmx_version", cmx_version);
  j.str("domain", a.domain).str("status", status).str("message", message);
  j.obj("options", options_json(a));
  api::add_result_fields(j, fields);
  return j;
}

}  // namespace cmx::cli
