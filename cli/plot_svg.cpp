#include "cli/plot_svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

namespace cmx::cli {
namespace {

constexpr double width = 900, panel_height = 260, margin_left = 80, margin_right = 80, margin_top = 50,
                 panel_gap = 70;
constexpr double plot_width = width - margin_left - margin_right;

std::string fmt(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string px(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else
      out += c;
  }
  return out;
}

// A "nice" upper bound for an axis starting at 0: 1, 2 or 5 times a power of ten.
double nice_max(double v) {
  if (!(v > 0)) return 1;
  const double p = std::pow(10.0, std::floor(std::log10(v)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= v) return m * p;
  return 10 * p;
}

struct Frame {
  double top, x0, x1, y_left, y_right;  // data ranges: x in [x0, x1], y in [0, y_*]
  double sx(double x) const { return margin_left + (x1 > x0 ? (x - x0) / (x1 - x0) : 0.5) * plot_width; }
  double sy(double y, bool right) const {
    return top + panel_height - y / (right ? y_right : y_left) * panel_height;
  }
};

// Lowest and highest value per pixel column, in x order.
std::vector<std::pair<double, double>> reduce(const Frame& f, const std::vector<double>& x,
                                              const std::vector<double>& y) {
  std::map<long, std::pair<std::pair<double, double>, std::pair<double, double>>>
      columns;  // column -> (min, max) points
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
    if (!std::isfinite(y[i])) continue;
    const long c = std::lround(f.sx(x[i]));
    auto it = columns.find(c);
    if (it == columns.end()) {
      columns[c] = {{x[i], y[i]}, {x[i], y[i]}};
      continue;
    }
    if (y[i] < it->second.first.second) it->second.first = {x[i], y[i]};
    if (y[i] > it->second.second.second) it->second.second = {x[i], y[i]};
  }
  std::vector<std::pair<double, double>> out;
  for (const auto& [c, mm] : columns) {
    const auto& [lo, hi] = mm;
    if (lo.first <= hi.first) {
      out.push_back(lo);
      if (hi != lo) out.push_back(hi);
    } else {
      out.push_back(hi);
      out.push_back(lo);
    }
  }
  return out;
}

void axes(std::string& svg, const Frame& f, const Panel& p, const std::string& x_label, bool has_right) {
  const double bottom = f.top + panel_height;
  svg += "<text x=\"" + px(margin_left) + "\" y=\"" + px(f.top - 12) + "\" font-weight=\"bold\">" +
         escape(p.title) + "</text>\n";
  svg += "<rect x=\"" + px(margin_left) + "\" y=\"" + px(f.top) + "\" width=\"" + px(plot_width) +
         "\" height=\"" + px(panel_height) + "\" fill=\"none\" stroke=\"#444\"/>\n";
  for (int i = 0; i <= 4; ++i) {
    const double yl = f.y_left * i / 4, yy = f.sy(yl, false);
    svg += "<line x1=\"" + px(margin_left) + "\" x2=\"" + px(margin_left + plot_width) + "\" y1=\"" + px(yy) +
           "\" y2=\"" + px(yy) + "\" stroke=\"#ddd\"/>\n";
    svg += "<text x=\"" + px(margin_left - 6) + "\" y=\"" + px(yy + 4) + "\" text-anchor=\"end\">" + fmt(yl) +
           "</text>\n";
    if (has_right)
      svg += "<text x=\"" + px(margin_left + plot_width + 6) + "\" y=\"" + px(yy + 4) + "\">" +
             fmt(f.y_right * i / 4) + "</text>\n";
    const double xv = f.x0 + (f.x1 - f.x0) * i / 4;
    svg += "<text x=\"" + px(f.sx(xv)) + "\" y=\"" + px(bottom + 16) + "\" text-anchor=\"middle\">" +
           fmt(std::round(xv)) + "</text>\n";
  }
  svg += "<text x=\"" + px(margin_left + plot_width / 2) + "\" y=\"" + px(bottom + 34) +
         "\" text-anchor=\"middle\">" + escape(x_label) + "</text>\n";
  svg += "<text transform=\"translate(" + px(18) + "," + px(f.top + panel_height / 2) +
         ") rotate(-90)\" text-anchor=\"middle\">" + escape(p.left_label) + "</text>\n";
  if (has_right)
    svg += "<text transform=\"translate(" + px(width - 14) + "," + px(f.top + panel_height / 2) +
           ") rotate(90)\" text-anchor=\"middle\">" + escape(p.right_label) + "</text>\n";
}

void draw_series(std::string& svg, const Frame& f, const std::vector<double>& x, const Series& s) {
  const auto points = reduce(f, x, s.y);
  if (s.dots) {
    for (const auto& [xv, yv] : points)
      svg += "<circle cx=\"" + px(f.sx(xv)) + "\" cy=\"" + px(f.sy(yv, s.right_axis)) +
             "\" r=\"1.3\" fill=\"" + s.colour + "\"/>\n";
    return;
  }
  svg += "<polyline fill=\"none\" stroke=\"" + s.colour + "\" stroke-width=\"1.5\" points=\"";
  for (const auto& [xv, yv] : points) svg += px(f.sx(xv)) + "," + px(f.sy(yv, s.right_axis)) + " ";
  svg += "\"/>\n";
}

void legend(std::string& svg, const Frame& f, const Panel& p) {
  double x = margin_left + 10;
  for (const Series& s : p.series) {
    const double y = f.top + 16;
    svg += "<rect x=\"" + px(x) + "\" y=\"" + px(y - 9) + "\" width=\"12\" height=\"4\" fill=\"" + s.colour +
           "\"/>\n";
    const std::string text = s.label + (s.right_axis ? " (right axis)" : "");
    svg += "<text x=\"" + px(x + 16) + "\" y=\"" + px(y - 3) + "\">" + escape(text) + "</text>\n";
    x += 24 + 7.0 * double(text.size());
  }
}

}  // namespace

std::string svg_chart(const std::string& title, const std::string& x_label, const std::vector<double>& x,
                      const std::vector<Panel>& panels) {
  const double height = margin_top + double(panels.size()) * (panel_height + panel_gap);
  std::string svg = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  svg += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + px(width) + "\" height=\"" + px(height) +
         "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg += "<text x=\"" + px(width / 2) + "\" y=\"24\" text-anchor=\"middle\" font-size=\"15\">" +
         escape(title) + "</text>\n";
  const double x0 = x.empty() ? 0 : x.front(), x1 = x.empty() ? 1 : x.back();
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const Panel& p = panels[i];
    double left = 0, right = 0;
    bool has_right = false;
    for (const Series& s : p.series)
      for (double v : s.y) {
        if (!std::isfinite(v)) continue;
        (s.right_axis ? right : left) = std::max(s.right_axis ? right : left, v);
        has_right = has_right || s.right_axis;
      }
    const Frame f{margin_top + double(i) * (panel_height + panel_gap) + 20, x0, x1, nice_max(left),
                  nice_max(right)};
    axes(svg, f, p, x_label, has_right);
    for (const Series& s : p.series) draw_series(svg, f, x, s);
    legend(svg, f, p);
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace cmx::cli
