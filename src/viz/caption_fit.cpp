#include "caption_fit.hpp"

#include <algorithm>
#include <cmath>

namespace amp::viz {

namespace {

double width_of(std::size_t chars, int size_px) { return kGlyphEm * size_px * static_cast<double>(chars); }

// The break at a space (after a comma if `after_comma`) whose longer line is shortest; npos if none.
std::size_t best_break(const std::string& text, bool after_comma) {
  std::size_t best = std::string::npos, best_len = text.size();
  for (std::size_t i = 1; i + 1 < text.size(); ++i) {
    if (text[i] != ' ' || (after_comma && text[i - 1] != ',')) continue;
    const std::size_t longer = std::max(i, text.size() - i - 1);
    if (longer < best_len) {
      best = i;
      best_len = longer;
    }
  }
  return best;
}

// `line` cut to `chars` characters, the last three of them "...", never inside a UTF-8 sequence.
std::string cut(const std::string& line, std::size_t chars) {
  if (line.size() <= chars) return line;
  std::size_t keep = chars > 3 ? chars - 3 : 0;
  while (keep > 0 && (static_cast<unsigned char>(line[keep]) & 0xC0) == 0x80) --keep;
  return line.substr(0, keep) + "...";
}

}  // namespace

FittedCaption fit_caption(const std::string& text, double width_px, int size_px, int min_size_px) {
  if (width_of(text.size(), size_px) <= width_px) return {{text}, size_px};
  std::size_t at = best_break(text, true);
  const bool comma_fits = at != std::string::npos && width_of(std::max(at, text.size() - at - 1), size_px) <= width_px;
  if (!comma_fits) at = best_break(text, false);
  FittedCaption out{{text}, size_px};
  if (at != std::string::npos) out.lines = {text.substr(0, at), text.substr(at + 1)};
  std::size_t longest = 0;
  for (const std::string& line : out.lines) longest = std::max(longest, line.size());
  if (width_of(longest, size_px) <= width_px) return out;
  const int fitting = static_cast<int>(std::floor(width_px / (kGlyphEm * static_cast<double>(longest))));
  out.size_px = std::clamp(fitting, min_size_px, size_px);
  const auto chars = static_cast<std::size_t>(std::max(0.0, std::floor(width_px / (kGlyphEm * out.size_px))));
  for (std::string& line : out.lines) line = cut(line, chars);
  return out;
}

}  // namespace amp::viz
