// `import amp`: AMP from Python (pybind11). Problems, planner runs, navigation runs and benchmark
// experiments, with AMP's records as dicts and paths as NumPy arrays when NumPy is present (lists of
// states otherwise). AMP's errors arrive as amp.Error (a RuntimeError) with the same one-line message.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "amp/bench/bench_runner.hpp"
#include "amp/bench/experiment.hpp"
#include "amp/bench/record_format.hpp"
#include "amp/core/error.hpp"
#include "amp/core/version.hpp"
#include "amp/nav/navigator_catalog.hpp"
#include "amp/nav/sins/parameter_policy.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/roadmap/run.hpp"
#include "amp/study/explore_study.hpp"
#include "amp/study/navigate_study.hpp"
#include "amp/study/navigation_run.hpp"
#include "amp/study/sins_study.hpp"
#include "amp/viz/viewer_page.hpp"
#include "amp/world/arm_problem.hpp"
#include "amp/world/problem.hpp"

namespace py = pybind11;

namespace {

// A record as a Python dict (through its JSON form, so that Python sees what `amp plan --json` prints).
py::object to_dict(const amp::core::RunRecord& r) {
  return py::module_::import("json").attr("loads")(amp::bench::to_json(r).dump());
}

// States as rows: a NumPy array when NumPy imports, else a list of lists.
py::object states(const std::vector<std::vector<double>>& rows) {
  py::list list;
  for (const auto& row : rows) list.append(py::cast(row));
  try {
    return py::module_::import("numpy").attr("array")(list);
  } catch (const py::error_already_set&) {
    return list;
  }
}

std::vector<double> as_vector(const amp::State& s) { return std::vector<double>(s.data(), s.data() + s.size()); }

amp::core::ParamMap params_of(const py::dict& params) {
  amp::core::ParamMap out;
  for (const auto& [key, value] : params) {
    const std::string name = py::str(key);
    if (py::isinstance<py::bool_>(value)) {
      out.emplace(name, amp::core::ParamValue(std::string(value.cast<bool>() ? "true" : "false")));
    } else if (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value)) {
      out.emplace(name, amp::core::ParamValue(value.cast<double>()));
    } else {
      out.emplace(name, amp::core::ParamValue(std::string(py::str(value))));
    }
  }
  return out;
}

py::tuple plan(const amp::world::Problem& problem, const std::string& planner, std::uint64_t seed,
               const py::dict& params, std::optional<double> time_limit, std::optional<std::size_t> node_limit) {
  const amp::core::ParamMap p = params_of(params);
  amp::roadmap::RunOutcome run;
  {
    py::gil_scoped_release free;  // a run may take seconds: let other Python threads go on
    run = amp::roadmap::execute_run(problem, planner.empty() ? problem.defaults.planner : planner, p, seed,
                                    time_limit.value_or(problem.defaults.time_limit_s), node_limit);
  }
  std::vector<std::vector<double>> path;
  for (const amp::State& s : run.path) path.push_back(as_vector(s));
  return py::make_tuple(to_dict(run.record), states(path));
}

// `amp view` from Python: the 3-D viewer page of a problem and a path (checked, as the command
// checks a path file), as HTML text, e.g. for IPython.display.HTML or a file.
std::string viewer_page(const amp::world::Problem& problem, const std::vector<std::vector<double>>& path,
                        const std::string& title, const std::string& subtitle) {
  std::vector<amp::State> states_of_path;
  for (const std::vector<double>& row : path) {
    if (static_cast<int>(row.size()) != problem.space->dimension()) {
      throw amp::Error("path: a state has " + std::to_string(row.size()) + " values, the problem's space " +
                       std::to_string(problem.space->dimension()));
    }
    states_of_path.push_back(Eigen::Map<const Eigen::VectorXd>(row.data(), static_cast<Eigen::Index>(row.size())));
  }
  amp::viz::ViewerContent content = amp::viz::path_content(problem, std::move(states_of_path), subtitle);
  content.title = title;
  py::gil_scoped_release free;
  return amp::viz::viewer_page(problem, content);
}

