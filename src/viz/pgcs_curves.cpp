// pgcs_curves_svg (viz/pgcs_figures.hpp): the exploration's curves as stacked line charts.
#include <algorithm>
#include <functional>

#include "amp/viz/charts.hpp"
#include "amp/viz/pgcs_figures.hpp"
#include "amp/viz/svg_canvas.hpp"

namespace amp::viz {

namespace {

constexpr const char* kAxisColor = "#52606d";
constexpr const char* kGridColor = "#e4e7eb";
constexpr const char* kTextColor = "#1f2933";
constexpr const char* kLineColor = "#2563eb";
constexpr int kWidthPx = 760;
constexpr int kPanelPx = 150;   // height of one chart
constexpr int kPanelGapPx = 34; // between charts: room for the next one's title
constexpr int kTopPx = 34;      // the figure's title
constexpr int kBottomPx = 40;   // the step axis' labels
constexpr double kLeftPx = 70, kRightPx = 20;

// Pixel coordinates (y down) on a canvas whose world is [0, w] x [-h, 0], as charts.cpp does.
Eigen::Vector2d px(double x, double y) { return {x, -y}; }

struct Panel {
  std::string name;
  std::function<double(const CurveSample&)> value;
  bool unit_range = false;  // coverage: 0..1 whatever the data
};

}  // namespace

std::string pgcs_curves_svg(const std::vector<CurveSample>& curves, const std::string& title) {
  std::vector<Panel> panels = {
      {"clusters", [](const CurveSample& s) { return static_cast<double>(s.clusters); }, false},
      {"coverage (reachable free cells within 2 sigma of a centre)", [](const CurveSample& s) { return s.coverage; },
       true},
      {"quantisation error (RMS distance to the nearest centre)",
       [](const CurveSample& s) { return s.quantisation_error; }, false}};
  // Closed prior only means something when a door closed during the exploration.
  if (std::any_of(curves.begin(), curves.end(), [](const CurveSample& s) { return s.closed_prior != 0.0; })) {
    panels.push_back({"closed prior (prior mass cut off by a closed door)",
                      [](const CurveSample& s) { return s.closed_prior; }, true});
  }
  const int n = static_cast<int>(panels.size());
  const int height = kTopPx + n * kPanelPx + (n - 1) * kPanelGapPx + kBottomPx + kPanelGapPx / 2;
  SvgCanvas c(Eigen::AlignedBox2d(Eigen::Vector2d(0, -height), Eigen::Vector2d(kWidthPx, 0)), kWidthPx, 0, 0);
  c.text_px(kLeftPx, 18, title, 14, kTextColor, "start", true);

  const double last = curves.empty() ? 1.0 : static_cast<double>(std::max<long>(curves.back().step, 1));
  const auto [x_lo, x_hi] = nice_range(0.0, last, AxisScale::kLinear);
  const ValueAxis x_axis(x_lo, x_hi, AxisScale::kLinear, kLeftPx, kWidthPx - kRightPx);

  for (int p = 0; p < n; ++p) {
    const Panel& panel = panels[static_cast<std::size_t>(p)];
    const double top = kTopPx + kPanelGapPx / 2.0 + p * (kPanelPx + kPanelGapPx);
    const double bottom = top + kPanelPx;
    double hi = 0.0;
    for (const CurveSample& s : curves) hi = std::max(hi, panel.value(s));
    const auto [y_lo, y_hi] = panel.unit_range ? std::pair{0.0, 1.0} : nice_range(0.0, hi, AxisScale::kLinear);
    const ValueAxis y_axis(y_lo, y_hi, AxisScale::kLinear, bottom, top);

    c.begin_group("curve");
    c.text_px(kLeftPx, top - 8, panel.name, 12, kTextColor, "start", true);
    for (const double t : y_axis.ticks(4)) {
      const double y = y_axis.to_px(t);
      c.line(px(kLeftPx, y), px(kWidthPx - kRightPx, y), Style{"none", kGridColor, 1.0});
      c.text_px(kLeftPx - 6, y + 4, compact_number(t), 11, kAxisColor, "end");
    }
    for (const double t : x_axis.ticks(6)) {
      const double x = x_axis.to_px(t);
      c.line(px(x, top), px(x, bottom), Style{"none", kGridColor, 1.0});
      if (p == n - 1) c.text_px(x, bottom + 15, compact_number(t), 11, kAxisColor, "middle");
    }
    c.rect_px(kLeftPx, top, kWidthPx - kRightPx - kLeftPx, kPanelPx, Style{"none", kAxisColor, 1.0});
    std::vector<Eigen::Vector2d> line;
    for (const CurveSample& s : curves) {
      line.push_back(px(x_axis.to_px(static_cast<double>(s.step)), y_axis.to_px(panel.value(s))));
    }
    c.polyline(line, Style{"none", kLineColor, 1.8, 1.0, true});
    c.end_group();
  }
  const double axis_label_y = kTopPx + kPanelGapPx / 2.0 + n * kPanelPx + (n - 1) * kPanelGapPx + 32;
  c.text_px((kLeftPx + kWidthPx - kRightPx) / 2, axis_label_y, "exploration steps", 12, kTextColor, "middle");
  return c.str();
}

}  // namespace amp::viz
