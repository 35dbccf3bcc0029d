// amp: the command line of the Adaptive Motion Planning library.
#include <cstdio>
#include <exception>
#include <string>

#include <CLI/CLI.hpp>

#include "amp/core/version.hpp"
#include "amp/core/error.hpp"
#include "cli_util.hpp"
#include "commands.hpp"

namespace {

// The error contract is one line on stderr; messages quoted from libraries (yaml-cpp, assimp,
// CLI11) may carry line breaks, so those become spaces here.
void print_error(const char* prefix, const char* what) {
  std::string line = what;
  for (char& c : line) c = (c == '\n' || c == '\r') ? ' ' : c;
  while (!line.empty() && line.back() == ' ') line.pop_back();
  std::fprintf(stderr, "amp: error: %s%s\n", prefix, line.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"amp: adaptive motion planning (PRM family, UAS, PGCS, policy search, SINS)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("amp ") + amp::core::kVersion);
  int exit_code = amp::cli::kExitOk;
  amp::cli::add_plan_command(app, exit_code);
  amp::cli::add_render_command(app, exit_code);
  amp::cli::add_view_command(app, exit_code);
  amp::cli::add_regions_command(app, exit_code);
  amp::cli::add_explore_command(app, exit_code);
  amp::cli::add_navigate_command(app, exit_code);
  amp::cli::add_sins_command(app, exit_code);
  amp::cli::add_bench_command(app, exit_code);
  amp::cli::add_demo_command(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    print_error("", e.what());
    return amp::cli::kExitError;
  } catch (const amp::Error& e) {
    print_error("", e.what());
    return amp::cli::kExitError;
  } catch (const std::exception& e) {
    print_error("internal: ", e.what());
    return amp::cli::kExitError;
  }
  return exit_code;
}
