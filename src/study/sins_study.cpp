#include "amp/study/sins_study.hpp"

#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

#include "amp/core/error.hpp"
#include "amp/core/param_routing.hpp"
#include "amp/core/rng.hpp"
#include "amp/nav/sins/parameter_policy.hpp"
#include "amp/viz/scene_renderer.hpp"
#include "amp/viz/sins_figures.hpp"
#include "amp/study/output_dir.hpp"
#include "amp/study/record_json.hpp"

namespace amp::study {

namespace {

// The three systems of the paper, in the order of its figures.
const std::vector<std::string>& systems() {
  static const std::vector<std::string> s = {"static", "random", "adaptive"};
  return s;
}

// The systems run, in the paper's order, then any beyond the paper's (sins-plus, when chosen).
std::vector<std::string> figure_order(const SinsResult& r) {
  std::vector<std::string> order = systems();
  for (const SystemRun& run : r.runs) {
    if (std::find(order.begin(), order.end(), run.system) == order.end()) order.push_back(run.system);
  }
  return order;
}

// The worlds every system meets (nav::draw_sequence_worlds), a clutter no world can be drawn at
// reported naming the option that set it.
nav::SequenceWorlds draw_worlds(const SinsSetup& setup) {
  try {
    return nav::draw_sequence_worlds(setup.sins, setup.seed);
  } catch (const nav::SequenceDrawError& e) {
    throw ParameterError(std::string(e.after_change() ? "--param clutter_after" : "--clutter") + ": " + e.what());
  }
}

// One system over the drawn worlds: nav::run_sequence, the last world's trace kept.
SystemRun run_system(const SinsSetup& setup, const std::string& system, const nav::SequenceWorlds& worlds,
                     const std::function<void()>& world_done) {
  SystemRun run;
  run.system = system;
  const std::unique_ptr<nav::ParameterPolicy> policy =
      nav::make_parameter_policy(system, setup.cases, setup.initial, setup.sins.stall_exploration, setup.plus);
  nav::SequenceHooks hooks;
  hooks.last_trace = &run.last_trace;
  if (world_done) hooks.on_world = [&world_done](const nav::WorldOutcome&) { world_done(); };
  nav::SequenceOutcome outcome = nav::run_sequence(*policy, setup.sins, setup.seed, worlds, hooks);
  run.worlds = std::move(outcome.worlds);
  run.estimators = nav::estimate(run.worlds, run.worlds.size());
  run.cases = outcome.cases;
  return run;
}

nlohmann::ordered_json estimators_json(const nav::Estimators& e) {
  nlohmann::ordered_json j;
  j["worlds"] = e.worlds;
  j["solved_fraction"] = e.solved_fraction;
  j["steps_mean"] = e.steps_mean;
  j["distance_mean"] = e.distance_mean;
  j["distance_ratio_mean"] = e.distance_ratio_mean;
  j["virtual_collisions_mean"] = e.virtual_collisions_mean;
  j["time_per_world_ms_mean"] = e.time_per_world_ms_mean;
  return j;
}

nlohmann::ordered_json flat_record(const SinsSetup& setup, const SinsResult& r) {
  const SystemRun& run = r.runs.front();
  nlohmann::ordered_json j;
  j["system"] = run.system;
  j["seed"] = setup.seed;
  j["clutter"] = setup.sins.world.clutter;
  const nlohmann::ordered_json estimators = estimators_json(run.estimators);
  for (const auto& [key, value] : estimators.items()) j[key] = value;
  j["cases"] = run.cases;
  j["rejected_worlds"] = r.rejected_worlds;
  return j;
}

}  // namespace

nlohmann::ordered_json sins_record(const SinsSetup& setup, const SinsResult& r) {
  nlohmann::ordered_json j = r.record;
  nlohmann::ordered_json settings;
  settings["system"] = setup.system;
  settings["seed"] = setup.seed;
  for (const auto& [name, value] : nav::SinsSettings::schema().values(setup.sins)) settings[name] = param_json(value);
  settings["width"] = setup.sins.world.width;  // the box, which --scale sets (it is no parameter)
  settings["height"] = setup.sins.world.height;
  for (const auto& [name, value] : learn::CaseSettings::schema().values(setup.cases)) settings[name] = param_json(value);
  if (setup.system == "sins-plus") {
    for (const auto& [name, value] : learn::SplittingCaseSettings::schema().values(setup.plus)) {
      settings[name] = param_json(value);
    }
  }
  for (const auto& [name, value] : nav::SchemaParameters::schema().values(setup.initial)) {
    settings[name] = param_json(value);
  }
  j["settings"] = settings;
  nlohmann::ordered_json by_system;
  for (const SystemRun& run : r.runs) {
    nlohmann::ordered_json e = estimators_json(run.estimators);
    e["cases"] = run.cases;
    by_system[run.system] = e;
  }
  j["systems"] = by_system;
  nlohmann::ordered_json outcomes = nlohmann::ordered_json::array();
  for (const nav::WorldOutcome& w : r.runs.front().worlds) {
    outcomes.push_back({{"index", w.index},
                        {"solved", w.solved},
                        {"steps", w.steps},
                        {"distance", w.distance},
                        {"optimal", finite_or_null(w.optimal)},
                        {"virtual_collisions", w.virtual_collisions},
                        {"blocked", w.blocked},
                        {"min_clearance", w.min_clearance},
                        {"time_ms", w.time_ms},
                        {"clutter", w.clutter}});
  }
  j["world_outcomes"] = outcomes;
  return j;
}

namespace {

std::string number_text(const char* format, double x) {
  char buf[48];
  std::snprintf(buf, sizeof buf, format, x);
  return buf;
}

viz::SinsRunDrawing run_drawing(const SinsSetup& setup, const nav::ClutterWorld& world, const SystemRun& run) {
  viz::SinsRunDrawing d;
  d.width = setup.sins.world.width;
  d.height = setup.sins.world.height;
  d.circles = world.circles;
  d.start = world.start;
  d.goal = world.goal;
  d.robot_radius = setup.sins.world.robot_radius;
  d.goal_tolerance = setup.sins.goal_tolerance;
  d.positions = run.last_trace.positions;
  for (const nav::SchemaParameters& p : run.last_trace.parameters) d.parameters.push_back(p.normalised());
  using P = nav::SchemaParameters;
  const auto name = [](const char* n, P::Range r) {
    return std::string(n) + " [" + number_text("%g", r.lo) + ", " + number_text("%g", r.hi) + "]";
  };
  d.parameter_names = {name("obstacle gain", P::kObstacleGain), name("goal gain", P::kGoalGain),
                       name("noise gain", P::kNoiseGain), name("noise persistence", P::kNoisePersistence)};
  d.solved = !run.worlds.empty() && run.worlds.back().solved;
  return d;
}

}  // namespace

void read_sins_params(const core::ParamMap& params, const nav::SinsScale& scale, SinsSetup& setup) {
  const auto& sins_schema = nav::SinsSettings::schema();
  const auto& motor_schema = nav::SchemaParameters::schema();
  const auto& case_schema = learn::CaseSettings::schema();
  const auto& plus_schema = learn::SplittingCaseSettings::schema();
  // max_cases goes to the cases and to sins-plus, as both declare it.
  std::vector<core::ParamMap> routed = core::route_params(
      params, {&sins_schema.specs(), &motor_schema.specs(), &case_schema.specs(), &plus_schema.specs()});
  // The scale's step limit and radii, unless given; its box after reading (the box is no parameter).
  nav::SinsSettings scaled;
  scaled.set_scale(scale);
  routed[0].try_emplace("step_limit", static_cast<double>(scaled.step_limit));
  routed[0].try_emplace("min_radius", scaled.world.min_radius);
  routed[0].try_emplace("max_radius", scaled.world.max_radius);
  setup.sins = sins_schema.read(core::Params(sins_schema.owner(), sins_schema.specs(), routed[0]));
  setup.initial = motor_schema.read(core::Params(motor_schema.owner(), motor_schema.specs(), routed[1]));
  setup.cases = case_schema.read(core::Params(case_schema.owner(), case_schema.specs(), routed[2]));
  setup.plus = plus_schema.read(core::Params(plus_schema.owner(), plus_schema.specs(), routed[3]));
  setup.sins.world.width = scaled.world.width;
  setup.sins.world.height = scaled.world.height;
}

SinsResult run_sins(const SinsSetup& setup, bool all_systems) {
  SinsResult r;
  nav::SequenceWorlds drawn = draw_worlds(setup);
  std::vector<std::string> order = {setup.system};
  if (all_systems) {
    for (const std::string& s : systems()) {
      if (s != setup.system) order.push_back(s);
    }
  }
  const int total = static_cast<int>(drawn.worlds.size() * order.size());
  int done = 0;
  std::function<void()> world_done;
  if (setup.progress) world_done = [&] { setup.progress(++done, total); };
  for (const std::string& s : order) r.runs.push_back(run_system(setup, s, drawn, world_done));
  r.worlds = std::move(drawn.worlds);
  r.rejected_worlds = drawn.rejected;
  r.record = flat_record(setup, r);
  return r;
}

const std::vector<std::string>& sins_output_files() {
  static const std::vector<std::string> files = {"record.json", "learning.svg", "run.svg"};
  return files;
}

void check_sins_dir(const std::filesystem::path& dir, bool force, const std::string& option) {
  check_output_dir(dir, sins_output_files(), force, option);
}

void write_sins_outputs(const SinsSetup& setup, const SinsResult& r, const std::filesystem::path& dir) {
  create_output_dir(dir);
  viz::write_text_file((dir / "record.json").string(), sins_record(setup, r).dump(2) + "\n");

  // Figure 5 in the paper's order of the systems, whichever was chosen.
  std::vector<viz::SinsCurves> curves;
  for (const std::string& s : figure_order(r)) {
    for (const SystemRun& run : r.runs) {
      if (run.system != s) continue;
      viz::SinsCurves c{run.system, {}};
      for (const nav::Estimators& e : nav::cumulative_estimates(run.worlds)) {
        c.points.push_back({e.solved_fraction, e.steps_mean, e.distance_mean, e.distance_ratio_mean,
                            e.virtual_collisions_mean, e.time_per_world_ms_mean});
      }
      curves.push_back(std::move(c));
    }
  }
  const std::string settings_text = std::to_string(r.worlds.size()) + " worlds, clutter " +
                                    number_text("%g", setup.sins.world.clutter) + ", seed " +
                                    std::to_string(setup.seed);
  viz::write_text_file((dir / "learning.svg").string(),
                       viz::sins_learning_svg(curves, "SINS: static, random and adaptive systems, " + settings_text));

  const SystemRun& chosen = r.runs.front();
  const nav::ClutterWorld& last = r.worlds.back();
  const nav::WorldOutcome& outcome = chosen.worlds.back();
  const std::string run_title = "SINS " + chosen.system + ": world " + std::to_string(r.worlds.size()) + " of " +
                                std::to_string(r.worlds.size()) + " (clutter " +
                                number_text("%.1f", 100.0 * last.clutter) + "%), " +
                                (outcome.solved ? "solved in " : "unsolved after ") + std::to_string(outcome.steps) +
                                " steps, seed " + std::to_string(setup.seed);
  viz::write_text_file((dir / "run.svg").string(), viz::sins_run_svg(run_drawing(setup, last, chosen), run_title));
}

std::string format_sins_table(const nlohmann::ordered_json& record) {
  std::ostringstream out;
  for (const auto& [key, value] : record.items()) {
    char line[96];
    if (value.is_number_float()) {
      std::snprintf(line, sizeof line, "  %-26s %.4g\n", key.c_str(), value.get<double>());
    } else {
      const std::string text = value.is_string() ? value.get<std::string>() : value.dump();
      std::snprintf(line, sizeof line, "  %-26s %s\n", key.c_str(), text.c_str());
    }
    out << line;
  }
  return out.str();
}

std::string format_sins_comparison(const SinsResult& r) {
  std::ostringstream out;
  char line[160];
  std::snprintf(line, sizeof line, "  %-9s %7s %9s %10s %10s %10s %10s %6s\n", "system", "solved", "steps",
                "distance", "ratio", "virt.coll", "ms/world", "cases");
  out << line;
  for (const std::string& s : figure_order(r)) {
    for (const SystemRun& run : r.runs) {
      if (run.system != s) continue;
      const nav::Estimators& e = run.estimators;
      std::snprintf(line, sizeof line, "  %-9s %7.3f %9.1f %10.2f %10.3f %10.2f %10.2f %6d\n", s.c_str(),
                    e.solved_fraction, e.steps_mean, e.distance_mean, e.distance_ratio_mean, e.virtual_collisions_mean,
                    e.time_per_world_ms_mean, run.cases);
      out << line;
    }
  }
  return out.str();
}

}  // namespace amp::study
