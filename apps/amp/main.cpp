// amp: the command line of the Adaptive Motion Planning library.
#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>

#include "amp/core/error.hpp"
#include "cli_util.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"amp: adaptive motion planning (PRM family, UAS, PGCS, policy search, SINS)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "amp 0.1.0");
  int exit_code = amp::cli::kExitOk;
  amp::cli::add_plan_command(app, exit_code);
  amp::cli::add_render_command(app, exit_code);
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
    std::fprintf(stderr, "amp: error: %s\n", e.what());
    return amp::cli::kExitError;
  } catch (const amp::Error& e) {
    std::fprintf(stderr, "amp: error: %s\n", e.what());
    return amp::cli::kExitError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "amp: error: internal: %s\n", e.what());
    return amp::cli::kExitError;
  }
  return exit_code;
}
