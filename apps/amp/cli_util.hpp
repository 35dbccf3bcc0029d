#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "amp/roadmap/parameters.hpp"

namespace amp::cli {

// Exit codes: 0 solved/ok, 1 error (bad input), 2 ran fine but found no solution within the limits.
inline constexpr int kExitOk = 0;
inline constexpr int kExitError = 1;
inline constexpr int kExitNotSolved = 2;

// Refuses to overwrite an existing file unless `force` (nothing the user wrote is lost unasked);
// also refuses a directory or a path whose parent directory does not exist.
void check_writable(const std::filesystem::path& file, bool force, const std::string& option);

// Parses `--param name=value` items; values stay strings, the planner's specs type them.
roadmap::ParamMap parse_params(const std::vector<std::string>& items);

// The directory of the bundled problems: $AMP_PROBLEMS, ./problems, or the source tree's.
std::filesystem::path problems_dir();

}  // namespace amp::cli
