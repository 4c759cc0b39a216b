#include "cli/command_line.hpp"

#include <cstdio>

#include "cli/command.hpp"
#include "cli/messages.hpp"
#include "cmx_version.hpp"

namespace cmx::cli {
namespace {

// CLI11's layout with the synopsis first and the description after it, as man pages have it.
class HelpFormatter : public CLI::Formatter {
 public:
  explicit HelpFormatter(HelpText text) : text_(std::move(text)) { column_width(26); }

  std::string make_help(const CLI::App* app, std::string, CLI::AppFormatMode mode) const override {
    return text_.synopsis + text_.description + make_positionals(app) + make_groups(app, mode) + "\n" + text_.footer;
  }

 private:
  HelpText text_;
};

}  // namespace

CommandLine::CommandLine(std::string_view command, HelpText help) : app_("", "cmx " + std::string(command)) {
  app_.formatter(std::make_shared<HelpFormatter>(std::move(help)));
  app_.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app_.set_help_flag("-h,--help", "print this help and exit");
  app_.set_version_flag("--version", "cmx " + std::string(cmx_version), "print the version of cmx and exit");
  quiet_option_ = app_.add_flag("-q,--quiet", quiet_, "no notes on what was written (results and errors stay)");
}

std::optional<int> CommandLine::parse(const std::vector<std::string>& args) {
  std::vector<std::string> last_first(args.rbegin(), args.rend());  // what App::parse(vector&) expects
  try {
    app_.parse(last_first);
  } catch (const CLI::CallForHelp&) {
    std::fputs(app_.help().c_str(), stdout);
    return exit_ok;
  } catch (const CLI::CallForVersion& e) {
    std::printf("%s\n", e.what());
    return exit_ok;
  } catch (const CLI::Error& e) {
    message(std::string(e.what()) + " (" + app_.get_name() + " --help lists the options)");
    return exit_usage;
  }
  set_quiet(quiet_);
  return std::nullopt;
}

void usage_error(const std::string& what) {
  throw Failure(exit_usage, what + " (cmx " + command_name() + " --help lists the options)");
}

}  // namespace cmx::cli