// A JSON document as Python objects (what `json.loads` makes of it).
py::object from_json(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

py::object points(const std::vector<Eigen::Vector2d>& ps) {
  std::vector<std::vector<double>> rows;
  for (const Eigen::Vector2d& q : ps) rows.push_back({q.x(), q.y()});
  return states(rows);
}

// `amp navigate` from Python (study::run_both_methods, the same runs on the same seeds): its
// record.json as a dict (the chosen method's Table 2 row, "table2", "run_details", "params"), plus
// "phases" (policy search's plan stages on the first seed: Figure 3), "speeds" (both methods'
// velocity profiles on the first seed: Figure 4) and "trace" (the chosen method's first driven trace).
py::dict navigate_study(const amp::world::Problem& problem, const std::string& method, std::uint64_t seed,
                        const py::dict& params, int runs) {
  namespace study = amp::study;
  if (method != study::kPolicyMethod && method != study::kDwaMethod) {
    throw amp::ParameterError("runs: Table 2 compares policy-search and dwa; '" + method +
                              "' runs once (leave runs at 0)");
  }
  study::NavigateSetup setup;
  setup.runs = runs;
  setup.seed = seed;
  setup.params = params_of(params);
  study::route_navigate_params(setup.params);
  study::NavigateResult r;
  {
    py::gil_scoped_release free;
    r = study::run_both_methods(problem, setup);
  }
  py::dict d = from_json(study::navigate_record(r, method, setup).dump());
  py::list phases;
  for (const amp::nav::PlanStage& s : r.policy.stages) {
    py::dict stage;
    stage["name"] = s.name;
    stage["points"] = points(s.points);
    stage["waypoints"] = s.waypoints;
    stage["value"] = s.value ? py::object(py::float_(*s.value)) : py::object(py::none());
    phases.append(stage);
  }
  d["phases"] = phases;
  py::dict speeds;
  speeds[study::kPolicyMethod] = r.policy.speeds;
  speeds[study::kDwaMethod] = r.dwa.speeds;
  d["speeds"] = speeds;
  d["trace"] = points(method == study::kPolicyMethod ? r.policy.trace : r.dwa.trace);
  return d;
}

py::object navigate(const amp::world::Problem& problem, const std::string& method, std::uint64_t seed,
                    const py::dict& params, double time_limit, int runs) {
  if (runs < 0) throw amp::ParameterError("runs: expected 0 (one run) or a positive count, got " + std::to_string(runs));
  if (runs > 0) return navigate_study(problem, method, seed, params, runs);
  const amp::core::ParamMap p = params_of(params);
  amp::nav::NavigationOutcome run;
  {
    py::gil_scoped_release free;
    run = amp::study::run_navigation(problem, method, p, seed, time_limit);
  }
  std::vector<std::vector<double>> trace;
  for (const Eigen::Vector2d& q : run.trace) trace.push_back({q.x(), q.y()});
  return py::make_tuple(to_dict(run.record), states(trace));
}

// `amp explore` from Python (study::run_exploration): its record.json as a dict.
py::object explore(const amp::world::Problem& problem, std::uint64_t seed, const py::dict& params) {
  amp::study::ExploreSetup setup;
  amp::study::read_explore_params(params_of(params), setup);
  setup.seed = seed;
  std::string record;
  {
    py::gil_scoped_release free;
    record = amp::study::explore_record(amp::study::run_exploration(problem, setup)).dump();
  }
  return from_json(record);
}

// `amp sins` from Python (study::run_sins): its record.json as a dict; with all_systems, the
// paper's three systems (and `system`) on the same worlds, as `amp sins -o` runs them.
py::object sins(const std::string& system, std::uint64_t seed, const py::dict& params, const std::string& scale,
                bool all_systems) {
  amp::study::SinsSetup setup;
  amp::study::read_sins_params(params_of(params), amp::nav::sins_scale(scale), setup);
  // An unknown system: one line, before any world is drawn.
  amp::nav::make_parameter_policy(system, setup.cases, setup.initial, setup.sins.stall_exploration, setup.plus);
  setup.system = system;
  setup.seed = seed;
  std::string record;
  {
    py::gil_scoped_release free;
    record = amp::study::sins_record(setup, amp::study::run_sins(setup, all_systems)).dump();
  }
  return from_json(record);
}

py::dict bench(const std::string& experiment, const std::string& out, int threads, bool force) {
  const amp::bench::Experiment e = amp::bench::load_experiment(experiment);
  amp::bench::BenchOptions o;
  o.out_dir = out;
  o.threads = threads;
  o.force = force;
  amp::bench::BenchResult r;
  {
    py::gil_scoped_release free;
    r = amp::bench::run_experiment(e, o);
  }
  py::dict d;
  d["runs"] = r.written;
  d["out"] = out;
  d["runs_csv"] = out + "/runs.csv";
  d["summary"] = py::module_::import("json").attr("load")(
      py::module_::import("builtins").attr("open")(out + "/summary.json"));
  return d;
}

}  // namespace

