// cmx: entry point. Dispatches to the registered subcommands.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <new>

#include "command.hpp"
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
  std::fprintf(out, "usage: cmx COMMAND [ARGS...]   (cmx COMMAND --help for details)\n\ncommands:\n");
  for (const auto& c : commands())
    std::fprintf(out, "  %-14.*s %.*s\n", int(c.name.size()), c.name.data(), int(c.summary.size()),
                 c.summary.data());
}

}  // namespace cmx::cli

int main(int argc, char** argv) {
  using namespace cmx::cli;
  if (argc < 2) {
    print_usage(stderr);
    return exit_usage;
  }
  std::string_view name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") {
    print_usage(stdout);
    return exit_ok;
  }
  for (const auto& c : commands()) {
    if (c.name != name) continue;
    std::vector<std::string> args(argv + 2, argv + argc);
    try {
      return c.run(args);
    } catch (const cmx::io::IoError& e) {
      // Commands report their input errors themselves; what escapes is mostly a failed write.
      const bool write = e.kind() == cmx::io::ErrorKind::write_failed;
      std::fprintf(stderr, "cmx %s: %s%s\n", argv[1], write ? "cannot write output: " : "", e.what());
      return write ? exit_write_failed : exit_bad_input;
    } catch (const std::bad_alloc&) {
      std::fprintf(stderr, "cmx %s: out of memory\n", argv[1]);
      return exit_internal;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "cmx %s: internal error: %s\n", argv[1], e.what());
      return exit_internal;
    }
  }
  std::fprintf(stderr, "cmx: unknown command '%s'\n", argv[1]);
  print_usage(stderr);
  return exit_usage;
}
