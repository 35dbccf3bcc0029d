#pragma once
#include <string>
#include <string_view>

namespace amp::viz {

// Escapes &, <, > and quotes for SVG/HTML text.
std::string xml_escape(std::string_view s);

}  // namespace amp::viz
