#include "amp/bench/experiment.hpp"

#include "amp/world/arm_problem.hpp"

#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <system_error>
#include <type_traits>

#include "amp/bench/cost_metric.hpp"
#include "amp/bench/method_runner.hpp"
#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/nav/nav_task.hpp"
#include "amp/nav/navigator_catalog.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/roadmap/run.hpp"
#include "amp/world/problem.hpp"
#include "amp/world/yaml_fields.hpp"

namespace amp::bench {

namespace {

// FNV-1a, 64 bit: a stated, portable string hash for seeds and fingerprints.
std::uint64_t fnv1a(std::string_view s, std::uint64_t h = 0xcbf29ce484222325ULL) {
  for (unsigned char c : s) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  return h;
}

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

core::ParamValue param_value(const YAML::Node& n) { return core::ParamValue(n.Scalar()); }

PlannerConfig parse_planner(const world::YamlFields& f) {
  PlannerConfig c;
  if (f.node().IsScalar()) {
    c.planner = f.node().Scalar();
    c.label = c.planner;
    return c;
  }
  f.allow_only({"name", "planner", "params", "draw"});
  c.planner = f.string("planner");
  c.label = f.string("name", c.planner);
  if (f.has("params")) {
    const world::YamlFields p = f.child("params");
    if (!p.is_map()) p.fail("", "expected a mapping of parameter: value");
    for (const auto& kv : p.node()) {
      if (!kv.second.IsScalar()) p.fail(kv.first.Scalar(), "expected a single value");
      c.params.insert_or_assign(kv.first.Scalar(), param_value(kv.second));
    }
  }
  if (f.has("draw")) {
    const world::YamlFields d = f.child("draw");
    if (!d.is_map()) d.fail("", "expected a mapping of parameter: [values]");
    for (const auto& kv : d.node()) {
      const world::YamlFields values = d.child(kv.first.Scalar());
      if (values.size() == 0) values.fail("", "expected at least one value to draw from");
      std::vector<core::ParamValue> list;
      for (std::size_t i = 0; i < values.size(); ++i) {
        if (!values.node()[i].IsScalar()) values.fail("", "expected a list of values");
        list.push_back(param_value(values.node()[i]));
      }
      if (c.params.count(kv.first.Scalar()) != 0) d.fail(kv.first.Scalar(), "is both fixed (params) and drawn");
      c.draws.emplace(kv.first.Scalar(), std::move(list));
    }
  }
  return c;
}

// Builds the method once, once per drawn value and, for a planner, once with each problem's
// parameter defaults, so a bad name, type or range fails before any run.
template <class Registry>
void check_method(const Registry& registry, const PlannerConfig& c, const std::vector<ExperimentProblem>& problems,
                  const world::YamlFields& where) {
  try {
    registry.make(c.planner, c.params);
    if constexpr (std::is_same_v<Registry, roadmap::PlannerRegistry>) {  // navigators read no problem defaults
      for (const ExperimentProblem& p : problems) {
        try {
          registry.make(c.planner, roadmap::with_problem_params(*p.problem, registry.info(c.planner), c.params));
        } catch (const Error& e) {
          throw ParameterError("with problem '" + p.label + "' (its defaults.params): " + e.what());
        }
      }
    }
    for (const auto& [name, values] : c.draws) {
      for (const auto& v : values) {
        core::ParamMap p = c.params;
        p.insert_or_assign(name, v);
        registry.make(c.planner, p);
      }
    }
  } catch (const Error& e) {
    where.fail("", e.what());
  }
}

// A navigation method runs on a disc robot in a 2-D world: the task of every problem is made once
// (the first navigation method's entry names the failure), so a problem no navigator can take fails
// before any run.
void check_nav_tasks(const std::vector<ExperimentProblem>& problems, const world::YamlFields& where) {
  for (const ExperimentProblem& p : problems) {
    try {
      nav::make_nav_task(*p.problem);
    } catch (const Error& e) {
      where.fail("", "problem '" + p.label + "' cannot be given to a navigation method: " + e.what());
    }
  }
}

}  // namespace

std::string experiment_fingerprint(const Experiment& e) {
  std::ostringstream canon;
  canon << "seed=" << e.seed << ";runs=" << e.runs << ";time=" << e.time_limit_s << ';';
  // A given limit keeps the fingerprints of files that set one; no limit is a setting of its own.
  canon << "nodes=" << (e.node_limit ? std::to_string(*e.node_limit) : std::string("default")) << ';';
  if (e.common_seeds) canon << "common_seeds;";  // only when set: older fingerprints stay valid
  if (e.cost != kDefaultCost) canon << "cost=" << e.cost << ';';  // likewise
  for (const auto& p : e.problems) {
    canon << "problem=" << p.label << ':' << fnv1a(read_file(p.file)) << ';';
    for (const auto& f : p.inputs) canon << "input=" << fnv1a(read_file(f)) << ';';
  }
  for (const auto& c : e.planners) {
    canon << "planner=" << c.label << ':' << c.planner;
    for (const auto& [k, v] : c.params) canon << ',' << k << '=' << v.to_string();
    for (const auto& [k, vs] : c.draws) {
      canon << ',' << k << "~";
      for (const auto& v : vs) canon << v.to_string() << '|';
    }
    canon << ';';
  }
  std::ostringstream hex;
  hex << std::hex << fnv1a(canon.str());
  return hex.str();
}

TrialId trial_id(const Experiment& e, std::size_t index) {
  TrialId id;
  id.index = index;
  const std::size_t per_problem = e.planners.size() * static_cast<std::size_t>(e.runs);
  id.problem = index / per_problem;
  id.planner = (index % per_problem) / static_cast<std::size_t>(e.runs);
  id.run = static_cast<int>(index % static_cast<std::size_t>(e.runs));
  return id;
}

std::uint64_t trial_seed(const Experiment& e, const TrialId& id) {
  const std::uint64_t problem = fnv1a(e.problems[id.problem].label + '\x1f');
  const std::uint64_t who = e.common_seeds ? problem : fnv1a(e.planners[id.planner].label, problem);
  return core::derive_seed(core::derive_seed(e.seed, who), static_cast<std::uint64_t>(id.run));
}

core::ParamMap trial_params(const Experiment& e, const TrialId& id, std::map<std::string, std::string>* drawn) {
  const PlannerConfig& c = e.planners[id.planner];
  core::ParamMap params = c.params;
  if (c.draws.empty()) return params;
  // A stream of its own (not the planner's), so drawing does not shift the planner's random numbers.
  core::Rng rng(core::derive_seed(trial_seed(e, id), 0x6d657461ULL));
  for (const auto& [name, values] : c.draws) {  // std::map: name order
    const core::ParamValue& v = values[rng.uniform_index(values.size())];
    params.insert_or_assign(name, v);
    if (drawn != nullptr) (*drawn)[name] = v.to_string();
  }
  return params;
}

// `{arm_folder: F, urdf: U, srdf: S, count: N}`: every sceneNNNN.yaml of folder F with its
// requestNNNN.yaml (MotionBenchMaker's layout), in name order, the first N when given; each a
// problem named <folder>-requestNNNN (docs/experiment-format.md, "Arm folders").
std::vector<ExperimentProblem> arm_folder_problems(const world::YamlFields& p) {
  p.allow_only({"arm_folder", "urdf", "srdf", "count", "package_paths", "collision", "spheres"});
  const std::filesystem::path folder = p.file().parent_path() / p.string("arm_folder");
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) p.fail("arm_folder", "no such folder '" + folder.string() + "'");
  std::vector<std::filesystem::path> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("scene", 0) == 0 && entry.path().extension() == ".yaml") scenes.push_back(entry.path());
  }
  std::sort(scenes.begin(), scenes.end());
  const long long count = p.integer("count", static_cast<long long>(scenes.size()));
  if (count < 1) p.fail("count", "expected a positive integer");
  if (scenes.size() > static_cast<std::size_t>(count)) scenes.resize(static_cast<std::size_t>(count));
  if (scenes.empty()) p.fail("arm_folder", "no sceneNNNN.yaml in '" + folder.string() + "'");
  std::vector<std::filesystem::path> package_paths;
  if (p.has("package_paths")) {
    const world::YamlFields paths = p.child("package_paths");
    for (std::size_t k = 0; k < paths.size(); ++k) {
      if (!paths.element(k).node().IsScalar()) paths.element(k).fail("", "expected a folder");
      package_paths.push_back(p.file().parent_path() / paths.element(k).node().Scalar());
    }
  }
  // The collision model, as a problem file's `collision:` and `spheres:` (docs/arms.md, "Sphere model").
  world::ArmCollisionOptions collision;
  if (p.has("spheres")) collision.spheres = p.file_path("spheres");
  try {
    collision.model = world::parse_arm_collision(p.string("collision", collision.spheres.empty() ? "meshes" : "spheres"), "collision");
  } catch (const Error& err) {
    p.fail("collision", err.what());
  }
  if (collision.model == world::ArmCollision::kMeshes && !collision.spheres.empty()) {
    p.fail("spheres", "a spherized URDF is used only with collision: spheres");
  }
  collision.cache_dir = world::default_sphere_cache_dir();
  world::ArmDescription robot;
  try {
    robot = world::load_arm_description(p.file_path("urdf"), p.file_path("srdf"), package_paths, collision);
  } catch (const Error& err) {
    p.fail("", err.what());
  }
  std::vector<ExperimentProblem> out;
  for (const std::filesystem::path& scene : scenes) {
    const std::filesystem::path request = folder / ("request" + scene.filename().string().substr(5));
    if (!std::filesystem::is_regular_file(request, ec)) {
      p.fail("arm_folder", "no " + request.filename().string() + " beside " + scene.filename().string());
    }
    ExperimentProblem ep;
    ep.file = request;
    ep.inputs = {scene, robot.urdf, robot.srdf};
    if (!collision.spheres.empty()) ep.inputs.push_back(collision.spheres);
    try {
      ep.problem = std::make_shared<const world::Problem>(world::load_arm_problem(robot, scene, request));
    } catch (const Error& err) {
      p.fail("arm_folder", err.what());
    }
    ep.label = ep.problem->name;
    out.push_back(std::move(ep));
  }
  return out;
}

