#include "amp/bench/report.hpp"

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "amp/bench/bench_runner.hpp"
#include "amp/bench/cost_metric.hpp"
#include "amp/bench/runs_csv.hpp"
#include "amp/core/error.hpp"
#include "amp/viz/scene_renderer.hpp"
#include "amp/viz/xml_escape.hpp"
#include "report_page.hpp"
#include "report_text.hpp"

namespace amp::bench {

namespace {

namespace text = report_text;
using viz::xml_escape;
using Json = nlohmann::json;

constexpr int kSceneWidthPx = 440;

// A run that is a sequence of worlds (report_text::RunKind::kWorldSequence) drives in worlds drawn
// anew per run, so no one path of it belongs in the problem's drawing.
bool world_sequence(const core::RunRecord& r) { return r.extra.count(text::kWorldsExtra) != 0; }

// What the page needs from runs.csv beyond summary.json: every run's cost (for box plots with
// outliers and for histograms on shared bins) and, per problem, the first solved trial with a path
// to draw.
report_page::RunData read_runs(const Experiment& e, const std::filesystem::path& csv) {
  report_page::RunData d;
  d.cost.assign(e.problems.size(), std::vector<std::vector<double>>(e.planners.size()));
  d.first_solved.assign(e.problems.size(), std::nullopt);
  d.first_run_solved.assign(e.problems.size(), std::vector<std::optional<std::size_t>>(e.planners.size()));
  d.found = std::filesystem::is_regular_file(csv);
  if (!d.found) return d;
  for_each_trial(csv, e, [&](const Trial& t) {
    const MetricSample s = metric_sample(t.record, e.cost);
    if (s.kind == MetricSample::Kind::kValue) d.cost[t.id.problem][t.id.planner].push_back(s.value);
    if (t.record.status == core::PlanStatus::kSolved && !world_sequence(t.record) && !d.first_solved[t.id.problem]) {
      d.first_solved[t.id.problem] = t.id.index;
    }
    if (t.id.run == 0 && t.record.status == core::PlanStatus::kSolved && !world_sequence(t.record) &&
        e.planners[t.id.planner].kind == MethodKind::kPlanner) {
      d.first_run_solved[t.id.problem][t.id.planner] = t.id.index;
    }
  });
  return d;
}

// The caption of a solved trial re-run from its seed (runs.csv keeps no paths), which fills `path`:
// a planner's solution, or a navigation method's driven trace.
std::string redrawn_caption(const Experiment& e, std::size_t index, std::vector<State>& path) {
  const Trial t = run_trial(e, index, nullptr, &path);
  const bool nav = e.planners[t.id.planner].kind == MethodKind::kNavigator;
  std::string caption = std::string(nav ? "Driven trace of <strong>" : "Solution of <strong>") +
                        xml_escape(e.planners[t.id.planner].label) + "</strong>, run " + std::to_string(t.id.run) +
                        " (seed " + std::to_string(t.seed) + ")";
  if (t.record.status == core::PlanStatus::kSolved && !path.empty()) {
    const text::CostStyle style = text::cost_style(e.cost, e.cost_direction);
    const MetricSample s = metric_sample(t.record, e.cost);
    return caption + ": " +
           (s.kind == MetricSample::Kind::kValue ? style.format(s.value) + " " + xml_escape(style.label)
                                                 : xml_escape(style.label) + " not reported") +
           (nav ? ", driven length " : ", path length ") + text::real(t.record.path_length) + ".";
  }
  path.clear();
  // A run near the time limit may not solve again: the limit is wall time, not a count.
  return caption + ": re-running it did not reproduce the " + (nav ? "run (" : "solution (") +
         xml_escape(std::string(core::to_string(t.record.status))) + "), so no " + (nav ? "trace" : "path") +
         " is drawn.";
}

// One line for the methods whose runs are sequences of worlds: what a run is, and why none is drawn.
std::string sequences_caption(const std::vector<std::string>& names) {
  if (names.empty()) return std::string();
  return " " + text::join_words(names) + (names.size() == 1 ? " runs" : " run") +
         " sequences of worlds drawn anew in this box, one sequence per run, so no single path of theirs is drawn.";
}

// The problem drawn with the path of its first solved trial, and a caption saying which run it is.
std::string scene_figure(const Experiment& e, std::size_t p, const report_page::RunData& runs, const Json& pj) {
  const auto& problem = e.problems[p].problem;
  if (problem == nullptr) return "<figure class=\"scene\"><figcaption>The problem is not loaded.</figcaption></figure>";
  std::vector<std::string> sequences;
  const Json& planners = pj.contains("planners") ? pj["planners"] : Json::array();
  for (const Json& pl : planners) {
    if (text::run_kind(pl) == text::RunKind::kWorldSequence) {
      sequences.push_back("<strong>" + xml_escape(pl.value("name", std::string())) + "</strong>");
    }
  }
  std::vector<State> path;
  std::string caption;
  if (runs.first_solved[p]) {
    caption = redrawn_caption(e, *runs.first_solved[p], path);
  } else if (!runs.found) {
    caption = "Start and goal (no runs.csv beside this report, so no solution to redraw).";
  } else {
    caption = sequences.size() == planners.size() && !sequences.empty()
                  ? std::string("The problem\u2019s box.")
                  : std::string("No planner solved this problem: start and goal only.");
  }
  caption += sequences_caption(sequences);
  viz::SceneOptions options;
  options.width_px = kSceneWidthPx;
  options.path = path.empty() ? nullptr : &path;
  options.footprints = 16;
  std::ostringstream out;
  out << "<figure class=\"scene\">";
  try {
    out << viz::render_scene(*problem, options);
  } catch (const Error& ex) {  // a drawing is no reason to lose the rest of the report
    caption += " (The problem could not be drawn: " + xml_escape(ex.what()) + ")";
  }
  out << "<figcaption>" << caption << "</figcaption></figure>\n";
  return out.str();
}

void header(std::ostream& out, const Experiment& e, const RunInfo& info) {
  auto item = [&](const std::string& label, const std::string& value) {
    out << "<div><dt>" << xml_escape(label) << "</dt><dd>" << xml_escape(value.empty() ? "\u2013" : value)
        << "</dd></div>\n";
  };
  out << "<header class=\"top\"><div class=\"wrap\"><p class=\"kicker\">AMP benchmark report</p><h1>"
      << xml_escape(e.name.empty() ? std::string("Experiment") : e.name) << "</h1>\n<dl class=\"meta\">\n";
  item("Date (UTC)", info.date);
  item("Host", info.hostname);
  item("CPU", info.cpu_info);
  item("Threads", std::to_string(info.threads));
  item("Trials", std::to_string(e.problems.size()) + " problems \u00d7 " + std::to_string(e.planners.size()) +
                     " planners \u00d7 " + std::to_string(e.runs) + " runs = " + std::to_string(e.trial_count()));
  item("Runs per planner", std::to_string(e.runs));
  item("Master seed", std::to_string(e.seed));
  item("Time limit per run", text::seconds(e.time_limit_s));
  item("Node limit per run", e.node_limit ? text::count(static_cast<double>(*e.node_limit))
                                          : std::string("the problem's, else the planner's"));
  item("Total wall time", info.total_time_s > 0 ? text::seconds(info.total_time_s) : std::string());  // 0: not known
  item("Experiment file", e.file.string());
  item("Version", info.version);
  out << "<div class=\"wide\"><dt>Fingerprint</dt><dd><code>" << xml_escape(e.fingerprint) << "</code></dd></div>\n";
  out << "</dl></div></header>\n";
}

}  // namespace

void write_report(const Experiment& e, const Json& summary, const RunInfo& info, const std::filesystem::path& dir) {
  const report_page::RunData runs = read_runs(e, dir / "runs.csv");
  const Json& problems = summary.contains("problems") ? summary["problems"] : Json::array();

  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>"
      << xml_escape(e.name) << " \u2013 AMP benchmark report</title>\n<style>" << report_page::kStyle
      << "</style>\n</head>\n<body>\n";
  header(out, e, info);
  out << "<main class=\"wrap\">\n";
  report_page::overview(out, e, problems);
  for (std::size_t p = 0; p < e.problems.size() && p < problems.size(); ++p) {
    const Json& pj = problems[p];
    out << "<section class=\"card problem\" id=\"problem-" << p << "\">\n<h2>"
        << xml_escape(pj.value("name", e.problems[p].label)) << " <span class=\"file\">"
        << xml_escape(e.problems[p].file.lexically_normal().string()) << "</span></h2>\n<div class=\"row\">\n"
        << scene_figure(e, p, runs, pj) << "<div class=\"findings\"><h3>Findings</h3><ul>\n";
    const text::CostStyle style = text::cost_style(e.cost, e.cost_direction);
    for (const auto& f : text::findings(pj, style)) out << "<li>" << f << "</li>\n";
    out << "</ul>" << report_page::viewer_links(e, p, runs, dir) << "</div>\n</div>\n";
    report_page::cost_table(out, e, pj);
    report_page::phase_table(out, pj);
    report_page::metrics_table(out, pj);
    report_page::charts(out, e, runs.cost[p]);
    out << "</section>\n";
  }
  out << "</main>\n<footer class=\"wrap\">Run cost is the number of collision-detection (CD) calls of a run, the "
         "measure of Isto, M\u00e4ntyl\u00e4 &amp; Tuominen, <em>On addressing the run-cost variance in randomized "
         "motion planners</em>"
      << (e.cost == kDefaultCost ? std::string()
                                 : "; this experiment names <code>" + xml_escape(e.cost) + "</code> as its cost instead")
      << (e.cost_direction == CostDirection::kHigher ? ", and higher values of it are better" : "")
      << ". Runs stopped at a limit enter the statistics with the cost they had spent. "
         "Quartiles are R\u2019s type 7; box whiskers reach the furthest run within 1.5 IQR. Generated by "
      << xml_escape(info.version) << " from runs.csv and summary.json in this directory.</footer>\n</body>\n</html>\n";

  const auto file = dir / "report.html";
  std::ofstream f(file, std::ios::binary);
  if (!f) throw FileError(file.string() + ": cannot open for writing");
  f << out.str();
  if (!f) throw FileError(file.string() + ": write failed");
}

}  // namespace amp::bench
