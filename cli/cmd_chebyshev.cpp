// cmx chebyshev: the exact Chebyshev centre of a set of half-spaces (lp/chebyshev_center.hpp).
//
// Input: one half-space per line, 4 exact numbers "a b c d" meaning a x + b y + c z <= d (any
// syntax of cmx::parse_rational); blank lines and '#' comments are skipped. Output: status,
// radius and centre as exact p/q and as nearest doubles; with --json exactly one object
//   {"cmx_version": V, "status": S, "radius": "p/q", "center": ["p/q", "p/q", "p/q"], "center_double": [x, y,
//   z]}
// with S one of interior, empty_interior, infeasible, unbounded. For infeasible and unbounded,
// radius, center and center_double are null (there is no centre). A double that overflows is
// printed as null in JSON and as inf in text.
// Exit codes: 0 solved (whatever the status), 2 bad option (or --lp glpk when not built),
// 3 malformed input ("line N: reason" on stderr for every bad line, nothing on stdout),
// 4 the chosen reference backend cannot take the data exactly (GLPK: integers >= 2^53).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <span>
#include <string>
#include <vector>

#include "arith/rational.hpp"
#include "arith/rounding.hpp"
#include "cli/command.hpp"
#include "cli/command_line.hpp"
#include "cli/common_options.hpp"
#include "cli/reference_backends/reference_backends.hpp"
#include "cli/files.hpp"
#include "cli/json.hpp"
#include "cli/messages.hpp"
#include "cli/number_lines.hpp"
#include "cli/option_values.hpp"
#include "cmx_version.hpp"
#include "lp/backend_registry.hpp"
#include "lp/chebyshev_center.hpp"

namespace cmx::cli::chebyshev_command {
namespace {

const HelpText help = {
    "usage: cmx chebyshev [--lp certified|exact|glpk] [--norm l2-upper|l1] [--weight-bits N] [--json] [FILE "
    "| -]\n",
    "Reads half-spaces 'a b c d' (a x + b y + c z <= d, exact numbers) from FILE or stdin and prints\n"
    "the Chebyshev centre: status (interior, empty_interior, infeasible, unbounded), radius r and\n"
    "centre, exactly and as nearest doubles. Blank lines and '#' comments are skipped.\n",
    "Exit status: 0 solved (whatever the status); 2 bad command line (or --lp glpk when not built);\n"
    "3 malformed input ('line N: reason' for every bad line, nothing on stdout) or unreadable FILE;\n"
    "4 the chosen reference backend cannot take the data exactly (GLPK: integers >= 2^53).\n"};

// Reads every line; on any malformed line reports all of them and returns false.
bool read_halfspaces(std::istream& in, std::vector<lp::HalfSpace>& out) {
  return read_number_lines(in, 4, "4 numbers (a b c d)", [&](std::span<const Rational> q) {
    out.push_back({q[0], q[1], q[2], q[3]});
  });
}

void print_result(const lp::ChebyshevResult& r, bool json) {
  const bool has_center =
      r.status == lp::ChebyshevStatus::interior || r.status == lp::ChebyshevStatus::empty_interior;
  const std::string status(lp::to_string(r.status));
  if (json) {
    std::printf("{\"cmx_version\": %s, \"status\": \"%s\", ", json_quote(cmx_version).c_str(),
                status.c_str());
    if (!has_center) {
      std::printf("\"radius\": null, \"center\": null, \"center_double\": null}\n");
      return;
    }
    std::printf(
        "\"radius\": \"%s\", \"center\": [\"%s\", \"%s\", \"%s\"], \"center_double\": [%s, %s, %s]}\n",
        to_string(r.radius).c_str(), to_string(r.center[0]).c_str(), to_string(r.center[1]).c_str(),
        to_string(r.center[2]).c_str(), json_number(to_double(r.center[0])).c_str(),
        json_number(to_double(r.center[1])).c_str(), json_number(to_double(r.center[2])).c_str());
    return;
  }
  std::printf("status: %s\n", status.c_str());
  if (!has_center) return;
  std::printf("radius: %s\n", to_string(r.radius).c_str());
  std::printf("radius_double: %.17g\n", to_double(r.radius));
  std::printf("center: %s %s %s\n", to_string(r.center[0]).c_str(), to_string(r.center[1]).c_str(),
              to_string(r.center[2]).c_str());
  std::printf("center_double: %.17g %.17g %.17g\n", to_double(r.center[0]), to_double(r.center[1]),
              to_double(r.center[2]));
}

int run(const std::vector<std::string>& args) {
  register_reference_backends();
  lp::ChebyshevOptions options;
  bool json = false;
  std::string file;
  CommandLine line("chebyshev", help);
  CLI::App& app = line.app();
  app.add_option("FILE", file, "the input (stdin when absent or -)")->type_name("");
  add_lp_option(app, options.backend,
                "LP backend: certified (default: float simplex + exact certificate),\n"
                "exact (exact simplex), glpk (GLPK's exact simplex, if built)");
  add_norm_option(app, options.norm, "row weights: l2-upper (default: rigorous upper bound of |n|_2) or l1");
  add_parsed(
      app, "--weight-bits", options.weight_bits,
      [](const std::string& t) { return unsigned(parse_integer(t, 2, 53)); },
      "significant bits of l2-upper weights, 2..53 (default 53); GLPK needs\n"
      "integer-scaled data below 2^53, which 24 usually gives")
      ->type_name("N");
  app.add_flag("--json", json, "one JSON object on stdout (with cmx_version)");
  line.quiet_flag()->description("accepted for uniformity: chebyshev prints only its results");
  if (const auto done = line.parse(args)) return *done;
  std::vector<lp::HalfSpace> halfspaces;
  if (file.empty() || file == "-") {
    if (!read_halfspaces(std::cin, halfspaces)) return exit_bad_input;
  } else {
    check_readable(file);
    std::ifstream in(file);
    if (!in) throw Failure(exit_bad_input, file + ": cannot open");
    if (!read_halfspaces(in, halfspaces)) return exit_bad_input;
  }
  try {
    print_result(lp::chebyshev_center(halfspaces, options), json);
  } catch (const lp::UnsupportedProblem& e) {
    message(std::string(e.what()) + " (try --weight-bits 24, or another --lp)");
    return exit_invalid_problem;
  }
  std::fflush(stdout);
  return exit_ok;
}

[[maybe_unused]] const bool registered = register_command(
    {"chebyshev", "exact Chebyshev centre of half-spaces (lines 'a b c d': ax+by+cz <= d)", &run});

}  // namespace
}  // namespace cmx::cli::chebyshev_command
