#pragma once
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace amp::viz {

// Charts of run-cost distributions for the benchmark report, as standalone SVG strings: box plots
// (Tukey: whiskers at 1.5 IQR, outliers as dots) and histograms. Run costs are heavy-tailed (the
// run-cost paper's CVs reach 170 %), so both take a log scale.

enum class AxisScale { kLinear, kLog };

// A value axis mapping [lo, hi] (data units) onto [px_lo, px_hi] (pixels; px_hi < px_lo for a
// vertical axis, whose pixels grow downwards). On a log axis lo must be > 0; values <= 0 map to px_lo.
class ValueAxis {
 public:
  ValueAxis(double lo, double hi, AxisScale scale, double px_lo, double px_hi);
  double lo() const { return lo_; }
  double hi() const { return hi_; }
  AxisScale scale() const { return scale_; }
  double to_px(double v) const;
  // Tick values inside [lo, hi]: 1-2-5 steps (about `target` of them) on a linear axis; decades,
  // with 2 and 5 between them when the axis spans few decades, on a log axis.
  std::vector<double> ticks(int target = 5) const;

 private:
  double lo_, hi_;
  AxisScale scale_;
  double px_lo_, px_hi_;
};

// [lo, hi] widened to round tick values ("nice numbers", 1-2-5 steps; decades on a log axis) so that
// the axis starts and ends on a tick. A degenerate range is widened around its value.
std::pair<double, double> nice_range(double lo, double hi, AxisScale scale, int target = 5);

// Short tick text: 950, 99.75, 1.23k, 34k, 1.5M, 0.25, 2.5e-05. Never "nan": a non-finite value is "–".
std::string compact_number(double v);

// Tukey's box: type-7 quartiles (stats::quantile, R's default, as stats::describe), whiskers at the
// most extreme data within 1.5 IQR of the box, everything beyond them an outlier.
struct BoxStats {
  std::size_t n = 0;
  double q1 = 0.0, median = 0.0, q3 = 0.0, mean = 0.0;
  double whisker_low = 0.0, whisker_high = 0.0;
  std::vector<double> outliers;  // ascending
};
inline constexpr double kWhiskerIqr = 1.5;

// Throws ParameterError for an empty sample or a non-finite value.
BoxStats box_stats(std::span<const double> values);

// One labelled sample (one planner's run costs), drawn in `color` (an SVG colour).
struct Series {
  std::string label;
  std::string color;
  std::vector<double> values;
};

struct ChartOptions {
  int width_px = 560;
  int height_px = 320;
  AxisScale scale = AxisScale::kLinear;
  std::string title;
  std::string value_label;   // names the value axis, e.g. "CD calls"
  std::optional<double> lo;  // value-axis range; by default the data's, widened to nice ticks
  std::optional<double> hi;
  std::optional<double> count_max;  // histogram: height of the count axis (to share it between charts)
};

// Where a box plot draws each series (pixels), computed before drawing so tests can check it.
struct BoxGeometry {
  double x_center = 0.0, half_width = 0.0;
  double y_q1 = 0.0, y_median = 0.0, y_q3 = 0.0, y_mean = 0.0;
  double y_whisker_low = 0.0, y_whisker_high = 0.0;
  std::vector<double> y_outliers;
  bool empty = true;  // a series without values: no box, a "no runs" note
};

struct BoxPlotLayout {
  ValueAxis axis;  // vertical
  double plot_left, plot_right, plot_top, plot_bottom;
  std::vector<BoxGeometry> boxes;
};

BoxPlotLayout box_plot_layout(const std::vector<Series>& series, const ChartOptions& options);
// Vertical boxes side by side, one per series, on one value axis; the mean as a white diamond.
std::string box_plot_svg(const std::vector<Series>& series, const ChartOptions& options);

// A histogram over given bins: bar i spans [edges[i], edges[i+1]) with height counts[i]. With a
// log value axis the bins should be equal in log (the report makes them so). Throws ParameterError
// unless edges.size() == counts.size() + 1 (an empty histogram, both empty, draws an empty frame).
std::string histogram_svg(const std::vector<double>& edges, const std::vector<std::size_t>& counts,
                          const std::string& color, const ChartOptions& options);

}  // namespace amp::viz
