#pragma once
// Line charts as SVG text, written by the project itself (no plotting dependency): the panels of
// `cmx plot` (bits and refinement over a `cmx map --trace` run).
#include <string>
#include <vector>

namespace cmx::cli {

struct Series {
  std::string label;
  std::string colour;       // any SVG colour
  std::vector<double> y;    // one value per x
  bool dots = false;        // markers instead of a line
  bool right_axis = false;  // scaled to the panel's right axis
};

struct Panel {
  std::string title, left_label, right_label;
  std::vector<Series> series;
};

// One SVG document with the panels stacked, sharing the x values `x` (increasing).
// Long series are reduced to at most two points (lowest and highest) per pixel column, so spikes
// stay visible and the file stays small.
std::string svg_chart(const std::string& title, const std::string& x_label, const std::vector<double>& x,
                      const std::vector<Panel>& panels);

}  // namespace cmx::cli
