// The report's table of the metrics besides the cost (summary.json's "metrics"): descriptive only,
// since the tests between methods are on the experiment's cost.
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "amp/viz/xml_escape.hpp"
#include "report_page.hpp"
#include "report_text.hpp"

namespace amp::bench::report_page {

void metrics_table(std::ostream& out, const nlohmann::json& problem) {
  namespace text = report_text;
  using Json = nlohmann::json;
  const Json& planners = problem.value("planners", Json::array());
  std::set<std::string> names;  // sorted: the same rows whatever the methods' order
  for (const Json& pl : planners) {
    if (!pl.contains("metrics")) continue;
    for (const auto& [name, stats] : pl["metrics"].items()) names.insert(name);
  }
  if (names.empty()) return;
  out << "<h3>Other metrics (descriptive)</h3>\n<table class=\"stats\"><thead><tr><th>Metric</th>";
  for (std::size_t c = 0; c < planners.size(); ++c) {
    out << "<th>" << "<span class=\"swatch\" style=\"background:" << planner_color(c) << "\"></span>"
        << viz::xml_escape(planners[c].value("name", std::string())) << "</th>";
  }
  out << "</tr></thead><tbody>\n";
  for (const std::string& name : names) {
    out << "<tr><td><code>" << viz::xml_escape(name) << "</code></td>";
    for (const Json& pl : planners) {
      const Json& m = pl.contains("metrics") && pl["metrics"].contains(name) ? pl["metrics"][name] : Json::object();
      if (m.empty()) {
        out << "<td>\u2013</td>";
        continue;
      }
      out << "<td>" << text::count(text::number_at(m, "median")) << "<br><small>"
          << text::count(text::number_at(m, "q1")) << "\u2013" << text::count(text::number_at(m, "q3"))
          << " \u00b7 n = " << text::count(text::number_at(m, "n")) << "</small></td>";
    }
    out << "</tr>\n";
  }
  out << "</tbody></table>\n<p class=\"note\">Median, quartiles (small) and the number of runs that report "
         "the metric; values that are not finite are left out.</p>\n";
}

}  // namespace amp::bench::report_page
