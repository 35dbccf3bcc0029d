#include "amp/viz/svg_canvas.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>

#include "amp/viz/xml_escape.hpp"

namespace amp::viz {

SvgCanvas::SvgCanvas(const Eigen::AlignedBox2d& world, int width_px, int margin_px, int footer_px)
    : world_(world), margin_(margin_px) {
  const Eigen::Vector2d size = world.sizes().cwiseMax(1e-9);
  scale_ = (width_px - 2.0 * margin_px) / size.x();
  width_ = width_px;
  height_ = static_cast<int>(std::ceil(size.y() * scale_)) + 2 * margin_px + footer_px;
  body_ << std::fixed << std::setprecision(2);
}

Eigen::Vector2d SvgCanvas::to_px(const Eigen::Vector2d& p) const {
  return {margin_ + (p.x() - world_.min().x()) * scale_, margin_ + (world_.max().y() - p.y()) * scale_};
}

void SvgCanvas::style_attrs(const Style& s) {
  body_ << " fill=\"" << s.fill << "\" stroke=\"" << s.stroke << "\"";
  if (s.stroke != "none") body_ << " stroke-width=\"" << s.stroke_width << "\"";
  if (s.opacity < 1.0) body_ << " opacity=\"" << s.opacity << "\"";
  if (s.round_joins) body_ << " stroke-linejoin=\"round\" stroke-linecap=\"round\"";
  if (!s.dash.empty()) body_ << " stroke-dasharray=\"" << s.dash << "\"";
}

void SvgCanvas::points_element(const char* tag, const std::vector<Eigen::Vector2d>& pts, const Style& s) {
  if (pts.size() < 2) return;
  body_ << '<' << tag << " points=\"";
  for (const auto& p : pts) {
    const auto q = to_px(p);
    body_ << q.x() << ',' << q.y() << ' ';
  }
  body_ << "\"";
  style_attrs(s);
  body_ << "/>\n";
}

void SvgCanvas::polygon(const std::vector<Eigen::Vector2d>& pts, const Style& s) { points_element("polygon", pts, s); }

void SvgCanvas::polyline(const std::vector<Eigen::Vector2d>& pts, const Style& s) { points_element("polyline", pts, s); }

void SvgCanvas::circle(const Eigen::Vector2d& c, double radius_world, const Style& s) {
  const auto q = to_px(c);
  body_ << "<circle cx=\"" << q.x() << "\" cy=\"" << q.y() << "\" r=\"" << std::max(radius_world * scale_, 0.5)
        << "\"";
  style_attrs(s);
  body_ << "/>\n";
}

void SvgCanvas::dot(const Eigen::Vector2d& c, double radius_px, const Style& s) {
  const auto q = to_px(c);
  body_ << "<circle cx=\"" << q.x() << "\" cy=\"" << q.y() << "\" r=\"" << radius_px << "\"";
  style_attrs(s);
  body_ << "/>\n";
}

void SvgCanvas::line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Style& s) {
  const auto p = to_px(a), q = to_px(b);
  body_ << "<line x1=\"" << p.x() << "\" y1=\"" << p.y() << "\" x2=\"" << q.x() << "\" y2=\"" << q.y() << "\"";
  style_attrs(s);
  body_ << "/>\n";
}

void SvgCanvas::rect(const Eigen::AlignedBox2d& box, const Style& s) {
  const auto p = to_px({box.min().x(), box.max().y()});
  rect_px(p.x(), p.y(), box.sizes().x() * scale_, box.sizes().y() * scale_, s);
}

void SvgCanvas::rect_px(double x, double y, double w, double h, const Style& s) {
  body_ << "<rect x=\"" << x << "\" y=\"" << y << "\" width=\"" << w << "\" height=\"" << h << "\"";
  style_attrs(s);
  body_ << "/>\n";
}

void SvgCanvas::text_px(double x, double y, std::string_view text, int size_px, const std::string& color,
                        std::string_view anchor, bool bold) {
  body_ << "<text x=\"" << x << "\" y=\"" << y << "\" font-size=\"" << size_px << "\" fill=\"" << color
        << "\" text-anchor=\"" << anchor << "\"" << (bold ? " font-weight=\"600\"" : "") << ">" << xml_escape(text)
        << "</text>\n";
}

void SvgCanvas::begin_group(std::string_view id, double opacity, bool crisp) {
  body_ << "<g class=\"" << xml_escape(id) << "\"";  // a class: several drawings may share one HTML page
  if (opacity < 1.0) body_ << " opacity=\"" << opacity << "\"";
  if (crisp) body_ << " shape-rendering=\"crispEdges\"";
  body_ << ">\n";
}
void SvgCanvas::begin_shifted_group(std::string_view id, double dx_px, double dy_px) {
  body_ << "<g class=\"" << xml_escape(id) << "\" transform=\"translate(" << dx_px << ' ' << dy_px << ")\">\n";
}

void SvgCanvas::end_group() { body_ << "</g>\n"; }

std::string SvgCanvas::str() const {
  std::ostringstream out;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width_ << "\" height=\"" << height_
      << "\" viewBox=\"0 0 " << width_ << ' ' << height_
      << "\" font-family=\"Helvetica, Arial, sans-serif\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n"
      << body_.str() << "</svg>\n";
  return out.str();
}

}  // namespace amp::viz
