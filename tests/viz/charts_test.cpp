#include "amp/viz/charts.hpp"

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"

namespace amp::viz {
namespace {

std::size_t count_of(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (auto pos = text.find(needle); pos != std::string::npos; pos = text.find(needle, pos + 1)) ++n;
  return n;
}

TEST(BoxStats, TukeyBoxOfOneToNineAndAnOutlier) {
  // Type-7 quartiles by hand: h = 9p; q1 = x[2] + 0.25 (x[3] - x[2]) = 3.25, median 5.5, q3 7.75;
  // IQR 4.5, upper fence 7.75 + 6.75 = 14.5, so 100 is an outlier and the whisker stops at 9.
  const std::vector<double> v = {100, 9, 8, 7, 6, 5, 4, 3, 2, 1};
  const BoxStats b = box_stats(v);
  EXPECT_EQ(b.n, 10u);
  EXPECT_DOUBLE_EQ(b.q1, 3.25);
  EXPECT_DOUBLE_EQ(b.median, 5.5);
  EXPECT_DOUBLE_EQ(b.q3, 7.75);
  EXPECT_DOUBLE_EQ(b.mean, 14.5);
  EXPECT_DOUBLE_EQ(b.whisker_low, 1.0);
  EXPECT_DOUBLE_EQ(b.whisker_high, 9.0);
  ASSERT_EQ(b.outliers.size(), 1u);
  EXPECT_DOUBLE_EQ(b.outliers[0], 100.0);
}

TEST(BoxStats, SingleValueIsADegenerateBox) {
  const std::vector<double> v = {7};
  const BoxStats b = box_stats(v);
  EXPECT_DOUBLE_EQ(b.q1, 7.0);
  EXPECT_DOUBLE_EQ(b.q3, 7.0);
  EXPECT_DOUBLE_EQ(b.whisker_low, 7.0);
  EXPECT_DOUBLE_EQ(b.whisker_high, 7.0);
  EXPECT_TRUE(b.outliers.empty());
}

TEST(BoxStats, RejectsEmptyAndNonFinite) {
  EXPECT_THROW(box_stats(std::vector<double>{}), ParameterError);
  EXPECT_THROW(box_stats(std::vector<double>{1, std::numeric_limits<double>::quiet_NaN()}), ParameterError);
}

TEST(BoxPlot, LinearGeometryMatchesHandComputedPixels) {
  ChartOptions o;
  o.width_px = 400;
  o.height_px = 300;
  o.lo = 0.0;
  o.hi = 100.0;
  const std::vector<Series> s = {{"a", "#123456", {100, 9, 8, 7, 6, 5, 4, 3, 2, 1}}, {"b", "#654321", {}}};
  const BoxPlotLayout l = box_plot_layout(s, o);
  // Plot area: x 64..384, y 36..254 (margins 64/16 and 36/46); value v at y = 254 - 2.18 v.
  ASSERT_DOUBLE_EQ(l.plot_top, 36.0);
  ASSERT_DOUBLE_EQ(l.plot_bottom, 254.0);
  auto y = [](double v) { return 254.0 - v * 218.0 / 100.0; };
  ASSERT_EQ(l.boxes.size(), 2u);
  const BoxGeometry& g = l.boxes[0];
  EXPECT_FALSE(g.empty);
  EXPECT_DOUBLE_EQ(g.x_center, 144.0);  // two slots of 160 px
  EXPECT_DOUBLE_EQ(g.half_width, 42.0);  // 0.3 * 160 = 48, capped at 42
  EXPECT_NEAR(g.y_q1, y(3.25), 1e-9);
  EXPECT_NEAR(g.y_median, y(5.5), 1e-9);
  EXPECT_NEAR(g.y_q3, y(7.75), 1e-9);
  EXPECT_NEAR(g.y_mean, y(14.5), 1e-9);
  EXPECT_NEAR(g.y_whisker_low, y(1), 1e-9);
  EXPECT_NEAR(g.y_whisker_high, y(9), 1e-9);
  ASSERT_EQ(g.y_outliers.size(), 1u);
  EXPECT_NEAR(g.y_outliers[0], 36.0, 1e-9);
  EXPECT_TRUE(l.boxes[1].empty);
  EXPECT_DOUBLE_EQ(l.boxes[1].x_center, 304.0);

  const std::string svg = box_plot_svg(s, o);
  // The box spans x 102..186 (width 84) and q3..q1 in y (height 4.5 * 2.18 = 9.81).
  EXPECT_NE(svg.find("<rect x=\"102.00\" y=\"237.10\" width=\"84.00\" height=\"9.81\""), std::string::npos)
      << svg;
  EXPECT_EQ(count_of(svg, "r=\"2.60\""), 1u);  // one outlier dot
  EXPECT_NE(svg.find("no runs"), std::string::npos);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
}

TEST(BoxPlot, LogAxisPlacesDecadesEvenly) {
  ChartOptions o;
  o.width_px = 400;
  o.height_px = 300;
  o.scale = AxisScale::kLog;
  // q1 = 10, median 100, q3 1000; fence 1000 + 1.5 * 990 = 2485 leaves 10000 an outlier.
  const std::vector<Series> s = {{"a", "#123456", {1, 10, 100, 1000, 10000}}};
  const BoxPlotLayout l = box_plot_layout(s, o);
  EXPECT_DOUBLE_EQ(l.axis.lo(), 1.0);  // the data's range, widened to whole decades
  EXPECT_DOUBLE_EQ(l.axis.hi(), 10000.0);
  auto y = [](double decade) { return 254.0 - decade * 218.0 / 4.0; };
  const BoxGeometry& g = l.boxes[0];
  EXPECT_NEAR(g.y_q1, y(1), 1e-9);
  EXPECT_NEAR(g.y_median, y(2), 1e-9);
  EXPECT_NEAR(g.y_q3, y(3), 1e-9);
  EXPECT_NEAR(g.y_whisker_low, y(0), 1e-9);
  EXPECT_NEAR(g.y_whisker_high, y(3), 1e-9);
  ASSERT_EQ(g.y_outliers.size(), 1u);
  EXPECT_NEAR(g.y_outliers[0], y(4), 1e-9);
}

TEST(Axis, NiceRangesAndTicks) {
  auto [a, b] = nice_range(0, 97, AxisScale::kLinear);
  EXPECT_DOUBLE_EQ(a, 0.0);
  EXPECT_DOUBLE_EQ(b, 100.0);
  EXPECT_EQ(ValueAxis(a, b, AxisScale::kLinear, 0, 1).ticks(), (std::vector<double>{0, 20, 40, 60, 80, 100}));

  auto [c, d] = nice_range(3, 2500, AxisScale::kLog);
  EXPECT_DOUBLE_EQ(c, 1.0);
  EXPECT_DOUBLE_EQ(d, 10000.0);
  const auto decades = ValueAxis(c, d, AxisScale::kLog, 0, 1).ticks();
  ASSERT_EQ(decades.size(), 5u);
  for (std::size_t i = 0; i < decades.size(); ++i) EXPECT_NEAR(decades[i], std::pow(10.0, i), 1e-9);

  const auto two_decades = ValueAxis(1, 100, AxisScale::kLog, 0, 1).ticks();
  const std::vector<double> expected = {1, 2, 5, 10, 20, 50, 100};
  ASSERT_EQ(two_decades.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(two_decades[i], expected[i], 1e-9);

  auto [e, f] = nice_range(5, 5, AxisScale::kLinear);  // one value: widened, still containing it
  EXPECT_LT(e, 5.0);
  EXPECT_GT(f, 5.0);
  EXPECT_THROW(ValueAxis(0, 10, AxisScale::kLog, 0, 1), ParameterError);
}

TEST(Axis, CompactNumbers) {
  EXPECT_EQ(compact_number(950), "950");
  EXPECT_EQ(compact_number(1234), "1.23k");
  EXPECT_EQ(compact_number(1.5e6), "1.5M");
  EXPECT_EQ(compact_number(0.25), "0.25");
  EXPECT_EQ(compact_number(100.2), "100.2");
  EXPECT_EQ(compact_number(0), "0");
  EXPECT_EQ(compact_number(2.5e-5), "2.5e-05");
  EXPECT_EQ(compact_number(std::numeric_limits<double>::quiet_NaN()), "\u2013");
}

TEST(Histogram, BarsScaleWithCounts) {
  ChartOptions o;
  o.width_px = 300;
  o.height_px = 200;
  // Plot area x 40..286 (82 px per unit over [0, 3]), y 28..176; counts axis 0..4.
  const std::string svg = histogram_svg({0, 1, 2, 3}, {1, 0, 4}, "#2563eb", o);
  EXPECT_NE(svg.find("<rect x=\"40.00\" y=\"139.00\" width=\"82.00\" height=\"37.00\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("<rect x=\"204.00\" y=\"28.00\" width=\"82.00\" height=\"148.00\""), std::string::npos);
  EXPECT_EQ(count_of(svg, "fill=\"#2563eb\""), 2u);  // the empty bin draws nothing

  o.count_max = 8;  // a shared count axis halves the bars
  const std::string shared = histogram_svg({0, 1, 2, 3}, {1, 0, 4}, "#2563eb", o);
  EXPECT_NE(shared.find("<rect x=\"204.00\" y=\"102.00\" width=\"82.00\" height=\"74.00\""), std::string::npos);
}

TEST(Histogram, EmptyAndMismatched) {
  EXPECT_NO_THROW(histogram_svg({}, {}, "#000", ChartOptions{}));
  EXPECT_THROW(histogram_svg({0, 1}, {1, 2}, "#000", ChartOptions{}), ParameterError);
}

}  // namespace
}  // namespace amp::viz
