#include "amp/viz/footprint_outline.hpp"

#include <cmath>

#include "amp/viz/svg_canvas.hpp"

namespace amp::viz {

std::vector<Eigen::Vector2d> outline_corners(const FootprintOutline& f, const Eigen::Vector2d& p, double heading) {
  if (f.disc) return {};
  const Eigen::Vector2d along = 0.5 * f.length * Eigen::Vector2d(std::cos(heading), std::sin(heading));
  const Eigen::Vector2d across = 0.5 * f.width * Eigen::Vector2d(-std::sin(heading), std::cos(heading));
  return {p + along + across, p - along + across, p - along - across, p + along - across};
}

void draw_footprint(SvgCanvas& c, const FootprintOutline& f, const Eigen::Vector2d& p, double heading, const Style& s) {
  if (f.disc) {
    c.circle(p, 0.5 * f.width, s);
  } else {
    c.polygon(outline_corners(f, p, heading), s);
  }
}

}  // namespace amp::viz
