#pragma once
#include <vector>

#include <Eigen/Core>

namespace amp::viz {

class SvgCanvas;
struct Style;

// A robot's outline as the figures draw it, centred on its position: a disc `width` across, or a
// `length` x `width` rectangle whose length lies along the heading. Plain values, so that viz
// stays below nav (the app converts nav::Footprint).
struct FootprintOutline {
  double length = 0.0;  // m along the heading (ignored for a disc)
  double width = 0.0;   // m across it; a disc's diameter
  bool disc = true;
};

// The rectangle's corners at pose (p, heading), counter-clockwise from the front left; empty for a
// disc.
std::vector<Eigen::Vector2d> outline_corners(const FootprintOutline& f, const Eigen::Vector2d& p, double heading);
// The outline at pose (p, heading): a circle for a disc, else a polygon.
void draw_footprint(SvgCanvas& c, const FootprintOutline& f, const Eigen::Vector2d& p, double heading, const Style& s);

}  // namespace amp::viz
