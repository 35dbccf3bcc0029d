// The runs of `amp navigate`, shared with `amp demo`: both methods of the policy-search paper on
// the same seeds, Table 2, and the paper's Figures 3 and 4.
#include "amp/study/navigate_study.hpp"

#include <algorithm>
#include <cstdio>

#include "amp/core/error.hpp"
#include "amp/core/param_routing.hpp"
#include "amp/core/rng.hpp"
#include "amp/nav/drive_settings.hpp"
#include "amp/nav/footprint.hpp"
#include "amp/nav/nav_task.hpp"
#include "amp/nav/navigator_catalog.hpp"
#include "amp/stats/descriptive.hpp"
#include "amp/study/navigation_run.hpp"
#include "amp/study/output_dir.hpp"
#include "amp/viz/policy_figures.hpp"
#include "amp/viz/scene_renderer.hpp"

namespace amp::study {

namespace {

constexpr double kRunTimeLimitS = 600.0;  // CPU seconds per run; simulated time has its own limit (max_time)

// The median of the runs (there is at least one).
double median(const std::vector<double>& x) { return stats::median(x).value_or(0.0); }

// The parameters in `params` that `method` declares: a parameter meant for one method is not an
// error for the other, which runs beside it for Table 2.
core::ParamMap declared_params(const std::string& method, const core::ParamMap& params) {
  const NavigateParams routed = route_navigate_params(params);
  return method == kPolicyMethod ? routed.policy : routed.dwa;
}

MethodRuns run_method(const world::Problem& problem, const std::string& method, const NavigateSetup& setup) {
  const core::ParamMap params = declared_params(method, setup.params);
  MethodRuns m;
  std::vector<double> planning, execution, distance;
  double min_clearance = 0.0, collisions = 0.0, waypoints = 0.0;
  int solved = 0;
  for (int i = 0; i < setup.runs; ++i) {
    const std::uint64_t seed = core::derive_seed(setup.seed, static_cast<std::uint64_t>(i));
    nav::NavigationOutcome out = run_navigation(problem, method, params, seed, kRunTimeLimitS);
    const core::RunRecord& r = out.record;
    if (r.status == core::PlanStatus::kError) throw Error(method + ": " + r.message);
    if (!out.drive) throw Error(method + ": drives to no goal (Table 2 compares policy-search and dwa)");
    const nav::DriveSummary& d = *out.drive;
    // Numbers as the record's extras hold them (doubles), so record.json reads as before.
    const double contacts = static_cast<double>(d.collisions);
    solved += d.arrived ? 1 : 0;
    planning.push_back(out.planning_time_s);
    execution.push_back(d.execution_time_s);
    distance.push_back(d.distance);
    collisions += contacts;
    min_clearance = i == 0 ? d.min_clearance : std::min(min_clearance, d.min_clearance);
    if (d.waypoints) waypoints = static_cast<double>(*d.waypoints);
    m.runs.push_back({{"seed", seed},
                      {"arrived", d.arrived},
                      {"planning_time_s", out.planning_time_s},
                      {"execution_time_s", d.execution_time_s},
                      {"distance", d.distance},
                      {"min_clearance", d.min_clearance},
                      {"collisions", contacts},
                      {"speeds", out.speeds}});
    if (i == 0) {  // the figures show one run, as the paper's do
      m.stages = std::move(out.stages);
      m.speeds = std::move(out.speeds);
      m.trace = std::move(out.trace);
      m.arrived = d.arrived;
    }
  }
  m.record = {{"method", method},
              {"problem", problem.name},
              {"seed", setup.seed},
              {"runs", setup.runs},
              {"solved_runs", solved},
              {"collisions_total", collisions},
              {"planning_time_median_s", median(planning)},
              {"execution_time_median_s", median(execution)},
              {"distance_median", median(distance)},
              {"min_clearance_min", min_clearance},
              {"waypoints", waypoints}};
  return m;
}

// The drive settings policy search ran with (shared with DWA): the figures' footprint and time step.
nav::DriveSettings drive_settings(const NavigateSetup& setup) {
  const core::ParamMap drive = declared_params(kPolicyMethod, setup.params);
  const auto& schema = nav::DriveSettings::schema();
  return schema.read(core::Params(kPolicyMethod, schema.specs(), drive));
}

viz::PolicyPhasesDrawing phases_drawing(const world::Problem& problem, const MethodRuns& policy,
                                        const nav::DriveSettings& drive) {
  viz::PolicyPhasesDrawing d;
  for (const nav::PlanStage& s : policy.stages) d.phases.push_back({s.name, s.points, s.waypoints, s.value});
  const nav::NavTask task = nav::make_nav_task(problem);
  d.start = task.start;
  d.goal = task.goal;
  const nav::Footprint footprint = drive.footprint(task.robot_radius);
  d.footprint = {footprint.length(), footprint.width(), footprint.is_disc()};
  d.trace = policy.trace;
  d.arrived = policy.arrived;
  return d;
}

}  // namespace

NavigateParams route_navigate_params(const core::ParamMap& params) {
  const auto& catalog = nav::builtin_navigators();
  std::vector<core::ParamMap> routed =
      core::route_params(params, {&catalog.info(kPolicyMethod).params, &catalog.info(kDwaMethod).params});
  return {std::move(routed[0]), std::move(routed[1])};
}

const std::vector<std::string>& navigate_output_files() {
  static const std::vector<std::string> files = {"record.json", "phases.svg", "velocity.svg"};
  return files;
}

NavigateResult run_both_methods(const world::Problem& problem, const NavigateSetup& setup) {
  NavigateResult r;
  r.policy = run_method(problem, kPolicyMethod, setup);
  r.dwa = run_method(problem, kDwaMethod, setup);
  return r;
}

std::string format_table2(const NavigateResult& r, const NavigateSetup& setup) {
  std::string out;
  char line[256];
  std::snprintf(line, sizeof line, "Table 2: %d noisy run(s) per method, seeds from %llu (medians; clearance: the minimum)\n",
                setup.runs, static_cast<unsigned long long>(setup.seed));
  out += line;
  std::snprintf(line, sizeof line, "  %-14s %8s %10s %11s %12s %11s %16s %10s\n", "method", "arrived", "contacts",
                "planning s", "execution s", "distance m", "min clearance m", "waypoints");
  out += line;
  for (const MethodRuns* m : {&r.policy, &r.dwa}) {
    const nlohmann::json& j = m->record;
    const std::string arrived = std::to_string(j["solved_runs"].get<int>()) + "/" + std::to_string(setup.runs);
    std::snprintf(line, sizeof line, "  %-14s %8s %10.0f %11.3f %12.1f %11.2f %16.3f %10.0f\n",
                  j["method"].get<std::string>().c_str(), arrived.c_str(), j["collisions_total"].get<double>(),
                  j["planning_time_median_s"].get<double>(), j["execution_time_median_s"].get<double>(),
                  j["distance_median"].get<double>(), j["min_clearance_min"].get<double>(),
                  j["waypoints"].get<double>());
    out += line;
  }
  return out;
}

nlohmann::json navigate_record(const NavigateResult& r, const std::string& method, const NavigateSetup& setup) {
  const MethodRuns& chosen = method == kPolicyMethod ? r.policy : r.dwa;
  nlohmann::json full = chosen.record;
  full["params"] = nlohmann::json::object();
  for (const auto& [name, value] : setup.params) full["params"][name] = value.to_string();
  full["table2"] = nlohmann::json::array({r.policy.record, r.dwa.record});
  full["run_details"] = chosen.runs;
  return full;
}

void write_navigate_outputs(const world::Problem& problem, const NavigateResult& r, const std::string& method,
                            const NavigateSetup& setup, const std::filesystem::path& dir) {
  create_output_dir(dir);
  viz::write_text_file((dir / "record.json").string(), navigate_record(r, method, setup).dump(2) + "\n");
  const nav::DriveSettings drive = drive_settings(setup);
  viz::write_text_file((dir / "phases.svg").string(),
                       viz::policy_phases_svg(problem, phases_drawing(problem, r.policy, drive),
                                              problem.name + ": policy search, the phases of Table 1 (first seed)"));
  viz::write_text_file((dir / "velocity.svg").string(),
                       viz::velocity_profiles_svg({{"policy search", r.policy.speeds}, {"DWA", r.dwa.speeds}},
                                                  drive.time_step,
                                                  problem.name + ": velocity profiles (first seed)"));
}

}  // namespace amp::study
