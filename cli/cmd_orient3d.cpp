// cmx orient3d: exact orientation signs for lines of four points, for people who test other
// predicate implementations against ours.
//
// Input: one quadruple per line, 12 numbers (ax ay az bx by bz cx cy cz dx dy dz) separated by
// blanks, in any exact syntax of cmx::parse_rational (integers, decimals taken exactly, p/q,
// hexfloats). Blank lines and '#' comments are skipped. Output: one of '+', '-', '0' per good
// line: the sign of det[b-a, c-a, d-a] (positive for the unit tetrahedron; the opposite of
// Shewchuk's orient3d). A malformed line prints NOTHING on stdout and "line N: reason" on stderr,
// the remaining lines are still answered, and the exit status is 3 at the end.
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
#include "cli/files.hpp"
#include "cli/messages.hpp"
#include "cli/number_lines.hpp"
#include "kernel/orient.hpp"

namespace cmx::cli::orient3d_command {
namespace {

const HelpText help = {
    "usage: cmx orient3d [--filter NAME] [--stats] [FILE | -]\n"
    "       cmx orient3d --demo\n",
    "Reads lines of 12 exact numbers (four points a b c d) from FILE or stdin and prints\n"
    "'+', '-' or '0' per line: the sign of det[b-a, c-a, d-a]. Blank lines and '#' comments are\n"
    "skipped; a malformed line gets 'line N: reason' on stderr and no output, and the exit\n"
    "status is then 3.\n",
    "Exit status: 0 every line answered; 2 bad command line; 3 a malformed line or an unreadable\n"
    "FILE; 10 internal error (the demo's exact signs disagree).\n"};

// Kettner, Mehlhorn, Pion, Schirra, Yap, "Classroom examples of robustness problems in geometric
// computations" (2004), witness B1: the naive orientation of (p3, p1, p4) is wrong. Lifted to 3D
// with the apex (0, 0, 1), orient3d equals that 2D orientation. Coordinates are the doubles
// nearest to these decimals.
int run_demo() {
  const char* text[4][3] = {{"-233.33333333333334", "50.93333333333333", "0"},
                            {"200", "49.200000000000003", "0"},
                            {"166.66666666666669", "49.333333333333336", "0"},
                            {"0", "0", "1"}};
  double p[4][3];
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) p[i][k] = to_double(*parse_rational(text[i][k]));
  const Sign naive = orient3d(p[0], p[1], p[2], p[3], {FilterPolicy{FilterPolicy::Kind::naive, 0}, nullptr});
  FilterStats stats;
  const Sign exact = orient3d(p[0], p[1], p[2], p[3], {FilterPolicy{}, &stats});
  const Sign reference =
      orient3d(p[0], p[1], p[2], p[3], {FilterPolicy{FilterPolicy::Kind::exact, 0}, nullptr});
  std::printf("orient3d demo: four nearly coplanar points (Kettner et al. 2004, witness B1, lifted to 3D)\n");
  for (int i = 0; i < 4; ++i)
    std::printf("  %c = (%.17g, %.17g, %.17g)\n", "abcd"[i], p[i][0], p[i][1], p[i][2]);
  std::printf("sign of det[b-a, c-a, d-a]:\n");
  std::printf("  naive double : %c%s\n", sign_char(naive), naive != reference ? "   <- wrong" : "");
  std::printf("  exact cascade: %c   (decided by the %s)\n", sign_char(exact),
              stats.semi_static ? "semi-static filter" : "adaptive expansion stages");
  if (exact != reference) {
    message("internal error: cascade and exact disagree");
    return exit_internal;
  }
  return exit_ok;
}

int answer_lines(std::istream& in, const FilterPolicy& policy, bool show_stats) {
  FilterStats stats;
  const bool ok = read_number_lines(in, 12, "12 numbers", [&](std::span<const Rational> q) {
    const HPoint a(q[0], q[1], q[2]), b(q[3], q[4], q[5]), c(q[6], q[7], q[8]), d(q[9], q[10], q[11]);
    std::putchar(sign_char(orient3d(a, b, c, d, {policy, &stats})));
    std::putchar('\n');
  });
  std::fflush(stdout);
  if (show_stats) std::fprintf(stderr, "%s", stats.report().c_str());
  return ok ? exit_ok : exit_bad_input;
}

int run(const std::vector<std::string>& args) {
  FilterPolicy policy;
  bool show_stats = false, demo = false;
  std::string file;
  CommandLine line("orient3d", help);
  CLI::App& app = line.app();
  app.add_option("FILE", file, "the input (stdin when absent or -)")->type_name("");
  add_filter_option(app, policy, true,
                    "cascade (default), interval, exact, mpfr:BITS, naive (plain doubles:\n"
                    "wrong near degeneracies, for demonstrations)");
  app.add_flag("--stats", show_stats, "print how many signs each filter tier decided to stderr");
  app.add_flag("--demo", demo, "a near-degenerate case that plain doubles get wrong: naive vs exact");
  line.quiet_flag()->description("accepted for uniformity: orient3d prints only its results");
  if (const auto done = line.parse(args)) return *done;
  if (demo) return run_demo();
  if (file.empty() || file == "-") return answer_lines(std::cin, policy, show_stats);
  check_readable(file);
  std::ifstream in(file);
  if (!in) throw Failure(exit_bad_input, file + ": cannot open");
  return answer_lines(in, policy, show_stats);
}

[[maybe_unused]] const bool registered =
    register_command({"orient3d", "exact orientation signs of point quadruples (lines of 12 numbers)", &run});

}  // namespace
}  // namespace cmx::cli::orient3d_command
