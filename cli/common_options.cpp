#include "cli/common_options.hpp"

#include <stdexcept>

#include "lp/backend_registry.hpp"

namespace cmx::cli {

CLI::Option* add_order_option(CLI::App& app, topology::ExpansionOrder& into, const std::string& description) {
  const auto parse = [](const std::string& text) {
    const auto order = topology::parse_expansion_order(text);
    if (!order)
      throw std::invalid_argument("unknown order '" + text + "' (" +
                                  std::string(topology::expansion_order_syntax) + ")");
    return *order;
  };
  return add_parsed(app, "--order", into, parse, description)->type_name("ORDER");
}

CLI::Option* add_filter_option(CLI::App& app, FilterPolicy& into, bool allow_naive, const std::string& description) {
  const auto parse = [allow_naive](const std::string& text) {
    std::string why;
    const auto policy = parse_filter_policy(text, &why);
    if (!policy) throw std::invalid_argument(why);
    if (!allow_naive && policy->kind == FilterPolicy::Kind::naive)
      throw std::invalid_argument("naive gives wrong signs; this command needs an exact policy");
    return *policy;
  };
  return add_parsed(app, "--filter", into, parse, description)->type_name("NAME");
}

CLI::Option* add_lp_option(CLI::App& app, std::string& into, const std::string& description) {
  const auto parse = [](const std::string& text) {
    if (lp::find_backend(text)) return text;
    throw std::invalid_argument("unknown LP backend '" + text + "'" +
                                (text == "glpk" ? " (this cmx is built without GLPK, which is GPL: the reference program "
                                                  "cmx-glpk has it, built next to cmx when configured with "
                                                  "-DCMX_WITH_GLPK=ON and libglpk-dev)"
                                                : " (certified, exact, glpk)"));
  };
  return add_parsed(app, "--lp", into, parse, description)->type_name("NAME");
}

CLI::Option* add_norm_option(CLI::App& app, lp::Norm& into, const std::string& description) {
  const auto parse = [](const std::string& text) {
    const auto norm = lp::parse_norm(text);
    if (!norm) throw std::invalid_argument("unknown norm '" + text + "' (l2-upper, l1)");
    return *norm;
  };
  return add_parsed(app, "--norm", into, parse, description)->type_name("NAME");
}

CLI::Option* add_corners_option(CLI::App& app, generators::CornerChoice& into) {
  const auto parse = [](const std::string& text) {
    const auto corners = generators::parse_corner_choice(text);
    if (!corners) throw std::invalid_argument("unknown corner choice '" + text + "' (random or farthest)");
    return *corners;
  };
  return add_parsed(app, "--corners", into, parse,
                    "random (default: the tetrahedron's corners go to drawn boundary\n"
                    "vertices) or farthest (to the ends of the longest protrusion or tunnel\n"
                    "and two vertices far from both, so that its vertices are spaced along\n"
                    "edges instead of crowded into a face; stiff-tet puts its corner 3 at\n"
                    "the inner end and corners 0, 1, 2 on a triangle at the outer end)")
      ->type_name("C");
}

}  // namespace cmx::cli
