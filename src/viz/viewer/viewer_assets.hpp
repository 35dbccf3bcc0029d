#pragma once
#include <string_view>

// The 3-D viewer's page template, its script, and three.js r111 with its orbit controls from
// Debian's libjs-three: compiled into the library by cmake/embed_assets.cmake.
namespace amp::viz::detail {
extern const std::string_view kThreeJs;
extern const std::string_view kOrbitControlsJs;
extern const std::string_view kViewerJs;
extern const std::string_view kViewerHtml;
}  // namespace amp::viz::detail
