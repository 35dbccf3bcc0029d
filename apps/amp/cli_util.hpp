#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "amp/core/parameters.hpp"
#include "amp/study/output_dir.hpp"

namespace amp::world {
struct Problem;
}

namespace amp::cli {

// Exit codes: 0 solved/ok, 1 error (bad input), 2 ran fine but found no solution within the limits.
inline constexpr int kExitOk = 0;
inline constexpr int kExitError = 1;
inline constexpr int kExitNotSolved = 2;

using study::check_writable;  // the one copy, shared with the studies (amp/study/output_dir.hpp)

// Option checks with one-line messages ("--time-limit: expected a positive number, got '0'");
// CLI11's PositiveNumber prints its range, up to a 300-digit DBL_MAX.
CLI::Validator positive_number();
CLI::Validator positive_integer();
// A whole number in 0..2^64-1 (seeds); CLI11 would wrap "-1" to 2^64-1 without a word.
CLI::Validator unsigned_integer();

// The planner to run: `option` (--planner) if given, else the problem's default, checked here so
// that a bad name in the problem file is reported at its field ("defaults.planner").
std::string resolve_planner(const std::string& option, const world::Problem& problem);

// Parses `--param name=value` items; values stay strings, the planner's specs type them.
core::ParamMap parse_params(const std::vector<std::string>& items);

// The directory of the bundled problems: $AMP_PROBLEMS, ./problems, or the source tree's.
std::filesystem::path problems_dir();

}  // namespace amp::cli
