// An experiment with `cost: path_length`, run for real: summary.json's cost statistics and tests,
// and the report's headings, agree with what is computed here from runs.csv alone (its own CSV
// split, no RunsCsvReader).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "amp/bench/bench_runner.hpp"
#include "support/source_tree.hpp"

namespace amp::bench {
namespace {

namespace fs = std::filesystem;

// runs.csv as rows of column name -> text (these rows hold no quoted fields: no message, no comma).
std::vector<std::map<std::string, std::string>> read_csv(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
    if (line.back() == ',') cells.emplace_back();
    if (header.empty()) {
      header = cells;
      continue;
    }
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < header.size() && i < cells.size(); ++i) row[header[i]] = cells[i];
    rows.push_back(row);
  }
  return rows;
}

TEST(CostFromRuns, PathLengthCostIsComputedFromSolvedRunsOfRunsCsv) {
  const fs::path root = fs::temp_directory_path() / ("amp-cost-from-runs-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root);
  const fs::path office = fs::path(AMP_SOURCE_DIR) / "problems" / "office-map.yaml";
  // A time limit that never binds: the results are the same on a loaded machine.
  std::ofstream(root / "exp.yaml") << "name: by-length\nseed: 5\nruns: 5\ntime_limit: 600\nnode_limit: 20000\n"
                                   << "cost: path_length\nproblems: [" << office.string() << "]\n"
                                   << "planners:\n  - prm\n  - {name: prm-k20, planner: prm, params: {k: 20}}\n";
  BenchOptions o;
  o.out_dir = root / "out";
  o.threads = 2;
  run_experiment(load_experiment(root / "exp.yaml"), o);

  std::map<std::string, std::vector<double>> lengths;  // solved runs' path_length per configuration
  for (const auto& row : read_csv(o.out_dir / "runs.csv")) {
    if (row.at("status") == "solved") lengths[row.at("planner")].push_back(std::stod(row.at("path_length")));
  }
  const nlohmann::json s = nlohmann::json::parse(std::ifstream(o.out_dir / "summary.json"));
  const auto& problem = s["problems"][0];
  EXPECT_EQ(problem["tests"]["metric"], "path_length");
  for (const auto& pl : problem["planners"]) {
    std::vector<double> x = lengths[pl["name"].get<std::string>()];
    ASSERT_GE(x.size(), 2u) << pl["name"];
    std::sort(x.begin(), x.end());
    double sum = 0.0;
    for (double v : x) sum += v;
    const double mean = sum / static_cast<double>(x.size());
    double ss = 0.0;
    for (double v : x) ss += (v - mean) * (v - mean);
    // Type-7 median: the middle value, or the mean of the two middle ones.
    const std::size_t n = x.size();
    const double median = n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
    const auto& cost = pl["cost"];
    EXPECT_EQ(cost["metric"], "path_length");
    EXPECT_EQ(cost["n"].get<std::size_t>(), n);
    EXPECT_NEAR(cost["mean"].get<double>(), mean, 1e-9 * mean);
    EXPECT_NEAR(cost["std"].get<double>(), std::sqrt(ss / static_cast<double>(n - 1)), 1e-9 * mean);
    EXPECT_NEAR(cost["median"].get<double>(), median, 1e-9 * mean);
    EXPECT_EQ(cost["min"].get<double>(), x.front());
    EXPECT_EQ(cost["max"].get<double>(), x.back());
    // The run-cost column keeps its own meaning beside the cost.
    EXPECT_EQ(pl["cd_calls"]["n"].get<std::size_t>(), 5u);
  }
  std::ifstream report(o.out_dir / "report.html");
  const std::string html((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
  EXPECT_NE(html.find("Run cost: path_length"), std::string::npos);
  EXPECT_EQ(html.find("Run cost in collision-detection calls"), std::string::npos);
  fs::remove_all(root);
}

}  // namespace
}  // namespace amp::bench
