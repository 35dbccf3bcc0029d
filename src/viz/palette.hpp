#pragma once
// The colours every figure shares, so that a start, a goal or a driven path looks the same in all
// of them (internal to viz).
namespace amp::viz::palette {

inline constexpr const char* kText = "#1f2933";
inline constexpr const char* kAxisColor = "#52606d";
inline constexpr const char* kGridColor = "#e4e7eb";
inline constexpr const char* kPathColor = "#2563eb";
inline constexpr const char* kStartColor = "#1b9e77";
inline constexpr const char* kGoalColor = "#d95f02";
inline constexpr const char* kStopColor = "#b91c1c";

}  // namespace amp::viz::palette
