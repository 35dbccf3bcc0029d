#include "cli_util.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "amp/core/error.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/world/problem.hpp"

namespace amp::cli {

namespace {

CLI::Validator positive(bool integer) {
  return CLI::Validator(
      [integer](std::string& text) -> std::string {
        const char* begin = text.c_str();
        char* end = nullptr;
        const double v = std::strtod(begin, &end);
        const bool number = end != begin && *end == '\0' && std::isfinite(v);
        if (!number || !(v > 0.0) || (integer && v != std::floor(v))) {
          return std::string("expected a positive ") + (integer ? "integer" : "number") + ", got '" + text + "'";
        }
        return {};
      },
      integer ? "POSITIVE INTEGER" : "POSITIVE");
}

}  // namespace

CLI::Validator positive_number() { return positive(false); }
CLI::Validator positive_integer() { return positive(true); }

CLI::Validator unsigned_integer() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        std::uint64_t v = 0;
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, v);
        if (text.empty() || ec != std::errc() || ptr != end) {
          return "expected a whole number in 0..18446744073709551615, got '" + text + "'";
        }
        return {};
      },
      "UINT64");
}

std::string resolve_planner(const std::string& option, const world::Problem& problem) {
  if (!option.empty()) return option;
  const auto& registry = roadmap::builtin_planners();
  if (registry.contains(problem.defaults.planner)) return problem.defaults.planner;
  if (problem.file.extension() == ".cfg") {
    // OMPL.app files name OMPL's planners (rrtconnect, kpiece...): they must run unchanged, so
    // their planner falls back to ours, with a note.
    std::fprintf(stderr, "amp: note: %s: [solver] planner '%s' is not an AMP planner; using prm\n",
                 problem.file.string().c_str(), problem.defaults.planner.c_str());
    return "prm";
  }
  try {
    registry.info(problem.defaults.planner);
  } catch (const ParameterError& e) {
    throw FileError(problem.file.string() + ": defaults.planner: " + e.what());
  }
  return problem.defaults.planner;
}

core::ParamMap parse_params(const std::vector<std::string>& items) {
  core::ParamMap params;
  for (const std::string& item : items) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == item.size()) {
      throw ParameterError("--param: expected name=value, got '" + item + "'");
    }
    params.insert_or_assign(item.substr(0, eq), core::ParamValue(item.substr(eq + 1)));
  }
  return params;
}

std::filesystem::path problems_dir() {
  if (const char* env = std::getenv("AMP_PROBLEMS"); env != nullptr && *env != '\0') return env;
  std::error_code ec;
  if (std::filesystem::is_regular_file("problems/maze.yaml", ec)) return "problems";
  return std::filesystem::path(AMP_SOURCE_DIR) / "problems";
}

}  // namespace amp::cli
