// `amp plan --planner grid-dp` on 512 x 512 MovingAI maps with default options (issue 34): grid-dp
// has no node limit of its own, so it returns the optimal octile length, checked against a Dijkstra
// written here; a limit given on the command line, in the problem or in an experiment still stops it.
#include <cmath>
#include <cstdint>
#include <fstream>
#include <functional>
#include <limits>
#include <numbers>
#include <queue>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "amp/core/rng.hpp"
#include "support/cli_errors_fixture.hpp"

namespace {

using namespace amp::test;  // CliErrors, RunResult, read_file, kExit*

constexpr int kSide = 512;  // as the MovingAI maps of the issue
// The roadmap planners' node limit, which grid-dp used to get: each map must need more cells.
constexpr double kRoadmapNodeLimit = 20000;
constexpr double kRelativeTolerance = 1e-6;
constexpr double kUnreached = std::numeric_limits<double>::infinity();

// A map as MovingAI's text rows: rows[0] is the top (largest y), '.' free, '@' blocked.
using Rows = std::vector<std::string>;

struct Cell {
  int row = 0;
  int col = 0;
};

bool free_at(const Rows& m, int row, int col) {
  if (row < 0 || col < 0 || row >= kSide || col >= kSide) return false;  // outside the map is blocked
  return m[static_cast<std::size_t>(row)][static_cast<std::size_t>(col)] == '.';
}

// A perfect maze of 255 x 255 rooms at odd coordinates (depth-first, every room reachable), then
// loops (one wall in 32 removed) and a few open halls, so that shortest paths have choices and
// diagonal steps.
Rows maze_map(std::uint64_t seed) {
  Rows m(kSide, std::string(kSide, '@'));
  amp::core::Rng rng(seed);
  constexpr int kRooms = (kSide - 1) / 2;
  const auto carve = [&m](int row, int col) { m[static_cast<std::size_t>(row)][static_cast<std::size_t>(col)] = '.'; };
  std::vector<Cell> stack = {{0, 0}};
  std::vector<bool> seen(kRooms * kRooms, false);
  seen[0] = true;
  carve(1, 1);
  const int dr[4] = {1, -1, 0, 0}, dc[4] = {0, 0, 1, -1};
  while (!stack.empty()) {
    const Cell c = stack.back();
    std::vector<int> open;
    for (int k = 0; k < 4; ++k) {
      const int r = c.row + dr[k], q = c.col + dc[k];
      const bool inside = r >= 0 && q >= 0 && r < kRooms && q < kRooms;
      if (inside && !seen[static_cast<std::size_t>(r * kRooms + q)]) open.push_back(k);
    }
    if (open.empty()) {
      stack.pop_back();
      continue;
    }
    const int k = open[rng.uniform_index(open.size())];
    const Cell n{c.row + dr[k], c.col + dc[k]};
    seen[static_cast<std::size_t>(n.row * kRooms + n.col)] = true;
    carve(2 * c.row + 1 + dr[k], 2 * c.col + 1 + dc[k]);
    carve(2 * n.row + 1, 2 * n.col + 1);
    stack.push_back(n);
  }
  constexpr std::uint64_t kOneWallIn = 32;
  for (int r = 1; r < kSide - 2; ++r) {
    for (int q = 1; q < kSide - 2; ++q) {
      if ((r + q) % 2 == 1 && rng.uniform_index(kOneWallIn) == 0) carve(r, q);  // a wall between two rooms
    }
  }
  constexpr int kHalls = 12, kHallSide = 24;
  for (int h = 0; h < kHalls; ++h) {
    const int r0 = 1 + static_cast<int>(rng.uniform_index(kSide - kHallSide - 3));
    const int q0 = 1 + static_cast<int>(rng.uniform_index(kSide - kHallSide - 3));
    for (int r = r0; r < r0 + kHallSide; ++r) {
      for (int q = q0; q < q0 + kHallSide; ++q) carve(r, q);
    }
  }
  return m;
}

// Each cell blocked with probability 0.3: above the percolation threshold of the free cells, so
// one component spans the map.
Rows random_map(std::uint64_t seed) {
  constexpr double kBlocked = 0.3;
  Rows m(kSide, std::string(kSide, '.'));
  amp::core::Rng rng(seed);
  for (std::string& row : m) {
    for (char& c : row) c = rng.uniform01() < kBlocked ? '@' : '.';
  }
  return m;
}

// Octile distances from `from` to every cell: 8-connected, steps 1 and sqrt(2), a diagonal step
// only when both cells beside it are free (no corner cutting), as grid-dp's GridCostToGo.
std::vector<double> dijkstra(const Rows& m, Cell from) {
  std::vector<double> dist(kSide * kSide, kUnreached);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  dist[static_cast<std::size_t>(from.row * kSide + from.col)] = 0.0;
  open.emplace(0.0, from.row * kSide + from.col);
  while (!open.empty()) {
    const auto [d, i] = open.top();
    open.pop();
    if (d > dist[static_cast<std::size_t>(i)]) continue;
    const int r = i / kSide, q = i % kSide;
    for (int dr = -1; dr <= 1; ++dr) {
      for (int dq = -1; dq <= 1; ++dq) {
        if ((dr == 0 && dq == 0) || !free_at(m, r + dr, q + dq)) continue;
        const bool diagonal = dr != 0 && dq != 0;
        if (diagonal && !(free_at(m, r + dr, q) && free_at(m, r, q + dq))) continue;
        const double nd = d + (diagonal ? std::numbers::sqrt2 : 1.0);
        const std::size_t n = static_cast<std::size_t>((r + dr) * kSide + q + dq);
        if (nd < dist[n]) {
          dist[n] = nd;
          open.emplace(nd, static_cast<int>(n));
        }
      }
    }
  }
  return dist;
}

// A free cell near the top-left corner and the cell reachable from it farthest along the diagonal.
std::pair<Cell, Cell> far_apart(const Rows& m) {
  Cell start{-1, -1};
  for (int s = 0; s < 2 * kSide && start.row < 0; ++s) {
    for (int r = 0; r <= s && start.row < 0; ++r) {
      if (free_at(m, r, s - r)) start = {r, s - r};
    }
  }
  const std::vector<double> dist = dijkstra(m, start);
  Cell goal = start;
  for (int i = 0; i < kSide * kSide; ++i) {
    const Cell c{i / kSide, i % kSide};
    if (dist[static_cast<std::size_t>(i)] < kUnreached && c.row + c.col > goal.row + goal.col) goal = c;
  }
  return {start, goal};
}

class CliGridDpMaps : public CliErrors {
 protected:
  // Writes the map and a problem for a point robot between cell centres; returns the problem's
  // path quoted for the shell. `defaults` is extra YAML (e.g. a problem node limit).
  std::string write_problem(const std::string& name, const Rows& m, Cell start, Cell goal,
                            const std::string& defaults = "") const {
    std::ofstream map(dir_ / (name + ".map"));
    map << "type octile\nheight " << kSide << "\nwidth " << kSide << "\nmap\n";
    for (const std::string& row : m) map << row << '\n';
    std::ofstream yaml(dir_ / (name + ".yaml"));
    yaml << "name: " << name << "\nworld: {map: " << name << ".map, resolution: 1.0}\nrobot: {type: point}\n"
         << "start: " << centre(start) << "\ngoal: " << centre(goal) << '\n' << defaults;
    return "'" + (dir_ / (name + ".yaml")).string() + "'";
  }

