#pragma once
#include <CLI/CLI.hpp>

namespace amp::cli {

// Each command adds its sub-command and options to the app and runs when it is chosen. A command
// returns the process exit code; errors are thrown as amp::Error and printed by main().
void add_plan_command(CLI::App& app, int& exit_code);
void add_render_command(CLI::App& app, int& exit_code);
void add_view_command(CLI::App& app, int& exit_code);
void add_demo_command(CLI::App& app, int& exit_code);
void add_bench_command(CLI::App& app, int& exit_code);  // also `amp merge`
void add_regions_command(CLI::App& app, int& exit_code);
void add_explore_command(CLI::App& app, int& exit_code);
void add_navigate_command(CLI::App& app, int& exit_code);
void add_sins_command(CLI::App& app, int& exit_code);

}  // namespace amp::cli
