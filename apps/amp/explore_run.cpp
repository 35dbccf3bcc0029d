#include "explore_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "amp/core/error.hpp"
#include "amp/nav/nav_task.hpp"
#include "amp/stats/descriptive.hpp"
#include "amp/viz/pgcs_figures.hpp"
#include "amp/viz/scene_renderer.hpp"
#include "amp/world/occupancy_grid.hpp"
#include "cli_util.hpp"

namespace amp::cli {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::string number_text(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

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
                         number_text(task.robot_radius) + " is not free there)");
  }
}

// The median of a sample, null when it is empty (no query solved: no path ratio).
nlohmann::ordered_json median_or_null(std::vector<double> values) {
  if (values.empty()) return nullptr;
  std::sort(values.begin(), values.end());
  return stats::quantile(values, 0.5);
}

nlohmann::ordered_json flat_record(const world::Problem& problem, const ExploreSetup& setup, const ExploreResult& r) {
  const nav::PgcsSession& s = *r.session;
  std::vector<double> replans, ratios, times;
  int solved = 0, replans_max = 0;
  for (const nav::QueryRecord& q : r.queries) {
    replans.push_back(q.replans);
    replans_max = std::max(replans_max, q.replans);
    times.push_back(q.plan_time_s);
    if (q.solved) {
      ++solved;
      ratios.push_back(q.ratio);
    }
  }
  nlohmann::ordered_json j;
  j["problem"] = problem.name;
  j["method"] = "pgcs";
  j["exploration"] = setup.run.exploration;
  j["seed"] = setup.seed;
  j["steps"] = s.steps();
  j["clusters"] = s.clusters().size();
  j["coverage"] = s.coverage();
  j["quantisation_error"] = s.quantisation_error();
  j["illegal_edges"] = s.memory().size();
  j["suspect_edges"] = s.memory().suspects();
  j["queries"] = r.queries.size();
  j["queries_solved"] = solved;
  j["replans_median"] = median_or_null(replans);
  j["replans_max"] = replans_max;
  j["path_ratio_median"] = median_or_null(ratios);
  j["explore_time_s"] = r.explore_time_s;
  // Route planning only (the method's cost); driving is the simulated robot's time.
  j["query_time_median_s"] = median_or_null(times);
  return j;
}

// A parameter's value as JSON: integers as integers (the schema stores every number as a double).
nlohmann::ordered_json param_json(const core::ParamValue& v) {
  if (!v.is_number()) return v.string();
  const double x = v.number();
  if (x == std::floor(x) && std::abs(x) < 9e15) return static_cast<long long>(x);
  return x;
}

nlohmann::ordered_json point_json(const Eigen::Vector2d& p) { return nlohmann::ordered_json::array({p.x(), p.y()}); }

nlohmann::ordered_json full_record(const ExploreResult& r) {
  const nav::PgcsSession& s = *r.session;
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
  for (std::size_t i = 0; i < r.queries.size(); ++i) {
    const nav::QueryRecord& q = r.queries[i];
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
                       {"wall_time_s", r.query_wall_s[i]},
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

ExploreResult run_exploration(const world::Problem& problem, const ExploreSetup& setup) {
  nav::NavTask task = nav::make_nav_task(problem);
  for (std::size_t i = 0; i < setup.queries.size(); ++i) {
    check_query_point(task, setup.queries[i].first, i, "start");
    check_query_point(task, setup.queries[i].second, i, "target");
  }
  ExploreResult r;
  r.session = std::make_unique<nav::PgcsSession>(std::move(task), setup.run, setup.pgcs, setup.seed);
  const long total = setup.run.steps;
  const auto t0 = Clock::now();
  std::function<void(long)> progress;
  if (setup.progress) progress = [&setup, total](long done) { setup.progress(done, total); };
  r.session->explore(total, nullptr, progress);
  r.explore_time_s = seconds_since(t0);

  const auto pairs = setup.queries.empty() ? r.session->draw_queries(setup.run.queries) : setup.queries;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const auto q0 = Clock::now();
    try {
      r.queries.push_back(r.session->query(pairs[i].first, pairs[i].second));
    } catch (const ParameterError& e) {
      // A door that closed during exploration may cover a point that was free at the start.
      throw ParameterError("--query " + std::to_string(i + 1) + ": " + e.what());
    }
    r.query_wall_s.push_back(seconds_since(q0));
  }
  r.record = flat_record(problem, setup, r);
  return r;
}

const std::vector<std::string>& explore_output_files() {
  static const std::vector<std::string> files = {"figure1.svg", "curves.svg", "queries.svg", "record.json"};
  return files;
}

void check_explore_dir(const std::filesystem::path& dir, bool force, const std::string& option) {
  std::error_code ec;
  if (std::filesystem::exists(dir, ec)) {
    if (!std::filesystem::is_directory(dir, ec)) {
      throw Error(option + ": '" + dir.string() + "' is a file, expected a directory");
    }
    for (const std::string& f : explore_output_files()) check_writable(dir / f, force, option);
    return;
  }
  const auto parent = dir.has_parent_path() ? dir.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::is_directory(parent, ec)) {
    throw Error(option + ": directory '" + parent.string() + "' does not exist");
  }
}

void write_explore_outputs(const world::Problem& problem, const ExploreResult& r, const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw FileError(dir.string() + ": cannot create the directory: " + ec.message());
  const nav::PgcsSession& s = *r.session;
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
  for (const nav::QueryRecord& q : r.queries) queries.push_back({q.start, q.target, q.solved, q.replans, q.trace, q.blocks});
  viz::write_text_file((dir / "queries.svg").string(), viz::pgcs_queries_svg(problem, drawing, queries, name));
  viz::write_text_file((dir / "record.json").string(), full_record(r).dump(2) + "\n");
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

}  // namespace amp::cli
