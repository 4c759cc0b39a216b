// cmx chebyshev: the exact Chebyshev centre of a set of half-spaces (lp/chebyshev_center.hpp).
//
// Input: one half-space per line, 4 exact numbers "a b c d" meaning a x + b y + c z <= d (any
// syntax of cmx::parse_rational); blank lines and '#' comments are skipped. Output: status,
// radius and centre as exact p/q and as nearest doubles; with --json exactly one object
//   {"status": S, "radius": "p/q", "center": ["p/q", "p/q", "p/q"], "center_double": [x, y, z]}
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
#include <sstream>
#include <string>
#include <vector>

#include "arith/rational.hpp"
#include "arith/rounding.hpp"
#include "cli/command.hpp"
#include "lp/backend_registry.hpp"
#include "lp/chebyshev_center.hpp"
#ifdef CMX_HAVE_GLPK
#include "lp/glpk/glpk_backend.hpp"
#endif

namespace cmx::cli {
namespace {

constexpr const char* usage =
    "usage: cmx chebyshev [--lp certified|exact|glpk] [--norm l2-upper|l1] [--weight-bits N] [--json] [FILE | -]\n"
    "Reads half-spaces 'a b c d' (a x + b y + c z <= d, exact numbers) from FILE or stdin and prints\n"
    "the Chebyshev centre: status (interior, empty_interior, infeasible, unbounded), radius r and\n"
    "centre, exactly and as nearest doubles. Blank lines and '#' comments are skipped.\n"
    "  --lp NAME         LP backend: certified (default: float simplex + exact certificate),\n"
    "                    exact (exact simplex), glpk (GLPK's exact simplex, if built)\n"
    "  --norm NAME       row weights: l2-upper (default: rigorous upper bound of |n|_2) or l1\n"
    "  --weight-bits N   significant bits of l2-upper weights, 2..53 (default 53); GLPK needs\n"
    "                    integer-scaled data below 2^53, which 24 usually gives\n"
    "  --json            one JSON object on stdout\n";

std::vector<std::string> tokens(const std::string& line) {
  std::istringstream in(line.substr(0, line.find('#')));
  std::vector<std::string> out;
  for (std::string t; in >> t;) out.push_back(t);
  return out;
}

// Reads every line; on any malformed line reports all of them and returns false.
bool read_halfspaces(std::istream& in, std::vector<lp::HalfSpace>& out) {
  bool ok = true;
  std::string line, why;
  for (long number = 1; std::getline(in, line); ++number) {
    const std::vector<std::string> t = tokens(line);
    if (t.empty()) continue;
    if (t.size() != 4) {
      std::fprintf(stderr, "line %ld: expected 4 numbers (a b c d), got %zu\n", number, t.size());
      ok = false;
      continue;
    }
    Rational q[4];
    bool line_ok = true;
    for (int i = 0; i < 4 && line_ok; ++i) {
      if (auto v = parse_rational(t[std::size_t(i)], &why)) {
        q[i] = *v;
      } else {
        std::fprintf(stderr, "line %ld: number %d: %s\n", number, i + 1, why.c_str());
        line_ok = false;
      }
    }
    if (!line_ok) {
      ok = false;
      continue;
    }
    out.push_back({q[0], q[1], q[2], q[3]});
  }
  if (in.bad()) {
    std::fprintf(stderr, "cmx chebyshev: read error\n");
    return false;
  }
  return ok;
}

std::string json_double(double x) {
  if (!std::isfinite(x)) return "null";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

void print_result(const lp::ChebyshevResult& r, bool json) {
  const bool has_center = r.status == lp::ChebyshevStatus::interior || r.status == lp::ChebyshevStatus::empty_interior;
  const std::string status(lp::to_string(r.status));
  if (json) {
    std::printf("{\"status\": \"%s\", ", status.c_str());
    if (!has_center) {
      std::printf("\"radius\": null, \"center\": null, \"center_double\": null}\n");
      return;
    }
    std::printf("\"radius\": \"%s\", \"center\": [\"%s\", \"%s\", \"%s\"], \"center_double\": [%s, %s, %s]}\n",
                to_string(r.radius).c_str(), to_string(r.center[0]).c_str(), to_string(r.center[1]).c_str(),
                to_string(r.center[2]).c_str(), json_double(to_double(r.center[0])).c_str(),
                json_double(to_double(r.center[1])).c_str(), json_double(to_double(r.center[2])).c_str());
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

// Value of "--name VALUE" or "--name=VALUE" at args[i] (advancing i), or nullopt with a message.
bool option_value(const std::vector<std::string>& args, std::size_t& i, const std::string& name, std::string& value) {
  const std::string& a = args[i];
  if (a == name) {
    if (i + 1 == args.size()) {
      std::fprintf(stderr, "cmx chebyshev: %s needs a value\n%s", name.c_str(), usage);
      return false;
    }
    value = args[++i];
    return true;
  }
  value = a.substr(name.size() + 1);
  return true;
}

bool is_option(const std::string& a, const std::string& name) { return a == name || a.rfind(name + "=", 0) == 0; }

int run(const std::vector<std::string>& args) {
#ifdef CMX_HAVE_GLPK
  lp::register_glpk_backend();
#endif
  lp::ChebyshevOptions options;
  bool json = false;
  std::string file, value;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      std::printf("%s", usage);
      return exit_ok;
    } else if (a == "--json") {
      json = true;
    } else if (is_option(a, "--lp")) {
      if (!option_value(args, i, "--lp", value)) return exit_usage;
      if (!lp::find_backend(value)) {
        std::fprintf(stderr, "cmx chebyshev: unknown LP backend '%s'%s\n", value.c_str(),
                     value == "glpk" ? " (this cmx was built without GLPK: configure with -DCMX_WITH_GLPK=ON and libglpk-dev)" : "");
        return exit_usage;
      }
      options.backend = value;
    } else if (is_option(a, "--norm")) {
      if (!option_value(args, i, "--norm", value)) return exit_usage;
      const auto norm = lp::parse_norm(value);
      if (!norm) {
        std::fprintf(stderr, "cmx chebyshev: unknown norm '%s' (l2-upper or l1)\n", value.c_str());
        return exit_usage;
      }
      options.norm = *norm;
    } else if (is_option(a, "--weight-bits")) {
      if (!option_value(args, i, "--weight-bits", value)) return exit_usage;
      char* end = nullptr;
      const long bits = std::strtol(value.c_str(), &end, 10);
      if (value.empty() || *end != '\0' || bits < 2 || bits > 53) {
        std::fprintf(stderr, "cmx chebyshev: --weight-bits wants an integer in 2..53, got '%s'\n", value.c_str());
        return exit_usage;
      }
      options.weight_bits = unsigned(bits);
    } else if (a.size() > 1 && a[0] == '-') {
      std::fprintf(stderr, "cmx chebyshev: unknown option '%s'\n%s", a.c_str(), usage);
      return exit_usage;
    } else if (!file.empty()) {
      std::fprintf(stderr, "cmx chebyshev: more than one input file\n%s", usage);
      return exit_usage;
    } else {
      file = a;
    }
  }
  std::vector<lp::HalfSpace> halfspaces;
  if (file.empty() || file == "-") {
    if (!read_halfspaces(std::cin, halfspaces)) return exit_bad_input;
  } else {
    std::ifstream in(file);
    if (!in) {
      std::fprintf(stderr, "cmx chebyshev: cannot open '%s'\n", file.c_str());
      return exit_bad_input;
    }
    if (!read_halfspaces(in, halfspaces)) return exit_bad_input;
  }
  try {
    print_result(lp::chebyshev_center(halfspaces, options), json);
  } catch (const lp::UnsupportedProblem& e) {
    std::fprintf(stderr, "cmx chebyshev: %s (try --weight-bits 24, or another --lp)\n", e.what());
    return exit_invalid_problem;
  }
  std::fflush(stdout);
  return exit_ok;
}

[[maybe_unused]] const bool registered =
    register_command({"chebyshev", "exact Chebyshev centre of half-spaces (lines 'a b c d': ax+by+cz <= d)", &run});

}  // namespace
}  // namespace cmx::cli
