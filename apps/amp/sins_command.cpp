// `amp sins`: SINS (Ram & Santamaria 1993): a sequence of clutter worlds driven by a disc under the
// motor schemas, the parameters chosen by the static, random, adaptive (case-based) or sins-plus system; prints
// the six estimators, draws the paper's Figures 4 and 5.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "amp/bench/sins_calibration.hpp"
#include "amp/core/error.hpp"
#include "amp/core/parameters.hpp"
#include "cli_util.hpp"
#include "commands.hpp"
#include "amp/study/sins_study.hpp"

namespace amp::cli {

namespace {

struct SinsOptions {
  std::string system = "adaptive";
  int worlds = nav::SinsSettings{}.worlds;
  double clutter = nav::ClutterWorldSettings{}.clutter;
  int max_cases = learn::CaseSettings{}.max_cases;
  int case_length = learn::CaseSettings{}.case_length;
  int control_interval = nav::SinsSettings{}.control_interval;
  int step_limit = nav::SinsSettings{}.step_limit;
  std::uint64_t seed = 1;
  std::string scale{nav::kCalibratedScale.name};
  bool calibrate = false;
  std::vector<std::string> params;
  std::string output;
  bool json = false;
  bool force = false;
  // The named options that are schema parameters, by schema name (they must not also come as --param).
  std::vector<std::pair<std::string, const CLI::Option*>> named;
  // Options --calibrate has no use for (it searches the scale and the step limit, prints, writes nothing).
  std::vector<const CLI::Option*> not_calibrated;
};

constexpr double kProgressAfterS = 1.0;  // short runs draw no bar (nothing to wait for)

// A bar on stderr while driving, only on a terminal: a pipe or a file (tests, scripts) gets
// stderr's one-line error contract untouched.
std::function<void(int, int)> progress_bar() {
  if (isatty(STDERR_FILENO) == 0) return {};
  const auto t0 = std::chrono::steady_clock::now();
  auto shown = std::make_shared<bool>(false);
  return [t0, shown](int done, int total) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (elapsed < kProgressAfterS && !*shown) return;
    *shown = true;
    constexpr int kWidth = 30;
    const double frac = total > 0 ? static_cast<double>(done) / total : 1.0;
    const int fill = static_cast<int>(frac * kWidth);
    const double remaining = done > 0 ? elapsed * (total - done) / done : 0.0;
    std::fprintf(stderr, "\r[%s%s] %d/%d worlds  elapsed %.0f s  remaining %.0f s ", std::string(fill, '#').c_str(),
                 std::string(kWidth - fill, '.').c_str(), done, total, elapsed, remaining);
    if (done >= total) std::fputc('\n', stderr);
    std::fflush(stderr);
  };
}

// A number in (0, 1), e.g. the clutter: the fraction of the box covered.
CLI::Validator open_unit_interval() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const char* begin = text.c_str();
        char* end = nullptr;
        const double v = std::strtod(begin, &end);
        if (end == begin || *end != '\0' || !(v > 0.0 && v < 1.0)) {
          return "expected a number in (0, 1), got '" + text + "'";
        }
        return {};
      },
      "(0, 1)");
}

// The settings: the defaults, then --param name=value (by the names of SinsSettings::schema(),
// SchemaParameters::schema() and CaseSettings::schema()), then the named options.
study::SinsSetup read_setup(const SinsOptions& o) {
  const core::ParamMap given = parse_params(o.params);
  for (const auto& [name, option] : o.named) {
    if (option->count() > 0 && given.contains(name)) {
      throw ParameterError(option->get_name() + ": also given as --param " + name + "=...; give it once");
    }
  }
  const nav::SinsScale* scale = nullptr;
  try {
    scale = &nav::sins_scale(o.scale);
  } catch (const ParameterError& e) {
    throw ParameterError(std::string("--scale: ") + e.what());
  }
  study::SinsSetup setup;
  try {
    study::read_sins_params(given, *scale, setup);
  } catch (const ParameterError& e) {
    throw ParameterError(std::string("--param: ") + e.what());
  }
  for (const auto& [name, option] : o.named) {
    if (option->count() == 0) continue;
    if (name == "worlds") setup.sins.worlds = o.worlds;
    if (name == "clutter") setup.sins.world.clutter = o.clutter;
    if (name == "control_interval") setup.sins.control_interval = o.control_interval;
    if (name == "step_limit") setup.sins.step_limit = o.step_limit;
    if (name == "max_cases") setup.cases.max_cases = setup.plus.max_cases = o.max_cases;
    if (name == "case_length") setup.cases.case_length = o.case_length;
  }
  try {
    setup.sins.validate();
    setup.cases.validate();
    setup.plus.validate();
    setup.initial.validate();
  } catch (const ParameterError& e) {
    // Named after the option that set the parameter the message names, else --param.
    const std::string what = e.what();
    std::string flag = "--param";
    for (const auto& [name, option] : o.named) {
      if (option->count() > 0 && what.find("'" + name + "'") != std::string::npos) flag = option->get_name();
    }
    throw ParameterError(flag + ": " + what);
  }
  setup.system = o.system;
  setup.seed = o.seed;
  return setup;
}

