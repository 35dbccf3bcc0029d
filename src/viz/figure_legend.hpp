#pragma once
#include <string>

#include "amp/viz/svg_canvas.hpp"

namespace amp::viz {

// Legend items left to right along a figure's footer (the PGCS and policy-search figures), each a
// colour swatch and its label.
class FigureLegend {
 public:
  FigureLegend(SvgCanvas& c, double y_px, double x_px, const char* text_color)
      : c_(c), x_(x_px), y_(y_px), text_color_(text_color) {}
  void item(const char* color, const std::string& label, double opacity = 0.8) {
    c_.rect_px(x_, y_ - 9, 14, 14, Style{color, "none", 0, opacity});
    c_.text_px(x_ + 20, y_ + 3, label, 13, text_color_);
    x_ += 30 + 7.5 * static_cast<double>(label.size());  // about 7.5 px per character at 13 px
  }

 private:
  SvgCanvas& c_;
  double x_;
  double y_;
  std::string text_color_;
};

}  // namespace amp::viz
