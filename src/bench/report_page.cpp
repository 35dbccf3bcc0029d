#include "report_page.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "amp/bench/cost_metric.hpp"
#include "amp/stats/histogram.hpp"
#include "amp/viz/charts.hpp"
#include "amp/viz/xml_escape.hpp"
#include "report_text.hpp"

namespace amp::bench::report_page {

namespace {

namespace text = report_text;
using viz::xml_escape;
using Json = nlohmann::json;

// Tableau 10: distinct on screen and in print, and the first few stay apart for the colour-blind.
constexpr const char* kPalette[] = {"#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f",
                                    "#edc948", "#b07aa1", "#ff9da7", "#9c755f", "#bab0ac"};
constexpr std::size_t kMaxChartBins = 30;  // more bars than this are noise at 270 px
constexpr int kBoxWidthPx = 470, kBoxHeightPx = 330;
constexpr int kHistWidthPx = 270, kHistHeightPx = 150;

std::string swatch(std::size_t i) {
  return "<span class=\"swatch\" style=\"background:" + planner_color(i) + "\"></span>";
}

std::string params_text(const core::ParamMap& params) {
  std::string s;
  for (const auto& [k, v] : params) s += (s.empty() ? "" : ", ") + k + " = " + v.to_string();
  return s;
}

std::string draws_text(const std::map<std::string, std::vector<core::ParamValue>>& draws) {
  std::string s;
  for (const auto& [k, values] : draws) {
    std::string set;
    for (const auto& v : values) set += (set.empty() ? "" : ", ") + v.to_string();
    s += (s.empty() ? "" : "; ") + k + " \u2208 {" + set + "}";
  }
  return s;
}

// Text (already escaped), highlighted when `best`.
std::string mark(bool best, const std::string& html) {
  return best ? "<span class=\"best\">" + html + "</span>" : html;
}

const Json& cost_of(const Json& planner) { return text::cost_json(planner); }

// Index of the planner with the best finite cost[key] in direction d, if more than one planner: the
// mean goes the cost's way, the CV is always better lower.
std::optional<std::size_t> best_of(const Json& planners, const char* key, CostDirection d) {
  std::optional<std::size_t> best;
  if (planners.size() < 2) return best;
  for (std::size_t i = 0; i < planners.size(); ++i) {
    const double v = text::number_at(cost_of(planners[i]), key);
    if (std::isfinite(v) && (!best || better(d, v, text::number_at(cost_of(planners[*best]), key)))) best = i;
  }
  return best;
}

// "solved", or "complete" for a method whose run is a sequence of worlds (its status is the
// sequence's: a complete sequence may have solved few of its worlds).
const char* solved_word(const Json& planner) {
  return text::run_kind(planner) == text::RunKind::kWorldSequence ? "complete" : "solved";
}

// Under the cost table, when some method's runs are sequences of worlds: what its Solved cell counts.
void sequences_note(std::ostream& out, const Json& planners) {
  std::vector<std::string> names;
  for (const Json& pl : planners) {
    if (text::run_kind(pl) == text::RunKind::kWorldSequence) {
      names.push_back("<strong>" + xml_escape(pl.value("name", std::string())) + "</strong>");
    }
  }
  if (names.empty()) return;
  out << "<p class=\"note\">" << text::join_words(names) << (names.size() == 1 ? " runs" : " run")
      << " sequences of worlds: each run is one sequence, and Solved counts sequences driven to their end, "
         "not worlds solved.</p>\n";
}

bool heavy_tailed(const std::vector<std::vector<double>>& cost) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const auto& g : cost) {
    for (double v : g) {
      if (v <= 0) return false;  // a log axis cannot show it
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  return std::isfinite(lo) && hi / lo > kLogSpan;
}

// Equal-width bins over the pooled costs (in log10 when `log`), as many as Freedman-Diaconis asks
// for the pooled sample, so every planner's histogram shares them (counted by stats::bin_counts).
std::vector<double> shared_edges(const std::vector<std::vector<double>>& cost, bool log) {
  std::vector<double> pooled;
  for (const auto& g : cost) {
    for (double v : g) pooled.push_back(log ? std::log10(v) : v);
  }
  if (pooled.empty()) return {};
  const auto [mn, mx] = std::minmax_element(pooled.begin(), pooled.end());
  double lo = *mn, hi = *mx;
  // At least one: bin_count's size_t cast can give 0 when range / width exceeds 2^64.
  std::size_t bins = std::max<std::size_t>(1, stats::bin_count(pooled, stats::BinRule::kFreedmanDiaconis, kMaxChartBins));
  if (hi == lo) {  // one value: one bin around it (a fifth of a decade on a log axis)
    lo -= log ? 0.1 : 0.5;
    hi += log ? 0.1 : 0.5;
    bins = 1;
  }
  std::vector<double> edges = stats::equal_width_edges(lo, hi, bins);
  if (log) {
    for (double& x : edges) x = std::pow(10.0, x);
  }
  return edges;
}

}  // namespace

std::string planner_color(std::size_t i) { return kPalette[i % std::size(kPalette)]; }

void overview(std::ostream& out, const Experiment& e, const Json& problems) {
  out << "<section class=\"card\"><h2>Planner configurations</h2>\n<table class=\"configs\"><thead><tr>"
         "<th>Configuration</th><th>Planner</th><th>Fixed parameters</th><th>Drawn per run</th></tr></thead><tbody>\n";
  for (std::size_t c = 0; c < e.planners.size(); ++c) {
    const auto& pc = e.planners[c];
    const std::string params = params_text(pc.params), draws = draws_text(pc.draws);
    out << "<tr><td>" << swatch(c) << "<strong>" << xml_escape(pc.label) << "</strong></td><td><code>"
        << xml_escape(pc.planner) << "</code></td><td>" << xml_escape(params.empty() ? "defaults" : params)
        << "</td><td>" << xml_escape(draws.empty() ? "\u2013" : draws) << "</td></tr>\n";
  }
  out << "</tbody></table>\n";
  if (problems.empty() || e.planners.empty()) {
    out << "</section>\n";
    return;
  }
  const text::CostStyle style = text::cost_style(e.cost, e.cost_direction);
  out << "<h2>Overview</h2><p class=\"note\">"
      << (style.higher() ? "Mean " + xml_escape(style.label) + " (higher is better)"
                         : "Mean run cost in " + xml_escape(style.label))
      << ", its coefficient of variation and the share of solved runs; the "
      << (style.higher() ? "highest" : "lowest") << " mean and the lowest CV of each problem are marked.</p>\n"
         "<table class=\"overview\"><thead><tr><th>Problem</th>";
  for (std::size_t c = 0; c < e.planners.size(); ++c) {
    out << "<th>" << swatch(c) << xml_escape(e.planners[c].label) << "</th>";
  }
  out << "</tr></thead><tbody>\n";
  for (std::size_t p = 0; p < problems.size(); ++p) {
    const Json& planners = problems[p].value("planners", Json::array());
    const auto best_mean = best_of(planners, "mean", e.cost_direction);
    const auto low_cv = best_of(planners, "cv_percent", CostDirection::kLower);
    out << "<tr><td><a href=\"#problem-" << p << "\">" << xml_escape(problems[p].value("name", std::string()))
        << "</a></td>";
    for (std::size_t c = 0; c < planners.size(); ++c) {
      const Json& cost = cost_of(planners[c]);
      out << "<td>" << mark(best_mean == c, style.format(text::number_at(cost, "mean"))) << "<br><small>"
          << mark(low_cv == c, "CV " + text::percent(std::round(text::number_at(cost, "cv_percent")))) << " \u00b7 "
          << text::percent(std::round(text::number_at(planners[c], "solved_percent"))) << " "
          << solved_word(planners[c]) << "</small></td>";
    }
    out << "</tr>\n";
  }
  out << "</tbody></table></section>\n";
}

// The cost table's heading: the run-cost paper's words for a cost, the metric's name for a value
// that is better higher.
std::string cost_heading(const Experiment& e) {
  if (e.cost_direction == CostDirection::kHigher) return "<h3>" + xml_escape(e.cost) + " (higher is better)</h3>";
  return e.cost == kDefaultCost ? std::string("<h3>Run cost in collision-detection calls</h3>")
                                : "<h3>Run cost: " + xml_escape(e.cost) + "</h3>";
}

void cost_table(std::ostream& out, const Experiment& e, const Json& problem) {
  const Json& planners = problem.value("planners", Json::array());
  const auto best_mean = best_of(planners, "mean", e.cost_direction);
  const auto low_cv = best_of(planners, "cv_percent", CostDirection::kLower);
  const text::CostStyle style = text::cost_style(e.cost, e.cost_direction);
  out << cost_heading(e)
      << "\n<table class=\"stats\"><thead>"
         "<tr class=\"group\"><th colspan=\"3\"></th><th colspan=\"3\">as the paper\u2019s Table 1</th>"
         "<th colspan=\"5\">five-number summary</th><th colspan=\"3\">medians</th></tr>"
         "<tr><th>Planner</th><th>Runs</th><th>Solved</th><th>Mean</th><th>Std. dev.</th><th>CV</th>"
         "<th>Min</th><th>Q1</th><th>Median</th><th>Q3</th><th>Max</th><th>Time</th><th>Nodes</th>"
         "<th>Path length</th></tr></thead><tbody>\n";
  for (std::size_t c = 0; c < planners.size(); ++c) {
    const Json& pl = planners[c];
    const Json& cost = cost_of(pl);
    auto cell = [&](const char* key) { return "<td>" + style.format(text::number_at(cost, key)) + "</td>"; };
    auto median_of = [&](const char* metric) {
      return text::number_at(pl.contains(metric) ? pl[metric] : Json::object(), "median");
    };
    const double n = text::number_at(pl, "n"), solved = text::number_at(pl, "solved");
    out << "<tr><td>" << swatch(c) << "<strong>" << xml_escape(pl.value("name", std::string())) << "</strong></td><td>"
        << text::count(n) << "</td><td>" << text::count(solved) << " <small>"
        << (text::run_kind(pl) == text::RunKind::kWorldSequence ? "complete " : "") << "("
        << text::percent(text::number_at(pl, "solved_percent")) << ")</small></td>"
        << "<td>" << mark(best_mean == c, style.format(text::number_at(cost, "mean"))) << "</td>" << cell("std")
        << "<td>" << mark(low_cv == c, text::percent(std::round(text::number_at(cost, "cv_percent")))) << "</td>" << cell("min") << cell("q1")
        << cell("median") << cell("q3") << cell("max") << "<td>" << text::seconds(median_of("time_s")) << "</td><td>"
        << text::count(median_of("nodes")) << "</td><td>" << text::real(median_of("path_length")) << "</td></tr>\n";
  }
  out << "</tbody></table>\n";
  sequences_note(out, planners);
}

void phase_table(std::ostream& out, const Json& problem) {
  const Json& planners = problem.value("planners", Json::array());
  auto median = [](const Json& pl, const char* key) {
    const Json& phases = pl.contains("by_phase") ? pl["by_phase"] : Json::object();
    return text::number_at(phases.contains(key) ? phases[key] : Json::object(), "median");
  };
  const bool any_training = std::any_of(planners.begin(), planners.end(), [&](const Json& pl) {
    const double m = median(pl, "cd_calls_training");
    return std::isfinite(m) && m > 0.0;
  });
  if (!any_training) return;  // no learner in this experiment: the cost table says it all
  out << "<h3>Cost by phase (medians, as UAS\u2019s Table 4)</h3>\n<table class=\"stats\"><thead>"
         "<tr class=\"group\"><th></th><th colspan=\"3\">nodes</th><th colspan=\"4\">CD calls</th></tr>"
         "<tr><th>Planner</th><th>Training</th><th>Planning</th><th>Total</th><th>Training</th><th>Planning</th>"
         "<th>Total</th><th>CV of total</th></tr></thead><tbody>\n";
  for (std::size_t c = 0; c < planners.size(); ++c) {
    const Json& pl = planners[c];
    const Json& cost = pl.contains("cd_calls") ? pl["cd_calls"] : Json::object();  // CD calls whatever the cost
    const Json& nodes = pl.contains("nodes") ? pl["nodes"] : Json::object();
    out << "<tr><td>" << swatch(c) << "<strong>" << xml_escape(pl.value("name", std::string())) << "</strong></td><td>"
        << text::count(median(pl, "nodes_training")) << "</td><td>" << text::count(median(pl, "nodes_planning"))
        << "</td><td>" << text::count(text::number_at(nodes, "median")) << "</td><td>"
        << text::count(median(pl, "cd_calls_training")) << "</td><td>" << text::count(median(pl, "cd_calls_planning"))
        << "</td><td>" << text::count(text::number_at(cost, "median")) << "</td><td>"
        << text::percent(std::round(text::number_at(cost, "cv_percent"))) << "</td></tr>\n";
  }
  out << "</tbody></table>\n<p class=\"note\">Medians are taken per column, so training + planning need not "
         "equal the total. A reused training roadmap counts in the planning roadmap\u2019s total nodes.</p>\n";
}

void charts(std::ostream& out, const Experiment& e, const std::vector<std::vector<double>>& cost) {
  if (std::all_of(cost.begin(), cost.end(), [](const auto& g) { return g.empty(); })) {
    out << "<p class=\"note\">No runs to chart.</p>\n";
    return;
  }
  const bool log = heavy_tailed(cost);
  std::vector<viz::Series> series;
  for (std::size_t c = 0; c < cost.size() && c < e.planners.size(); ++c) {
    series.push_back({e.planners[c].label, planner_color(c), cost[c]});
  }
  viz::ChartOptions box;
  box.width_px = kBoxWidthPx;
  box.height_px = kBoxHeightPx;
  box.scale = log ? viz::AxisScale::kLog : viz::AxisScale::kLinear;
  const text::CostStyle style = text::cost_style(e.cost, e.cost_direction);
  box.title = style.higher() ? style.label + " per method (higher is better)" : std::string("Run cost per planner");
  box.value_label = style.label;
  const bool non_negative = std::all_of(cost.begin(), cost.end(), [](const auto& g) {
    return std::all_of(g.begin(), g.end(), [](double v) { return v >= 0.0; });
  });
  if (!log && non_negative) box.lo = 0.0;  // counts and lengths: a linear axis starts at zero
  out << "<div class=\"charts\"><figure class=\"box\">" << viz::box_plot_svg(series, box)
      << "<figcaption>Box: quartiles, bar: median, \u25c7: mean, whiskers: 1.5 IQR, dots: outliers"
      << (log ? "; log scale (the costs span more than " + text::count(kLogSpan) + "\u00d7)" : std::string())
      << ".</figcaption></figure>\n<div class=\"hists\">\n";

  const std::vector<double> edges = shared_edges(cost, log);
  std::vector<std::vector<std::size_t>> counts;
  double count_max = 1.0;
  for (const auto& g : cost) {
    counts.push_back(stats::bin_counts(g, edges));
    for (std::size_t k : counts.back()) count_max = std::max(count_max, static_cast<double>(k));
  }
  for (std::size_t c = 0; c < series.size(); ++c) {
    viz::ChartOptions h;
    h.width_px = kHistWidthPx;
    h.height_px = kHistHeightPx;
    h.scale = box.scale;
    h.count_max = count_max;
    h.title = series[c].label + (series[c].values.empty() ? " (no runs)" : "");
    out << "<figure>" << viz::histogram_svg(edges, counts[c], series[c].color, h) << "</figure>\n";
  }
  out << "</div></div>\n<p class=\"note\">Histograms share their bins (Freedman\u2013Diaconis over all planners"
      << (log ? ", equal in log scale" : "") << ") and their count axis.</p>\n";
}

const char* const kStyle = R"css(
*{box-sizing:border-box}
body{margin:0;background:#f3f5f8;color:#1f2933;font:14px/1.5 system-ui,-apple-system,"Segoe UI",Helvetica,Arial,sans-serif}
.wrap{max-width:1180px;margin:0 auto;padding:0 28px}
header.top{background:#1f2933;color:#f5f7fa;padding:26px 0 20px}
header.top .kicker{margin:0;color:#9aa5b1;text-transform:uppercase;letter-spacing:.08em;font-size:12px}
header.top h1{margin:2px 0 16px;font-size:28px;font-weight:650}
dl.meta{display:grid;grid-template-columns:repeat(auto-fill,minmax(205px,1fr));gap:10px 22px;margin:0}
dl.meta dt{color:#9aa5b1;font-size:11px;text-transform:uppercase;letter-spacing:.05em}
dl.meta dd{margin:0;font-size:14px;overflow-wrap:anywhere}
dl.meta .wide{grid-column:1/-1}
dl.meta code{background:#323f4b;color:#e4e7eb}
main{padding-top:8px;padding-bottom:8px}
.card{background:#fff;border:1px solid #e1e5ea;border-radius:10px;padding:18px 24px 20px;margin:22px 0;box-shadow:0 1px 3px rgba(31,41,51,.06)}
h2{font-size:20px;margin:4px 0 12px}
h2 .file{font-size:13px;font-weight:400;color:#7b8794;margin-left:8px}
h3{font-size:15px;margin:18px 0 8px}
table{border-collapse:collapse;width:100%;font-variant-numeric:tabular-nums}
th,td{padding:6px 9px;border-bottom:1px solid #e9ecf0;text-align:right;vertical-align:top}
th:first-child,td:first-child{text-align:left}
thead th{font-size:11px;text-transform:uppercase;letter-spacing:.04em;color:#616e7c;font-weight:600;border-bottom:2px solid #d5dae1}
tr.group th{border-bottom:1px solid #e9ecf0;text-align:center;text-transform:none;font-weight:500;color:#7b8794}
table.configs td,table.configs th{text-align:left}
td:first-child{white-space:nowrap}
table.stats td{white-space:nowrap}
figure.box{width:470px}
tbody tr:hover{background:#f8f9fb}
small{color:#616e7c}
.best{background:#e3f4e8;color:#145a32;font-weight:650;border-radius:3px;padding:1px 4px}
.swatch{display:inline-block;width:10px;height:10px;border-radius:2px;margin-right:7px;vertical-align:baseline}
.row{display:grid;grid-template-columns:440px 1fr;gap:26px;align-items:start}
.findings ul{margin:0;padding-left:18px}
.findings li{margin:0 0 7px}
.findings h3{margin-top:4px}
em{font-style:normal;font-weight:600}
figure{margin:0}
figcaption,.note{font-size:12px;color:#616e7c;margin:6px 0 0}
svg{display:block;max-width:100%;height:auto}
.charts{display:flex;flex-wrap:wrap;gap:14px 22px;margin-top:14px;align-items:flex-start}
.hists{display:grid;grid-template-columns:repeat(2,270px);gap:6px 10px}
code{font-family:ui-monospace,Menlo,Consolas,monospace;font-size:12px;background:#eef1f4;padding:1px 5px;border-radius:4px}
a{color:#2563eb;text-decoration:none}
footer{color:#7b8794;font-size:12px;padding-bottom:36px}
@media (max-width:900px){.row{grid-template-columns:1fr}.hists{grid-template-columns:1fr}}
)css";

}  // namespace amp::bench::report_page