std::string fixed(double v, int digits) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", digits, v);
  return text;
}

std::string share_text(const bench::SolvedShare& s) {
  return fixed(100 * s.mean, 1) + "% [" + fixed(100 * s.ci95_low, 1) + ", " + fixed(100 * s.ci95_high, 1) + "]";
}

// `amp sins --calibrate`: bench::calibrate_sins_scale from the command's settings (its clutter, worlds,
// ...), each factor printed as it is measured. Not reaching the targets is an error (exit 1).
int run_calibration(const SinsOptions& o, const CLI::Option* seed_option) {
  const std::string unused = " (the calibration searches the scale and the step limit, and writes nothing)";
  for (const CLI::Option* option : o.not_calibrated) {
    if (option->count() > 0) throw ParameterError("--calibrate: " + option->get_name() + " is not taken with it" + unused);
  }
  for (const auto& [name, value] : parse_params(o.params)) {
    if (name == "step_limit" || name == "min_radius" || name == "max_radius") {
      throw ParameterError("--calibrate: --param " + name + " is not taken with it" + unused);
    }
  }
  bench::SinsCalibrationSettings c;
  c.base = read_setup(o).sins;
  if (seed_option->count() > 0) c.seed = o.seed;
  std::cout << "calibrating the scale (seed " << c.seed << ", " << c.search_sequences << " sequences of "
            << c.base.worlds << " worlds per factor): static " << fixed(100 * c.static_target, 1) << "%, random "
            << fixed(100 * c.random_target, 1) << "% solved at clutter " << c.base.world.clutter << '\n';
  const bench::SinsCalibration r = bench::calibrate_sins_scale(c, [](const bench::ScaleProbe& p) {
    std::cout << "  scale " << fixed(p.factor, 4) << ": step limit " << p.step_limit << ", random "
              << fixed(100 * p.random_solved, 1) << "%, static " << fixed(100 * p.static_solved, 1) << "%\n"
              << std::flush;
  });
  if (r.scale.step_limit > 0) {
    const nav::ClutterWorldSettings classic{};
    std::cout << "scale " << fixed(r.scale.factor, 2) << " (a " << fixed(classic.width * r.scale.factor, 1) << " m box, circles "
              << fixed(classic.min_radius * r.scale.factor, 3) << "-" << fixed(classic.max_radius * r.scale.factor, 3)
              << " m), step limit " << r.scale.step_limit << '\n';
  }
  if (!r.static_share.per_sequence.empty()) {
    std::cout << "check over " << c.sequences << " fresh sequences: static " << share_text(r.static_share)
              << ", random " << share_text(r.random_share) << '\n';
  }
  if (!r.reached) throw Error("--calibrate: " + r.why);
  std::cout << "reached: both targets inside their 95% intervals\n";
  return kExitOk;
}

int run_sins_command(const SinsOptions& o) {
  if (!o.output.empty()) study::check_sins_dir(o.output, o.force, "-o");
  study::SinsSetup setup = read_setup(o);
  setup.progress = progress_bar();
  // Figure 5 compares the three systems on the same worlds: with -o the other two run as well.
  const study::SinsResult result = study::run_sins(setup, !o.output.empty());
  if (o.json) {
    std::cout << result.record.dump(2) << '\n';
  } else {
    std::cout << study::format_sins_table(result.record);
    if (result.runs.size() > 1) std::cout << '\n' << study::format_sins_comparison(result);
  }
  if (!o.output.empty()) {
    study::write_sins_outputs(setup, result, o.output);
    if (!o.json) {
      std::cout << "written to " << o.output << "/:";
      for (const std::string& f : study::sins_output_files()) std::cout << ' ' << f;
      std::cout << '\n';
    }
  }
  // Unsolved worlds are a result (solved_fraction counts them), not a failure of the command.
  return kExitOk;
}

}  // namespace

