#pragma once
#include <string>
#include <vector>

namespace amp::viz {

// SVG text does not wrap, and its width is known only to the renderer: estimate it at this many
// font sizes per character, above the average advance of Helvetica or Arial (about 0.5 em on
// captions) and of DejaVu Sans, their usual fallback (about 0.55 em).
inline constexpr double kGlyphEm = 0.6;

// A caption fitted to a width: one line if it fits at the preferred size, else two lines broken
// where the longer one is shortest (after a comma if one fits), shrunk towards `min_size_px` if
// they still do not fit, and cut with "..." as a last resort.
struct FittedCaption {
  std::vector<std::string> lines;
  int size_px = 0;
};

FittedCaption fit_caption(const std::string& text, double width_px, int size_px, int min_size_px);

}  // namespace amp::viz
