#include "cli_util.hpp"

#include <cstdlib>

#include "amp/core/error.hpp"

namespace amp::cli {

void check_writable(const std::filesystem::path& file, bool force, const std::string& option) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) {
    throw Error(option + ": '" + file.string() + "' is a directory, expected a file name");
  }
  if (std::filesystem::exists(file, ec) && !force) {
    throw Error(option + ": '" + file.string() + "' already exists (use --force to overwrite it)");
  }
  const auto parent = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::is_directory(parent, ec)) {
    throw Error(option + ": directory '" + parent.string() + "' does not exist");
  }
}

roadmap::ParamMap parse_params(const std::vector<std::string>& items) {
  roadmap::ParamMap params;
  for (const std::string& item : items) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == item.size()) {
      throw ParameterError("--param: expected name=value, got '" + item + "'");
    }
    params.insert_or_assign(item.substr(0, eq), roadmap::ParamValue(item.substr(eq + 1)));
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
