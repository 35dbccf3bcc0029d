// The report's links to 3-D viewer pages: each row's first run of a 3-D problem, re-run from its
// seed (runs.csv keeps no paths) and written as a page beside the report.
#include <fstream>
#include <sstream>

#include "amp/bench/bench_runner.hpp"
#include "amp/core/error.hpp"
#include "amp/viz/viewer_page.hpp"
#include "amp/viz/xml_escape.hpp"
#include "report_page.hpp"

namespace amp::bench::report_page {

namespace {

// A file name from a label: letters, digits, '-' and '_' kept, anything else '-'.
std::string file_slug(const std::string& label) {
  std::string slug;
  for (const char c : label) slug.push_back(std::isalnum(static_cast<unsigned char>(c)) || c == '_' ? c : '-');
  return slug;
}

void write_page(const std::filesystem::path& file, const std::string& page) {
  std::ofstream f(file, std::ios::binary);
  if (!f) throw FileError(file.string() + ": cannot open for writing");
  f << page;
  if (!f) throw FileError(file.string() + ": write failed");
}

// The row's first run as a page in dir/viewer/; the link's text, or why there is no page.
std::string row_page(const Experiment& e, std::size_t p, std::size_t m, std::size_t index,
                     const std::filesystem::path& dir) {
  const auto& problem = *e.problems[p].problem;
  const std::string& label = e.planners[m].label;
  std::vector<State> path;
  const Trial t = run_trial(e, index, nullptr, &path);
  // A run near the time limit may not solve again: the limit is wall time, not a count.
  if (t.record.status != core::PlanStatus::kSolved || path.empty()) {
    return viz::xml_escape(label) + " (re-running seed " + std::to_string(t.seed) + " did not solve again)";
  }
  std::ostringstream name_text;  // (a chain of string + string trips GCC 12's -Wstringop-overflow)
  name_text << 'p' << p << '-' << file_slug(e.problems[p].label) << '-' << m << '-' << file_slug(label) << ".html";
  const std::string name = name_text.str();
  viz::ViewerContent content =
      viz::path_content(problem, std::move(path), label + ", run 0, seed " + std::to_string(t.seed));
  content.title = e.problems[p].label + " \u2014 " + label;
  std::filesystem::create_directories(dir / "viewer");
  write_page(dir / "viewer" / name, viz::viewer_page(problem, content));
  return "<a href=\"viewer/" + viz::xml_escape(name) + "\">" + viz::xml_escape(label) + "</a>";
}

}  // namespace

std::string viewer_links(const Experiment& e, std::size_t p, const RunData& runs, const std::filesystem::path& dir) {
  const auto& problem = e.problems[p].problem;
  if (problem == nullptr || problem->environment->workspace_dimension() != 3 || p >= runs.first_run_solved.size()) {
    return {};
  }
  std::vector<std::string> links;
  for (std::size_t m = 0; m < e.planners.size(); ++m) {
    if (const auto& index = runs.first_run_solved[p][m]) links.push_back(row_page(e, p, m, *index, dir));
  }
  if (links.empty()) return {};
  std::string html = "<p class=\"views\">In 3-D, each row\u2019s first run (its first seed), the robot playing its "
                     "path: ";
  for (std::size_t i = 0; i < links.size(); ++i) html += (i > 0 ? " \u00b7 " : "") + links[i];
  return html + ".</p>";
}

}  // namespace amp::bench::report_page
