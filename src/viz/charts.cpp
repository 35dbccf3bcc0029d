#include "amp/viz/charts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "amp/core/error.hpp"
#include "amp/stats/descriptive.hpp"
#include "amp/viz/svg_canvas.hpp"

namespace amp::viz {

namespace {

constexpr const char* kAxisColor = "#52606d";
constexpr const char* kGridColor = "#e4e7eb";
constexpr const char* kTextColor = "#1f2933";
constexpr const char* kMutedText = "#616e7c";
constexpr double kCharWidthPx = 6.6;  // average glyph width of 12 px Helvetica, to fit labels

// SvgCanvas works in world coordinates with y up; a canvas over [0, w] x [-h, 0] with no margin
// makes one world unit one pixel, so charts place everything in pixels through this flip.
Eigen::Vector2d px(double x, double y) { return {x, -y}; }

SvgCanvas pixel_canvas(int width, int height) {
  return SvgCanvas(Eigen::AlignedBox2d(Eigen::Vector2d(0, -height), Eigen::Vector2d(width, 0)), width, 0, 0);
}

double nice_step(double range, int target) {
  const double rough = range / std::max(target, 1);
  const double mag = std::pow(10.0, std::floor(std::log10(rough)));
  const double f = rough / mag;
  return (f < 1.5 ? 1.0 : f < 3.0 ? 2.0 : f < 7.0 ? 5.0 : 10.0) * mag;
}

std::string fit_label(const std::string& s, double width_px) {
  const auto max_chars = static_cast<std::size_t>(std::max(3.0, width_px / kCharWidthPx));
  if (s.size() <= max_chars) return s;
  return s.substr(0, max_chars - 1) + "\u2026";
}

// The value range of all series (positive values only on a log axis), widened to nice ticks unless
// the options fix it.
std::pair<double, double> data_range(const std::vector<Series>& series, const ChartOptions& o) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& s : series) {
    for (double v : s.values) {
      if (o.scale == AxisScale::kLog && v <= 0) continue;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  if (!std::isfinite(lo)) lo = hi = 1.0;
  auto [nlo, nhi] = nice_range(lo, hi, o.scale);
  return {o.lo.value_or(nlo), o.hi.value_or(nhi)};
}

void draw_title(SvgCanvas& c, const ChartOptions& o, double left) {
  if (!o.title.empty()) c.text_px(left, 15, o.title, 13, kTextColor, "start", true);
}

}  // namespace

ValueAxis::ValueAxis(double lo, double hi, AxisScale scale, double px_lo, double px_hi)
    : lo_(lo), hi_(hi), scale_(scale), px_lo_(px_lo), px_hi_(px_hi) {
  if (!(hi > lo) || (scale == AxisScale::kLog && !(lo > 0))) {
    throw ParameterError("ValueAxis: range [" + std::to_string(lo) + ", " + std::to_string(hi) +
                         "] is empty or not positive on a log axis");
  }
}

double ValueAxis::to_px(double v) const {
  double t;
  if (scale_ == AxisScale::kLog) {
    if (v <= 0) return px_lo_;
    t = (std::log10(v) - std::log10(lo_)) / (std::log10(hi_) - std::log10(lo_));
  } else {
    t = (v - lo_) / (hi_ - lo_);
  }
  return px_lo_ + t * (px_hi_ - px_lo_);
}

std::vector<double> ValueAxis::ticks(int target) const {
  std::vector<double> out;
  constexpr double kEps = 1e-9;
  if (scale_ == AxisScale::kLinear) {
    const double step = nice_step(hi_ - lo_, target);
    for (double k = std::ceil(lo_ / step - kEps); k * step <= hi_ + kEps * step; k += 1.0) out.push_back(k * step);
    return out;
  }
  const int d0 = static_cast<int>(std::floor(std::log10(lo_) + kEps));
  const int d1 = static_cast<int>(std::ceil(std::log10(hi_) - kEps));
  const int decades = std::max(d1 - d0, 1);
  const int stride = std::max(1, (decades + 2 * target - 1) / (2 * target));  // thin out many decades
  const bool minor = decades <= 2;
  for (int d = d0; d <= d1; d += stride) {
    for (double m : {1.0, 2.0, 5.0}) {
      if (m != 1.0 && !minor) continue;
      const double v = m * std::pow(10.0, d);
      if (v >= lo_ * (1 - kEps) && v <= hi_ * (1 + kEps)) out.push_back(v);
    }
  }
  return out;
}

std::pair<double, double> nice_range(double lo, double hi, AxisScale scale, int target) {
  if (scale == AxisScale::kLog) {
    if (!(lo > 0)) lo = 1.0;
    hi = std::max(hi, lo);
    double a = std::pow(10.0, std::floor(std::log10(lo)));
    double b = std::pow(10.0, std::ceil(std::log10(hi)));
    if (b <= a) b = a * 10.0;
    return {a, b};
  }
  if (hi < lo) std::swap(lo, hi);
  if (hi == lo) {  // one value: a small range around it
    const double pad = lo == 0 ? 1.0 : std::abs(lo) * 0.1;
    lo -= pad;
    hi += pad;
  }
  const double step = nice_step(hi - lo, target);
  return {std::floor(lo / step) * step, std::ceil(hi / step) * step};
}

std::string compact_number(double v) {
  if (!std::isfinite(v)) return "\u2013";
  char buf[32];
  const double a = std::abs(v);
  struct Unit {
    double scale;
    const char* suffix;
  };
  for (const Unit u : {Unit{1e9, "G"}, Unit{1e6, "M"}, Unit{1e3, "k"}}) {
    if (a >= u.scale) {
      std::snprintf(buf, sizeof buf, "%.3g%s", v / u.scale, u.suffix);
      return buf;
    }
  }
  if (a == 0) return "0";
  std::snprintf(buf, sizeof buf, a < 1e-3 ? "%.2g" : "%.4g", v);  // 4 digits: ticks 99.8, 100.2 stay apart
  return buf;
}

BoxStats box_stats(std::span<const double> values) {
  if (values.empty()) throw ParameterError("box_stats: values: the sample is empty");
  std::vector<double> x(values.begin(), values.end());
  double sum = 0.0;
  for (double v : x) {
    if (!std::isfinite(v)) throw ParameterError("box_stats: values: value is not finite: " + std::to_string(v));
    sum += v;
  }
  std::sort(x.begin(), x.end());
  BoxStats b;
  b.n = x.size();
  b.mean = sum / x.size();
  b.q1 = stats::quantile(x, 0.25);
  b.median = stats::quantile(x, 0.5);
  b.q3 = stats::quantile(x, 0.75);
  const double reach = kWhiskerIqr * (b.q3 - b.q1);
  b.whisker_low = b.q1;
  b.whisker_high = b.q3;
  for (double v : x) {
    if (v < b.q1 - reach || v > b.q3 + reach) {
      b.outliers.push_back(v);
    } else {
      b.whisker_low = std::min(b.whisker_low, v);
      b.whisker_high = std::max(b.whisker_high, v);
    }
  }
  return b;
}

BoxPlotLayout box_plot_layout(const std::vector<Series>& series, const ChartOptions& o) {
  constexpr double kLeft = 64, kRight = 16, kTop = 36, kBottom = 46;
  constexpr double kMaxHalfWidth = 42;
  const auto [lo, hi] = data_range(series, o);
  BoxPlotLayout l{ValueAxis(lo, hi, o.scale, o.height_px - kBottom, kTop), kLeft, o.width_px - kRight, kTop,
                  o.height_px - kBottom, {}};
  const double slot = (l.plot_right - l.plot_left) / std::max<std::size_t>(series.size(), 1);
  for (std::size_t i = 0; i < series.size(); ++i) {
    BoxGeometry g;
    g.x_center = l.plot_left + (i + 0.5) * slot;
    g.half_width = std::min(0.3 * slot, kMaxHalfWidth);
    if (!series[i].values.empty()) {
      const BoxStats b = box_stats(series[i].values);
      g.empty = false;
      g.y_q1 = l.axis.to_px(b.q1);
      g.y_median = l.axis.to_px(b.median);
      g.y_q3 = l.axis.to_px(b.q3);
      g.y_mean = l.axis.to_px(b.mean);
      g.y_whisker_low = l.axis.to_px(b.whisker_low);
      g.y_whisker_high = l.axis.to_px(b.whisker_high);
      for (double v : b.outliers) g.y_outliers.push_back(l.axis.to_px(v));
    }
    l.boxes.push_back(std::move(g));
  }
  return l;
}

std::string box_plot_svg(const std::vector<Series>& series, const ChartOptions& o) {
  const BoxPlotLayout l = box_plot_layout(series, o);
  SvgCanvas c = pixel_canvas(o.width_px, o.height_px);
  draw_title(c, o, 8);
  if (!o.value_label.empty()) {
    c.text_px(l.plot_right, 15, o.value_label + (o.scale == AxisScale::kLog ? ", log scale" : ""), 11, kMutedText,
              "end");
  }
  c.begin_group("grid");
  for (double t : l.axis.ticks()) {
    const double y = l.axis.to_px(t);
    c.line(px(l.plot_left, y), px(l.plot_right, y), Style{"none", kGridColor, 1.0});
    c.text_px(l.plot_left - 6, y + 4, compact_number(t), 11, kMutedText, "end");
  }
  c.line(px(l.plot_left, l.plot_top), px(l.plot_left, l.plot_bottom), Style{"none", kAxisColor, 1.0});
  c.line(px(l.plot_left, l.plot_bottom), px(l.plot_right, l.plot_bottom), Style{"none", kAxisColor, 1.0});
  c.end_group();

  const double slot = (l.plot_right - l.plot_left) / std::max<std::size_t>(series.size(), 1);
  for (std::size_t i = 0; i < series.size(); ++i) {
    const BoxGeometry& g = l.boxes[i];
    const std::string& color = series[i].color;
    const double x = g.x_center, w = g.half_width;
    c.begin_group("box-" + std::to_string(i));
    c.text_px(x, l.plot_bottom + 17, fit_label(series[i].label, slot - 4), 12, kTextColor, "middle", true);
    c.text_px(x, l.plot_bottom + 32, "n = " + std::to_string(series[i].values.size()), 11, kMutedText, "middle");
    if (g.empty) {
      c.text_px(x, (l.plot_top + l.plot_bottom) / 2, "no runs", 12, kMutedText, "middle");
      c.end_group();
      continue;
    }
    const Style whisker{"none", kAxisColor, 1.2};
    c.line(px(x, g.y_whisker_high), px(x, g.y_q3), whisker);
    c.line(px(x, g.y_q1), px(x, g.y_whisker_low), whisker);
    c.line(px(x - w / 2, g.y_whisker_high), px(x + w / 2, g.y_whisker_high), whisker);
    c.line(px(x - w / 2, g.y_whisker_low), px(x + w / 2, g.y_whisker_low), whisker);
    // A box of zero height (all quartiles equal) still shows as a line.
    c.rect_px(x - w, g.y_q3, 2 * w, std::max(g.y_q1 - g.y_q3, 0.0), Style{color, color, 1.4, 0.85});
    c.line(px(x - w, g.y_median), px(x + w, g.y_median), Style{"none", kTextColor, 2.4});
    const double d = 4.5;
    c.polygon({px(x, g.y_mean - d), px(x + d, g.y_mean), px(x, g.y_mean + d), px(x - d, g.y_mean)},
              Style{"#ffffff", kTextColor, 1.2});
    for (double y : g.y_outliers) c.dot(px(x, y), 2.6, Style{"none", color, 1.2, 0.8});
    c.end_group();
  }
  return c.str();
}

std::string histogram_svg(const std::vector<double>& edges, const std::vector<std::size_t>& counts,
                          const std::string& color, const ChartOptions& o) {
  if (!(edges.size() == counts.size() + 1 || (edges.empty() && counts.empty()))) {
    throw ParameterError("histogram_svg: edges: expected " + std::to_string(counts.size() + 1) + " edges for " +
                         std::to_string(counts.size()) + " bins, got " + std::to_string(edges.size()));
  }
  constexpr double kLeft = 40, kRight = 14, kTop = 28, kBottom = 24;
  SvgCanvas c = pixel_canvas(o.width_px, o.height_px);
  draw_title(c, o, 8);
  const double left = kLeft, right = o.width_px - kRight, top = kTop, bottom = o.height_px - kBottom;

  double lo = edges.empty() ? 0.0 : edges.front(), hi = edges.empty() ? 1.0 : edges.back();
  if (o.scale == AxisScale::kLog && !(lo > 0)) lo = 1.0;
  if (!(hi > lo)) hi = lo + 1.0;
  const ValueAxis x_axis(o.lo.value_or(lo), o.hi.value_or(hi), o.scale, left, right);
  std::size_t peak = 1;
  for (std::size_t n : counts) peak = std::max(peak, n);
  const double count_hi = std::max(o.count_max.value_or(0.0), static_cast<double>(peak));
  const ValueAxis y_axis(0.0, nice_range(0.0, count_hi, AxisScale::kLinear, 3).second, AxisScale::kLinear, bottom,
                         top);

  c.begin_group("grid");
  for (double t : y_axis.ticks(3)) {
    if (t != std::floor(t)) continue;  // counts are whole
    const double y = y_axis.to_px(t);
    c.line(px(left, y), px(right, y), Style{"none", kGridColor, 1.0});
    c.text_px(left - 5, y + 4, compact_number(t), 10, kMutedText, "end");
  }
  c.end_group();
  c.begin_group("bars");
  for (std::size_t i = 0; i < counts.size(); ++i) {
    if (counts[i] == 0) continue;
    const double x0 = x_axis.to_px(edges[i]), x1 = x_axis.to_px(edges[i + 1]);
    const double y = y_axis.to_px(static_cast<double>(counts[i]));
    c.rect_px(x0, y, std::max(x1 - x0, 1.0), bottom - y, Style{color, "#ffffff", 0.6, 0.9});
  }
  c.end_group();
  c.line(px(left, bottom), px(right, bottom), Style{"none", kAxisColor, 1.0});
  const auto ticks = x_axis.ticks(4);
  for (double t : ticks) {
    const double x = x_axis.to_px(t);
    c.line(px(x, bottom), px(x, bottom + 4), Style{"none", kAxisColor, 1.0});
    c.text_px(x, bottom + 16, compact_number(t), 10, kMutedText, "middle");
  }
  return c.str();
}

}  // namespace amp::viz
