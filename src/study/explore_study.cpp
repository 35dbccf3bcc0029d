#include "amp/study/explore_study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "amp/core/error.hpp"
#include "amp/core/param_routing.hpp"
#include "amp/core/number_text.hpp"
#include "amp/nav/nav_task.hpp"
#include "amp/viz/pgcs_figures.hpp"
#include "amp/viz/scene_renderer.hpp"
#include "amp/world/occupancy_grid.hpp"
#include "amp/study/output_dir.hpp"
#include "amp/study/record_json.hpp"

namespace amp::study {

namespace {

std::string point_text(const Eigen::Vector2d& p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%g, %g)", p.x(), p.y());
  return buf;
}

// A query end must be a place the robot can stand: inside the map, its disc free. Checked before
// exploring, so a typo costs no exploration.
void check_query_point(const nav::NavTask& task, const Eigen::Vector2d& p, std::size_t index, const char* end) {
  const nav::NavWorld& world = *task.timeline->base();
  const std::string where = "--query " + std::to_string(index + 1) + ": " + end + " " + point_text(p);
  if (!p.allFinite() || !world.bounds().contains(p)) {
    throw ParameterError(where + " is outside the map " + point_text(world.bounds().min()) + "-" +
                         point_text(world.bounds().max()));
  }
  if (!world.disc_free(p, task.robot_radius)) {
    throw ParameterError(where + " is in an obstacle (the robot's disc of radius " +
                         core::number_text(task.robot_radius) + " is not free there)");
  }
}

nlohmann::ordered_json flat_record(const world::Problem& problem, const ExploreSetup& setup, const ExploreResult& r) {
  const nav::PgcsSummary& s = r.summary;
  nlohmann::ordered_json j;
  j["problem"] = problem.name;
  j["method"] = "pgcs";
  j["exploration"] = setup.run.exploration;
  j["seed"] = setup.seed;
  j["steps"] = s.steps;
  j["clusters"] = s.clusters;
  j["coverage"] = s.coverage;
  j["quantisation_error"] = s.quantisation_error;
  j["illegal_edges"] = s.illegal_edges;
  j["suspect_edges"] = s.suspect_edges;
  j["queries"] = s.queries;
  j["queries_solved"] = s.queries_solved;
  j["replans_median"] = optional_json(s.replans_median);
  j["replans_max"] = s.replans_max;
  j["path_ratio_median"] = optional_json(s.path_ratio_median);
  j["explore_time_s"] = r.run.explore_time_s;
  // Route planning only (the method's cost); driving is the simulated robot's time.
  j["query_time_median_s"] = optional_json(s.query_time_median_s);
  return j;
}

nlohmann::ordered_json point_json(const Eigen::Vector2d& p) { return nlohmann::ordered_json::array({p.x(), p.y()}); }

}  // namespace

nlohmann::ordered_json explore_record(const ExploreResult& r) {
  const nav::PgcsSession& s = *r.run.session;
  nlohmann::ordered_json j = r.record;
  nlohmann::ordered_json settings;
  for (const auto& [name, value] : nav::PgcsRunSettings::schema().values(s.settings())) {
    settings[name] = param_json(value);
  }
  for (const auto& [name, value] : learn::PgcsSettings::schema().values(s.clusters().settings())) {
    settings[name] = param_json(value);
  }
  j["settings"] = settings;
  nlohmann::ordered_json queries = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < r.run.queries.size(); ++i) {
    const nav::QueryRecord& q = r.run.queries[i];
    nlohmann::ordered_json blocks = nlohmann::ordered_json::array();
    for (const auto& b : q.blocks) blocks.push_back(point_json(b));
    queries.push_back({{"start", point_json(q.start)},
                       {"target", point_json(q.target)},
                       {"solved", q.solved},
                       {"unsolvable", q.unsolvable},
                       {"replans", q.replans},
                       {"left_out", q.left_out},
                       {"length", q.length},
                       // +inf (not connected) has no JSON number: null
                       {"shortest", std::isfinite(q.shortest) ? nlohmann::ordered_json(q.shortest) : nlohmann::ordered_json()},
                       {"ratio", q.ratio},
                       {"plan_time_s", q.plan_time_s},
                       {"wall_time_s", r.run.query_wall_s[i]},
                       {"illegal_edges", q.illegal_edges},
                       {"blocks", blocks}});
  }
  j["query_details"] = queries;
  nlohmann::ordered_json curves = nlohmann::ordered_json::array();
  for (const nav::CurvePoint& c : s.curves()) {
    curves.push_back({{"step", c.step},
                      {"clusters", c.clusters},
                      {"coverage", c.coverage},
                      {"quantisation_error", c.quantisation_error},
                      {"closed_prior", c.closed_prior}});
  }
  j["curves"] = curves;
  return j;
}

