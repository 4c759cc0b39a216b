// cmx: entry point. Dispatches to the registered subcommands; whatever a command lets escape is
// reported here, through the one printer of cli/messages.hpp.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>

#include "cli/command.hpp"
#include "cli/files.hpp"
#include "cli/messages.hpp"
#include "cmx_version.hpp"
#include "io/atomic_file.hpp"
#include "io/io_error.hpp"

namespace cmx::cli {

static std::vector<Command>& registry() {
  static std::vector<Command> all;
  return all;
}

bool register_command(const Command& command) {
  registry().push_back(command);
  return true;
}

const std::vector<Command>& commands() {
  auto& all = registry();
  std::sort(all.begin(), all.end(), [](const Command& a, const Command& b) { return a.name < b.name; });
  return all;
}

static void print_usage(std::FILE* out) {
  std::fprintf(out,
               "usage: cmx COMMAND [ARGS...]   (cmx COMMAND --help for details)\n"
               "       cmx --version\n\ncommands:\n");
  for (const auto& c : commands())
    std::fprintf(out, "  %-14.*s %.*s\n", int(c.name.size()), c.name.data(), int(c.summary.size()), c.summary.data());
}

// Runs a command; what it throws becomes a message and an exit code.
static int run_command(const Command& c, const std::vector<std::string>& args) {
  try {
    return c.run(args);
  } catch (const Failure& e) {
    message(e.what());
    return e.code();
  } catch (const io::IoError& e) {
    // Commands report their input errors themselves; what escapes is mostly a failed write.
    message(std::string(e.kind() == io::ErrorKind::write_failed ? "cannot write output: " : "") + e.what());
    return exit_code_of(e);
  } catch (const std::bad_alloc&) {
    message("out of memory");
    return exit_internal;
  } catch (const std::exception& e) {
    message(std::string("internal error: ") + e.what());
    return exit_internal;
  }
}

// CMX_SYNC_OUTPUT=1 makes every written file survive a power loss (io/atomic_file.hpp); unset,
// empty or 0: files are replaced atomically only. False for any other value (a usage error).
static bool read_sync_setting() {
  const char* value = std::getenv("CMX_SYNC_OUTPUT");
  if (!value || !*value || !std::strcmp(value, "0")) return true;
  if (std::strcmp(value, "1")) return false;
  io::set_output_durability(io::Durability::synced);
  return true;
}

}  // namespace cmx::cli

int main(int argc, char** argv) {
  using namespace cmx::cli;
  if (argc < 2) {
    print_usage(stderr);
    return exit_usage;
  }
  const std::string_view name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") {
    print_usage(stdout);
    return exit_ok;
  }
  if (name == "--version") {
    std::printf("cmx %s\n", cmx_version);
    return exit_ok;
  }
  for (const auto& c : commands())
    if (c.name == name) {
      set_command_name(name);
      if (!read_sync_setting()) {
        message("environment variable CMX_SYNC_OUTPUT: '" + std::string(std::getenv("CMX_SYNC_OUTPUT")) +
                "' is neither 0 nor 1");
        return exit_usage;
      }
      return run_command(c, std::vector<std::string>(argv + 2, argv + argc));
    }
  message("unknown command '" + std::string(name) + "' (cmx --help lists the commands)");
  return exit_usage;
}