  // Plans with no limit flags and checks the run against the Dijkstra's optimum.
  void expect_optimal(const std::string& name, const Rows& m) const {
    const auto [start, goal] = far_apart(m);
    const double optimum = dijkstra(m, start)[static_cast<std::size_t>(goal.row * kSide + goal.col)];
    ASSERT_LT(optimum, kUnreached);
    const RunResult r = run("plan " + write_problem(name, m, start, goal) + " --planner grid-dp --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("status"), "solved");
    EXPECT_NEAR(j.at("path_length").get<double>(), optimum, kRelativeTolerance * optimum);
    // The old default (the roadmaps' 20000) would have stopped this search.
    EXPECT_GT(j.at("nodes").get<double>(), kRoadmapNodeLimit);
  }

  static std::string centre(Cell c) {  // MovingAI's first row is the top: y counts from the last
    return "[" + std::to_string(c.col + 0.5) + ", " + std::to_string(kSide - 1 - c.row + 0.5) + "]";
  }
};

TEST_F(CliGridDpMaps, MazeWithDefaultOptionsIsOptimal) { expect_optimal("maze", maze_map(34)); }

TEST_F(CliGridDpMaps, RandomObstaclesWithDefaultOptionsIsOptimal) { expect_optimal("random", random_map(34)); }

// Node limits given explicitly still stop grid-dp, at exactly that many settled cells.
TEST_F(CliGridDpMaps, CommandLineNodeLimitStillApplies) {
  const Rows m = random_map(34);
  const auto [start, goal] = far_apart(m);
  const std::string problem = write_problem("random", m, start, goal);
  const RunResult r = run("plan " + problem + " --planner grid-dp --json --node-limit 1000");
  EXPECT_EQ(r.exit_code, kExitNotSolved) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("status"), "node_limit");
  EXPECT_EQ(j.at("nodes"), 1000);
  EXPECT_NE(r.err.find("node limit 1000"), std::string::npos) << r.err;
}

TEST_F(CliGridDpMaps, ProblemNodeLimitStillAppliesAndTheCommandLineWins) {
  const Rows m = random_map(34);
  const auto [start, goal] = far_apart(m);
  const std::string problem = write_problem("random", m, start, goal, "defaults: {node_limit: 1000}\n");
  const RunResult limited = run("plan " + problem + " --planner grid-dp --json");
  EXPECT_EQ(limited.exit_code, kExitNotSolved) << limited.err;
  EXPECT_EQ(nlohmann::json::parse(limited.out).at("status"), "node_limit");
  const RunResult wider = run("plan " + problem + " --planner grid-dp --json --node-limit 100000000");
  EXPECT_EQ(wider.exit_code, 0) << wider.err;
  EXPECT_EQ(nlohmann::json::parse(wider.out).at("status"), "solved");
}

// `amp bench` resolves the limit as `amp plan` does: none given, grid-dp solves; given, it stops.
TEST_F(CliGridDpMaps, ExperimentNodeLimitOnlyWhenGiven) {
  const Rows m = random_map(34);
  const auto [start, goal] = far_apart(m);
  write_problem("random", m, start, goal);
  const auto bench = [this](const std::string& name, const std::string& limit) {
    std::ofstream(dir_ / (name + ".yaml")) << "name: " << name << "\nruns: 1\n" << limit
                                           << "problems: [random.yaml]\nplanners: [grid-dp]\n";
    const RunResult r = run("bench " + name + ".yaml -j 1 --out " + name);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return nlohmann::json::parse(read_file(dir_ / name / "summary.json"));
  };
  const nlohmann::json open = bench("open", "");
  EXPECT_TRUE(open.at("experiment").at("node_limit").is_null());
  EXPECT_EQ(open.at("problems")[0].at("planners")[0].at("solved"), 1);
  const nlohmann::json capped = bench("capped", "node_limit: 1000\n");
  EXPECT_EQ(capped.at("experiment").at("node_limit"), 1000);
  EXPECT_EQ(capped.at("problems")[0].at("planners")[0].at("solved"), 0);
}

}  // namespace