Experiment load_experiment(const std::filesystem::path& file) {
  const world::YamlFields root(world::load_yaml_file(file), file, "");
  if (!root.is_map()) root.fail("", "an experiment file must be a YAML mapping");
  root.allow_only(
      {"name", "description", "seed", "runs", "time_limit", "node_limit", "common_seeds", "cost", "cost_direction",
       "problems", "planners"});
  Experiment e;
  e.file = file;
  e.name = root.string("name", file.stem().string());
  const long long seed = root.integer("seed", 1);
  if (seed < 0) root.fail("seed", "expected a non-negative integer");
  e.seed = static_cast<std::uint64_t>(seed);
  const long long runs = root.integer("runs", 50);
  if (runs < 1 || runs > 10'000'000) root.fail("runs", "expected an integer in [1, 10000000], got " + std::to_string(runs));
  e.runs = static_cast<int>(runs);
  e.time_limit_s = root.positive("time_limit", e.time_limit_s);
  if (root.has("node_limit")) {  // absent: each run's problem or planner default
    const long long nodes = root.integer("node_limit", 0);
    if (nodes < 1) root.fail("node_limit", "expected a positive integer, got " + std::to_string(nodes));
    e.node_limit = static_cast<std::size_t>(nodes);
  }
  e.common_seeds = root.boolean("common_seeds", false);
  e.cost = root.string("cost", std::string(kDefaultCost));
  try {
    check_cost_metric(e.cost);
  } catch (const Error& err) {
    root.fail("cost", err.what());
  }
  e.cost_direction = default_cost_direction(e.cost);
  if (root.has("cost_direction")) {
    try {
      e.cost_direction = parse_cost_direction(root.string("cost_direction"));
    } catch (const ParameterError& err) {
      root.fail("cost_direction", err.what());
    }
  }

  const world::YamlFields problems = root.child("problems");
  if (problems.size() == 0) problems.fail("", "expected at least one problem");
  std::set<std::string> labels;
  for (std::size_t i = 0; i < problems.size(); ++i) {
    const world::YamlFields p = problems.element(i);
    if (p.is_map() && p.has("arm_folder")) {
      for (ExperimentProblem& ep : arm_folder_problems(p)) {
        if (!labels.insert(ep.label).second) p.fail("", "problem name '" + ep.label + "' appears twice");
        e.problems.push_back(std::move(ep));
      }
      continue;
    }
    ExperimentProblem ep;
    if (p.node().IsScalar()) {
      const std::filesystem::path rel = p.node().Scalar();
      ep.file = rel.is_absolute() ? rel : file.parent_path() / rel;
      std::error_code ec;  // a name the OS refuses (too long, ...) is "no such file", not an exception
      if (!std::filesystem::is_regular_file(ep.file, ec)) p.fail("", "no such problem file '" + ep.file.string() + "'");
    } else {
      p.allow_only({"file", "name"});
      ep.file = p.file_path("file");
    }
    try {
      ep.problem = std::make_shared<const world::Problem>(world::load_problem(ep.file));
      ep.label = p.node().IsScalar() ? ep.problem->name : p.string("name", ep.problem->name);
    } catch (const Error& err) {
      p.fail("", err.what());
    }
    if (!labels.insert(ep.label).second) p.fail("", "problem name '" + ep.label + "' appears twice");
    e.problems.push_back(std::move(ep));
  }

  const world::YamlFields planners = root.child("planners");
  if (planners.size() == 0) planners.fail("", "expected at least one planner");
  labels.clear();
  bool tasks_checked = false;
  for (std::size_t i = 0; i < planners.size(); ++i) {
    const world::YamlFields f = planners.element(i);
    PlannerConfig c = parse_planner(f);
    try {
      c.kind = method_kind(c.planner);
    } catch (const Error& err) {
      f.fail(f.node().IsScalar() ? "" : "planner", err.what());
    }
    if (c.kind == MethodKind::kPlanner) {
      check_method(roadmap::builtin_planners(), c, e.problems, f);
    } else {
      check_method(nav::builtin_navigators(), c, e.problems, f);
      if (!tasks_checked) check_nav_tasks(e.problems, f);
      tasks_checked = true;
    }
    if (!labels.insert(c.label).second) f.fail("", "planner name '" + c.label + "' appears twice; give each a name");
    e.planners.push_back(std::move(c));
  }
  e.fingerprint = experiment_fingerprint(e);
  return e;
}

}  // namespace amp::bench
