#pragma once
// The command line of every subcommand, on CLI11: `--opt VALUE` and `--opt=VALUE`, `--help`
// (exit 0, on stdout), `--version` and `--quiet` everywhere, and every bad command line exit 2
// with a message "cmx CMD: ..." that names the option. Option values are checked while parsing
// (add_parsed): a value that does not parse is a bad command line, never a wrapped number.
#include <CLI/CLI.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace cmx::cli {

// What `cmx CMD --help` prints around CLI11's list of options.
struct HelpText {
  std::string synopsis;     // "usage: cmx CMD ..." lines
  std::string description;  // what the command does
  std::string footer;       // exit codes and notes
};

class CommandLine {
 public:
  CommandLine(std::string_view command, HelpText help);
  CommandLine(const CommandLine&) = delete;
  CommandLine& operator=(const CommandLine&) = delete;

  CLI::App& app() { return app_; }
  // -q, --quiet, for a command that says what it suppresses.
  CLI::Option* quiet_flag() { return quiet_option_; }

  // Parses the arguments after the command name. nullopt: go on and run the command; otherwise
  // the exit code to return at once: 0 after --help or --version (printed on stdout), 2 after a
  // bad command line (reported). Sets quiet() (cli/messages.hpp) from --quiet.
  std::optional<int> parse(const std::vector<std::string>& args);

 private:
  CLI::App app_;
  bool quiet_ = false;
  CLI::Option* quiet_option_ = nullptr;
};

// A contradiction found after parsing (two sources of one thing, ...): throws Failure(exit 2)
// with `what` and a pointer to --help.
[[noreturn]] void usage_error(const std::string& what);

// An option whose value `parse(text)` turns into `into`; parse throws std::invalid_argument with
// the reason, which becomes "OPTION: reason" (exit 2). The last occurrence wins.
template <class T, class Parse>
CLI::Option* add_parsed(CLI::App& app, const std::string& names, T& into, Parse parse, const std::string& description) {
  auto name = std::make_shared<std::string>();
  CLI::Option* option = app.add_option_function<std::string>(
      names,
      [&into, parse, name](const std::string& text) {
        try {
          into = parse(text);
        } catch (const std::invalid_argument& e) {
          throw CLI::ValidationError(*name, e.what());
        }
      },
      description);
  *name = option->get_name();
  return option;
}

}  // namespace cmx::cli
