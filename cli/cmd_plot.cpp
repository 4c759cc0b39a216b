// cmx plot T.csv -o T.svg: draws a `cmx map --trace` file: coordinate bits over the run (largest,
// mean, and each new position's) and refinement (vertices added so far, degenerate tets left).
// Exit: 0 written; 2 bad command line; 3 unreadable or malformed trace (file:line named); 9 the SVG
// cannot be written. Written atomically: a failure leaves no file (an existing one untouched).
#include <charconv>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "cli/command_line.hpp"
#include "cli/files.hpp"
#include "cli/messages.hpp"
#include "cli/plot_svg.hpp"
#include "io/atomic_file.hpp"
#include "io/io_error.hpp"

namespace cmx::cli::plot_command {
namespace {

const HelpText help = {
    "usage: cmx plot TRACE.csv -o OUT.svg [--title TEXT]\n",
    "Draws a `cmx map --trace` file as an SVG chart: coordinate bits over the expansions (largest,\n"
    "mean, and each new position's) and refinement (vertices added so far, degenerate tets left).\n",
    "Exit status: 0 written; 2 bad command line (also: OUT.svg is TRACE.csv); 3 unreadable or\n"
    "malformed trace; 9 OUT.svg cannot be written.\n"};

struct Trace {
  std::vector<double> step, bits, max_bits, mean_bits, added, degenerate;
};

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) out.push_back(cell);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

// Throws io::IoError naming file:line on anything malformed.
Trace read_trace(const std::string& path) {
  check_readable(path);
  std::ifstream in(path);
  if (!in) throw io::IoError(io::ErrorKind::open_failed, path, 0, "cannot open the trace file");
  std::string line;
  if (!std::getline(in, line))
    throw io::IoError(io::ErrorKind::truncated, path, 1,
                      "empty file (expected the header of `cmx map --trace`)");
  const std::vector<std::string> header = split_csv(line);
  std::map<std::string, std::size_t> column;
  for (std::size_t i = 0; i < header.size(); ++i) column[header[i]] = i;
  const char* needed[] = {"step", "bits", "max_bits", "mean_bits", "added_vertices", "degenerate_left"};
  for (const char* name : needed)
    if (!column.count(name))
      throw io::IoError(io::ErrorKind::syntax, path, 1,
                        std::string("no column '") + name + "' in the header");
  Trace t;
  std::vector<double>* into[] = {&t.step, &t.bits, &t.max_bits, &t.mean_bits, &t.added, &t.degenerate};
  for (std::size_t number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    const std::vector<std::string> cells = split_csv(line);
    if (cells.size() != header.size())
      throw io::IoError(
          io::ErrorKind::count_mismatch, path, number,
          std::to_string(cells.size()) + " fields, the header has " + std::to_string(header.size()));
    for (std::size_t k = 0; k < std::size(needed); ++k) {
      const std::string& cell = cells[column[needed[k]]];
      double v = 0;
      const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), v);
      if (ec != std::errc() || end != cell.data() + cell.size() || !(v >= 0) || v > 1e300)
        throw io::IoError(
            io::ErrorKind::syntax, path, number,
            std::string("column '") + needed[k] + "': not a finite number >= 0: '" + cell + "'");
      into[k]->push_back(v);
    }
    if (t.step.size() >= 2 && !(t.step.back() > t.step[t.step.size() - 2]))
      throw io::IoError(io::ErrorKind::syntax, path, number, "steps must increase");
  }
  if (t.step.empty())
    throw io::IoError(io::ErrorKind::truncated, path, 2, "no rows (the run made no expansion)");
  return t;
}

std::string chart(const Trace& t, const std::string& title) {
  Panel bits{"coordinate bits", "bits", "", {}};
  bits.series.push_back({"new position", "#9a9a9a", t.bits, true, false});
  bits.series.push_back({"largest so far", "#c0392b", t.max_bits, false, false});
  bits.series.push_back({"mean so far", "#2471a3", t.mean_bits, false, false});
  Panel refinement{"refinement", "vertices added", "degenerate tets left", {}};
  refinement.series.push_back({"vertices added", "#1e8449", t.added, false, false});
  refinement.series.push_back({"degenerate tets left", "#d68910", t.degenerate, false, true});
  return svg_chart(title, "expansion", t.step, {bits, refinement});
}

int run(const std::vector<std::string>& args) {
  std::string input, output, title;
  CommandLine line("plot", help);
  CLI::App& app = line.app();
  app.add_option("TRACE", input, "the trace of `cmx map --trace T.csv`")->required()->type_name("");
  app.add_option("-o,--output", output, "the SVG to write (atomically)")->required()->type_name("OUT.svg");
  app.add_option("--title", title, "the chart's title (default: the trace's path)")->type_name("TEXT");
  line.quiet_flag()->description("do not say what was written");
  if (const auto done = line.parse(args)) return *done;
  check_outputs_apart({output}, {input});
  check_writable({output});
  Trace t;
  try {
    t = read_trace(input);
  } catch (const io::IoError& e) {
    throw Failure(exit_bad_input, e.what());
  }
  const std::string svg = chart(t, title.empty() ? input : title);
  io::write_file_atomically(output, [&](std::ostream& os) { os << svg; });
  if (!quiet()) std::printf("wrote %s: %zu expansions\n", output.c_str(), t.step.size());
  return exit_ok;
}

const bool registered = register_command({"plot", "draw a `cmx map --trace` file as an SVG chart", run});

}  // namespace
}  // namespace cmx::cli::plot_command
