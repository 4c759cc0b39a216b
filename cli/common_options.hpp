#pragma once
// Options that several commands share, declared once so that they read and document the same.
#include <string>

#include "cli/command_line.hpp"
#include "generators/boundary_shapes.hpp"
#include "kernel/filter_policy.hpp"
#include "lp/row_weights.hpp"
#include "topology/topological_expansion.hpp"

namespace cmx::cli {

// --order priority|index|random:SEED
CLI::Option* add_order_option(CLI::App& app, topology::ExpansionOrder& into, const std::string& description);
// --filter cascade|interval|exact|mpfr:BITS|naive; `allow_naive` false refuses naive (wrong signs).
CLI::Option* add_filter_option(CLI::App& app, FilterPolicy& into, bool allow_naive, const std::string& description);
// --lp certified|exact|glpk (glpk only when built with it)
CLI::Option* add_lp_option(CLI::App& app, std::string& into, const std::string& description);
// --norm l2-upper|l1
CLI::Option* add_norm_option(CLI::App& app, lp::Norm& into, const std::string& description);
// --corners random|farthest, for generated boundary shapes (generators/boundary_shapes.hpp).
CLI::Option* add_corners_option(CLI::App& app, generators::CornerChoice& into);

}  // namespace cmx::cli
