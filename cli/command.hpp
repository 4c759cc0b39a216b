#pragma once
// Registry of cmx subcommands. A command is a function taking the arguments after its name and
// returning the process exit code; it writes results to stdout and diagnostics to stderr.
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace cmx::cli {

// Documented exit codes shared by every subcommand (README "Exit codes").
enum ExitCode : int {
  exit_ok = 0,
  exit_usage = 2,          // bad command line
  exit_bad_input = 3,      // unreadable or malformed input file / line
  exit_invalid_problem = 4,  // input read, but not a valid problem (not a ball, ...)
  exit_not_star_shaped = 5,
  exit_time_limit = 6,
  exit_stuck = 7,
  exit_precision_lost = 8,  // a run with non-exact coordinates (--arith) lost validity
  exit_write_failed = 9,   // an output file cannot be written (checked before computing)
  exit_internal = 10,      // a bug: an invariant or verification failed
};

struct Command {
  std::string_view name;
  std::string_view summary;  // one line for `cmx --help`
  int (*run)(const std::vector<std::string>& args);
};

// What a command throws when it cannot go on: main prints the message (cli/messages.hpp) and
// returns the code.
class Failure : public std::runtime_error {
 public:
  Failure(int code, const std::string& message) : std::runtime_error(message), code_(code) {}
  int code() const { return code_; }

 private:
  int code_;
};

// Returns true so that it can initialise a namespace-scope constant (self-registration).
bool register_command(const Command& command);
const std::vector<Command>& commands();

}  // namespace cmx::cli