PYBIND11_MODULE(amp, m) {
  m.doc() = "AMP, adaptive motion planning: problems, planners, navigation methods and benchmarks";
  m.attr("__version__") = std::string(amp::core::kVersion);
  static py::exception<amp::Error> error(m, "Error", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const amp::Error& e) {
      error(e.what());
    }
  });

  py::class_<amp::world::Problem>(m, "Problem", "A loaded planning problem (amp.load_problem)")
      .def_readonly("name", &amp::world::Problem::name)
      .def_property_readonly("file", [](const amp::world::Problem& p) { return p.file.string(); })
      .def_property_readonly("dimension", [](const amp::world::Problem& p) { return p.space->dimension(); })
      .def_property_readonly("start", [](const amp::world::Problem& p) { return as_vector(p.start()); })
      .def_property_readonly("goal", [](const amp::world::Problem& p) { return as_vector(p.goal()); })
      .def("__repr__", [](const amp::world::Problem& p) { return "<amp.Problem '" + p.name + "'>"; });

  m.def(
      "load_problem",
      [](const std::string& path, const std::string& collision, const std::string& spheres) {
        amp::world::ProblemOverrides o{collision, spheres, amp::world::default_sphere_cache_dir()};
        if (o.collision.empty() && !spheres.empty()) o.collision = "spheres";
        return amp::world::load_problem(path, o);
      },
      py::arg("path"), py::arg("collision") = "", py::arg("spheres") = "",
      "Loads a problem file (YAML or OMPL.app .cfg); an arm's collision model 'meshes' or 'spheres' (and a spherized "
      "URDF) over the file's, as amp plan --collision --spheres; raises amp.Error naming the file and field");
  m.def(
      "load_arm_problem",
      [](const std::string& urdf, const std::string& srdf, const std::string& scene, const std::string& request,
         const std::vector<std::string>& package_paths, const std::string& collision, const std::string& spheres) {
        amp::world::ArmFiles files{urdf, srdf, scene, request, {}, {}};
        for (const std::string& p : package_paths) files.package_paths.emplace_back(p);
        files.collision.model = amp::world::parse_arm_collision(collision.empty() && !spheres.empty() ? "spheres" : collision.empty() ? "meshes" : collision, "collision");
        files.collision.spheres = spheres;
        files.collision.cache_dir = amp::world::default_sphere_cache_dir();
        return amp::world::load_arm_problem(files);
      },
      py::arg("urdf"), py::arg("srdf"), py::arg("scene"), py::arg("request"), py::arg("package_paths") = std::vector<std::string>{},
      py::arg("collision") = "", py::arg("spheres") = "",
      "Loads an arm problem from a MoveIt user's files (as amp plan --urdf --srdf --scene --request)");
  m.def("plan", &plan, py::arg("problem"), py::arg("planner") = "prm", py::arg("seed") = 1,
        py::arg("params") = py::dict(), py::arg("time_limit") = py::none(), py::arg("node_limit") = py::none(),
        "Runs a planner once: (record as a dict, path as an array of states; empty when unsolved)");
  m.def("navigate", &navigate, py::arg("problem"), py::arg("method"), py::arg("seed") = 1,
        py::arg("params") = py::dict(), py::arg("time_limit") = 600.0, py::arg("runs") = 0,
        "Runs a navigation method once (pgcs, policy-search, dwa, static, random, sins, sins-plus): (record, driven "
        "trace); with runs=N (policy-search or dwa), `amp navigate`: both methods on N seeds, its record.json as a dict "
        "with Table 2 ('table2'), each run ('run_details'), policy search's phases ('phases'), the velocity profiles "
        "('speeds') and the first driven trace ('trace')");
  m.def("explore", &explore, py::arg("problem"), py::arg("seed") = 1, py::arg("params") = py::dict(),
        "`amp explore`: PGCS exploration, then the queries; its record.json as a dict (params: steps, queries, "
        "exploration, max_clusters, ...)");
  m.def("sins", &sins, py::arg("system") = "adaptive", py::arg("seed") = 1, py::arg("params") = py::dict(),
        py::arg("scale") = "calibrated", py::arg("all_systems") = false,
        "`amp sins`: a system over a sequence of clutter worlds; its record.json as a dict (params: worlds, clutter, "
        "max_cases, ...)");
  m.def("bench", &bench, py::arg("experiment"), py::arg("out"), py::arg("threads") = 0, py::arg("force") = false,
        "Runs an experiment file as `amp bench` does; returns the run count and summary.json as a dict");
  m.def("viewer_page", &viewer_page, py::arg("problem"), py::arg("path") = std::vector<std::vector<double>>{},
        py::arg("title") = "", py::arg("subtitle") = "",
        "`amp view`: the interactive 3-D page (HTML text) of a problem with the robot playing `path` (states as rows; "
        "empty: the robot at the start); the page says whether the path is certified collision-free");
  m.def("planners", [] { return amp::roadmap::builtin_planners().names(); }, "The planners' names");
  m.def("navigation_methods", [] { return amp::nav::builtin_navigators().names(); }, "The navigation methods' names");
}