void add_sins_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<SinsOptions>();
  CLI::App* cmd = app.add_subcommand("sins", "SINS (Ram & Santamaria): a disc driven by motor schemas through "
                                             "clutter worlds, the parameters static, random or adapted from cases; "
                                             "the six estimators, Figures 4 and 5");
  o->not_calibrated.push_back(
      cmd->add_option("--system", o->system, "How the schema parameters are chosen: static, random, adaptive (SINS) or sins-plus (AMP's "
                      "horizon credit and splitting cases, docs/sins.md) [adaptive]")
          ->check(CLI::IsMember({"static", "random", "adaptive", "sins-plus"})));
  o->named.emplace_back("worlds", cmd->add_option("--worlds", o->worlds, "Worlds in the sequence [" +
                                                                           std::to_string(o->worlds) + "]")
                                      ->check(positive_integer()));
  o->named.emplace_back("clutter", cmd->add_option("--clutter", o->clutter,
                                                   "Fraction of the box covered by circles, in (0, 1) [0.25]")
                                       ->check(open_unit_interval()));
  o->named.emplace_back("max_cases", cmd->add_option("--max-cases", o->max_cases,
                                                     "Adaptive and sins-plus: no case is created beyond this many [" +
                                                         std::to_string(o->max_cases) + "]")
                                         ->check(positive_integer()));
  o->named.emplace_back("case_length", cmd->add_option("--case-length", o->case_length,
                                                       "Adaptive: samples per case and per history [" +
                                                           std::to_string(o->case_length) + "]")
                                           ->check(positive_integer()));
  o->named.emplace_back("control_interval", cmd->add_option("--control-interval", o->control_interval,
                                                            "Steps between two choices of the parameters [" +
                                                                std::to_string(o->control_interval) + "]")
                                                ->check(positive_integer()));
  o->named.emplace_back("step_limit", cmd->add_option("--step-limit", o->step_limit,
                                                      "Steps per world before it counts as unsolved [the scale's: " +
                                                          std::to_string(o->step_limit) + " at the calibrated]")
                                          ->check(positive_integer()));
  o->not_calibrated.push_back(o->named.back().second);
  const CLI::Option* seed = cmd->add_option("--seed", o->seed,
                                            "Random seed (the worlds, and the robot's stream) [1; with --calibrate "
                                            "the calibration's own, " + std::to_string(bench::SinsCalibrationSettings{}.seed) + "]")
                                ->check(unsigned_integer());
  std::string scales;
  for (const nav::SinsScale& s : nav::kSinsScales) {
    scales += std::string(scales.empty() ? "" : "; ") + std::string(s.name) + ": " + std::string(s.what);
  }
  o->not_calibrated.push_back(cmd->add_option(
      "--scale", o->scale,
      "The worlds' scale against the robot and the step limit (" + scales + ") [" +
          std::string(nav::kCalibratedScale.name) + "]"));
  cmd->add_flag("--calibrate", o->calibrate,
                "Search the scale at which the static and random systems solve the paper's 14.5% and 41.5% "
                "(docs/sins.md, \"The calibrated scale\"); exit 1 if it cannot");
  cmd->add_option("--param", o->params,
                  "Run, schema or case parameter name=value (repeatable): obstacle_gain (the static system's and "
                  "where the adaptive starts), change_at, clutter_after, learning_rate, ...; an unknown name lists "
                  "them all");
  o->not_calibrated.push_back(cmd->add_option(
      "-o,--output", o->output,
      "Directory for record.json, learning.svg (Figure 5, every system run) and run.svg (Figure 4)"));
  o->not_calibrated.push_back(cmd->add_flag("--json", o->json, "Print the record as one flat JSON object"));
  o->not_calibrated.push_back(cmd->add_flag("--force", o->force, "Overwrite existing output files"));
  cmd->callback([o, seed, &exit_code] { exit_code = o->calibrate ? run_calibration(*o, seed) : run_sins_command(*o); });
}

}  // namespace amp::cli
