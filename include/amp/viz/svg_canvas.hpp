#pragma once
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace amp::viz {

// Paint for one SVG element.
struct Style {
  std::string fill = "none";
  std::string stroke = "none";
  double stroke_width = 1.0;  // pixels, whatever the zoom
  double opacity = 1.0;
  bool round_joins = false;
  std::string dash = {};  // SVG stroke-dasharray in pixels ("6 4"); empty: solid
};

// An SVG document over a world rectangle: world coordinates in (y up), pixels out (y down). Stroke
// widths are in pixels so that thin lines stay visible on large worlds.
class SvgCanvas {
 public:
  // `world` is the drawn rectangle; `width_px` the image width (height follows the aspect ratio);
  // `margin_px` around the world, `footer_px` extra space below it for a legend.
  SvgCanvas(const Eigen::AlignedBox2d& world, int width_px, int margin_px = 24, int footer_px = 0);

  int width_px() const { return width_; }
  int height_px() const { return height_; }
  double scale() const { return scale_; }
  Eigen::Vector2d to_px(const Eigen::Vector2d& p) const;

  void polygon(const std::vector<Eigen::Vector2d>& pts, const Style& s);
  void polyline(const std::vector<Eigen::Vector2d>& pts, const Style& s);
  void circle(const Eigen::Vector2d& c, double radius_world, const Style& s);
  void dot(const Eigen::Vector2d& c, double radius_px, const Style& s);
  void line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Style& s);
  void rect(const Eigen::AlignedBox2d& box, const Style& s);
  // Text at a pixel position (for titles and legends).
  void text_px(double x, double y, std::string_view text, int size_px, const std::string& color,
               std::string_view anchor = "start", bool bold = false);
  void rect_px(double x, double y, double w, double h, const Style& s);
  // Opens/closes a <g> group (one per layer). A group's opacity composites the group as one image,
  // so overlapping members (mesh triangles, grid runs) show no seams or double darkening;
  // `crisp` turns off anti-aliasing inside it (pixel-aligned rasters such as occupancy grids).
  void begin_group(std::string_view name, double opacity = 1.0, bool crisp = false);
  // A group shifted by whole pixels: the same world drawn again beside itself (side-by-side panels
  // share one canvas and one scale).
  void begin_shifted_group(std::string_view name, double dx_px, double dy_px);
  void end_group();

  std::string str() const;

 private:
  void style_attrs(const Style& s);
  void points_element(const char* tag, const std::vector<Eigen::Vector2d>& pts, const Style& s);
  Eigen::AlignedBox2d world_;
  double scale_;
  int margin_;
  int width_;
  int height_;
  std::ostringstream body_;
};

}  // namespace amp::viz