namespace {

// The obstacles that appeared during the first `steps` steps (a vanish event is not subtracted:
// a door that closed and opened again is still drawn, as where the robot met one).
std::vector<world::Shapes2d> appeared_by(const world::Problem& problem, const nav::WorldTimeline& timeline,
                                         long steps) {
  std::vector<world::Shapes2d> out;
  const world::Outline outline = problem.environment->obstacle_outline();
  for (const nav::WorldEvent& e : timeline.events()) {
    if (static_cast<long>(e.step) >= steps || e.change.action != nav::ObstacleChange::Action::kAppear) continue;
    world::Shapes2d shapes = e.change.shapes;
    for (const nav::CellRect& r : e.change.cells) {
      if (outline.grid == nullptr) break;  // cells only apply to maps (the loader checked)
      Eigen::AlignedBox2d box = outline.grid->cell_box(r.x0, r.y0);
      box.extend(outline.grid->cell_box(r.x1, r.y1));
      shapes.polygons.push_back({{box.corner(Eigen::AlignedBox2d::BottomLeft),
                                  box.corner(Eigen::AlignedBox2d::BottomRight),
                                  box.corner(Eigen::AlignedBox2d::TopRight), box.corner(Eigen::AlignedBox2d::TopLeft)}});
    }
    out.push_back(std::move(shapes));
  }
  return out;
}

viz::PgcsDrawing drawing_of(const world::Problem& problem, const nav::PgcsSession& s) {
  viz::PgcsDrawing d;
  d.appeared = appeared_by(problem, *s.task().timeline, s.steps());
  const learn::Pgcs& k = s.clusters();
  for (const int id : k.ids()) d.clusters.push_back({k.mean(id), std::sqrt(std::max(0.0, k.variance(id)))});
  for (const auto& [a, b] : k.triangulation().edges()) {
    if (!s.memory().illegal(a, b, k.mean(a), k.mean(b))) d.legal_edges.emplace_back(k.mean(a), k.mean(b));
  }
  for (const nav::EdgeMemory::Entry& e : s.memory().entries()) {
    (e.blocks >= s.memory().strikes() ? d.illegal_edges : d.suspect_edges).emplace_back(e.pa, e.pb);
  }
  d.explored = s.exploration_trace();
  d.start = s.task().start;
  d.robot_radius = s.task().robot_radius;
  d.steps = s.steps();
  return d;
}

}  // namespace

void read_explore_params(const core::ParamMap& params, ExploreSetup& setup) {
  const auto& run_schema = nav::PgcsRunSettings::schema();
  const auto& pgcs_schema = learn::PgcsSettings::schema();
  const std::vector<core::ParamMap> routed = core::route_params(params, {&pgcs_schema.specs(), &run_schema.specs()});
  setup.run = run_schema.read(core::Params(run_schema.owner(), run_schema.specs(), routed[1]));
  setup.pgcs = pgcs_schema.read(core::Params(pgcs_schema.owner(), pgcs_schema.specs(), routed[0]));
}

ExploreResult run_exploration(const world::Problem& problem, const ExploreSetup& setup) {
  nav::NavTask task = nav::make_nav_task(problem);
  for (std::size_t i = 0; i < setup.queries.size(); ++i) {
    check_query_point(task, setup.queries[i].first, i, "start");
    check_query_point(task, setup.queries[i].second, i, "target");
  }
  ExploreResult r;
  try {
    r.run = nav::run_pgcs(std::move(task), setup.run, setup.pgcs, setup.seed, setup.queries, nullptr, setup.progress);
  } catch (const nav::PgcsQueryError& e) {
    // A door that closed during exploration may cover a point that was free at the start.
    throw ParameterError("--query " + std::to_string(e.index() + 1) + ": " + e.detail());
  }
  r.summary = nav::summarise_pgcs(*r.run.session, r.run.queries);
  r.record = flat_record(problem, setup, r);
  return r;
}

const std::vector<std::string>& explore_output_files() {
  static const std::vector<std::string> files = {"figure1.svg", "curves.svg", "queries.svg", "record.json"};
  return files;
}

void check_explore_dir(const std::filesystem::path& dir, bool force, const std::string& option) {
  check_output_dir(dir, explore_output_files(), force, option);
}

void write_explore_outputs(const world::Problem& problem, const ExploreResult& r, const std::filesystem::path& dir) {
  create_output_dir(dir);
  const nav::PgcsSession& s = *r.run.session;
  const viz::PgcsDrawing drawing = drawing_of(problem, s);
  const std::string name = problem.name + " — PGCS, " + s.settings().exploration + ", seed " +
                           r.record.at("seed").dump();
  viz::write_text_file((dir / "figure1.svg").string(), viz::pgcs_figure1_svg(problem, drawing, name));
  std::vector<viz::CurveSample> curves;
  for (const nav::CurvePoint& c : s.curves()) {
    curves.push_back({c.step, c.clusters, c.coverage, c.quantisation_error, c.closed_prior});
  }
  viz::write_text_file((dir / "curves.svg").string(), viz::pgcs_curves_svg(curves, name));
  std::vector<viz::QueryDrawing> queries;
  for (const nav::QueryRecord& q : r.run.queries) queries.push_back({q.start, q.target, q.solved, q.replans, q.trace, q.blocks});
  viz::write_text_file((dir / "queries.svg").string(), viz::pgcs_queries_svg(problem, drawing, queries, name));
  viz::write_text_file((dir / "record.json").string(), explore_record(r).dump(2) + "\n");
}

std::string format_explore_table(const nlohmann::ordered_json& record) {
  std::ostringstream out;
  for (const auto& [key, value] : record.items()) {
    char name[32];
    std::snprintf(name, sizeof name, "  %-22s", key.c_str());
    out << name;
    if (value.is_null()) {
      out << "-";
    } else if (value.is_number_float()) {
      char num[32];
      std::snprintf(num, sizeof num, "%.4g", value.get<double>());
      out << num;
    } else if (value.is_string()) {
      out << value.get<std::string>();
    } else {
      out << value.dump();
    }
    out << '\n';
  }
  return out.str();
}

}  // namespace amp::study
