// `amp explore`: PGCS exploration of a 2-D world by a simulated disc robot (Vlassis, Papakonstantinou
// & Tsanakas), then trial-and-error queries on the learned graph; prints the flat record, draws the
// paper's Figure 1, the curves and the driven queries.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "amp/core/error.hpp"
#include "amp/core/parameters.hpp"
#include "amp/world/problem.hpp"
#include "cli_util.hpp"
#include "problem_input.hpp"
#include "commands.hpp"
#include "amp/study/explore_study.hpp"

namespace amp::cli {

namespace {

struct ExploreOptions {
  std::string problem;
  MapQuery map;                  // with a map_server YAML as the problem
  const CLI::App* cmd = nullptr;  // to tell which options were given
  long steps = nav::PgcsRunSettings{}.steps;
  int max_clusters = learn::PgcsSettings{}.max_clusters;
  std::uint64_t seed = 1;
  int queries = nav::PgcsRunSettings{}.queries;
  std::vector<double> query;  // SX SY GX GY, four per --query
  std::string exploration = nav::PgcsRunSettings{}.exploration;
  std::vector<std::string> params;
  std::string output;
  bool json = false;
  bool force = false;
  // Which of the named options the user gave (they must not also come as --param).
  std::vector<std::pair<std::string, const CLI::Option*>> named;
};

constexpr double kProgressAfterS = 1.0;  // short explorations draw no bar (nothing to wait for)

// A bar on stderr while exploring, only on a terminal: a pipe or a file (tests, scripts) gets
// stderr's one-line error contract untouched.
std::function<void(long, long)> progress_bar() {
  if (isatty(STDERR_FILENO) == 0) return {};
  const auto t0 = std::chrono::steady_clock::now();
  auto shown = std::make_shared<bool>(false);
  return [t0, shown](long done, long total) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (elapsed < kProgressAfterS && !*shown) return;
    *shown = true;
    constexpr int kWidth = 30;
    const double frac = total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 1.0;
    const int fill = static_cast<int>(frac * kWidth);
    const double remaining = done > 0 ? elapsed * static_cast<double>(total - done) / static_cast<double>(done) : 0.0;
    std::fprintf(stderr, "\r[%s%s] %ld/%ld steps  elapsed %.0f s  remaining %.0f s ", std::string(fill, '#').c_str(),
                 std::string(kWidth - fill, '.').c_str(), done, total, elapsed, remaining);
    if (done >= total) std::fputc('\n', stderr);
    std::fflush(stderr);
  };
}

// The settings: the defaults, then --param name=value (PGCS's and the run's parameters by their
// schema names), then the named options.
study::ExploreSetup read_setup(const ExploreOptions& o) {
  const core::ParamMap given = parse_params(o.params);
  for (const auto& [name, option] : o.named) {
    if (option->count() > 0 && given.contains(name)) {
      throw ParameterError(option->get_name() + ": also given as --param " + name + "=...; give it once");
    }
  }
  study::ExploreSetup setup;
  try {
    study::read_explore_params(given, setup);
  } catch (const ParameterError& e) {
    throw ParameterError(std::string("--param: ") + e.what());
  }
  for (const auto& [name, option] : o.named) {
    if (option->count() == 0) continue;
    if (name == "steps") setup.run.steps = o.steps;
    if (name == "queries") setup.run.queries = o.queries;
    if (name == "exploration") setup.run.exploration = o.exploration;
    if (name == "max_clusters") setup.pgcs.max_clusters = o.max_clusters;
  }
  setup.run.validate();
  setup.pgcs.validate();
  setup.seed = o.seed;
  for (std::size_t i = 0; i + 3 < o.query.size(); i += 4) {
    setup.queries.push_back({{o.query[i], o.query[i + 1]}, {o.query[i + 2], o.query[i + 3]}});
  }
  return setup;
}

int run_explore(const ExploreOptions& o) {
  if (o.query.size() % 4 != 0) {
    throw ParameterError("--query: expected four numbers SX SY GX GY, got " + std::to_string(o.query.size()));
  }
  if (!o.output.empty()) study::check_explore_dir(o.output, o.force, "-o");
  study::ExploreSetup setup = read_setup(o);
  const world::Problem problem = load_problem_input(o.problem, o.map, false, *o.cmd);
  setup.progress = progress_bar();
  const study::ExploreResult result = study::run_exploration(problem, setup);
  if (o.json) {
    std::cout << result.record.dump(2) << '\n';
  } else {
    std::cout << study::format_explore_table(result.record);
  }
  if (!o.output.empty()) {
    study::write_explore_outputs(problem, result, o.output);
    if (!o.json) {
      std::cout << "written to " << o.output << "/:";
      for (const std::string& f : study::explore_output_files()) std::cout << ' ' << f;
      std::cout << '\n';
    }
  }
  // An unsolvable query is a result (queries_solved counts it), not a failure of the command.
  return kExitOk;
}

}  // namespace

void add_explore_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<ExploreOptions>();
  CLI::App* cmd = app.add_subcommand("explore", "PGCS exploration of a 2-D world by a disc robot, then queries "
                                                "on the learned graph; prints the record, draws Figure 1");
  cmd->add_option("problem", o->problem, "Problem file (2-D world, disc robot; exploration starts at its start), or a ROS map_server YAML with --start")
      ->required();
  o->named.emplace_back("steps", cmd->add_option("--steps", o->steps, "Exploration steps [" + std::to_string(nav::PgcsRunSettings{}.steps) + "]")
                                     ->check(positive_integer()));
  o->named.emplace_back("max_clusters", cmd->add_option("--max-clusters", o->max_clusters,
                                                        "No insertion beyond this many clusters (>= 3) [" +
                                                            std::to_string(learn::PgcsSettings{}.max_clusters) + "]")
                                            ->check(CLI::Range(3, 1000000)));
  cmd->add_option("--seed", o->seed, "Random seed (exploration and query pairs) [1]")->check(unsigned_integer());
  o->named.emplace_back("queries", cmd->add_option("--queries", o->queries,
                                                   "Random query pairs reachable from the start [" +
                                                       std::to_string(nav::PgcsRunSettings{}.queries) + "]")
                                       ->check(CLI::Range(0, 1000000)));
  cmd->add_option("--query", o->query, "A query SX SY GX GY instead of the random ones (repeatable)")
      ->type_name("SX SY GX GY")
      ->type_size(4)  // four numbers per --query, any number of --query
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  o->named.emplace_back("exploration", cmd->add_option("--exploration", o->exploration,
                                                       "How the robot explores: random-walk or novelty [random-walk]")
                                           ->check(CLI::IsMember({"random-walk", "novelty"})));
  cmd->add_option("--param", o->params,
                  "PGCS or run parameter name=value (repeatable): window (l), insert_every (N), delete_every (M), "
                  "...; an unknown name lists them all");
  cmd->add_option("-o,--output", o->output, "Directory for figure1.svg, curves.svg, queries.svg, record.json");
  cmd->add_flag("--json", o->json, "Print the record as one flat JSON object");
  cmd->add_flag("--force", o->force, "Overwrite existing output files");
  add_map_query_options(cmd, o->map);
  o->cmd = cmd;
  cmd->callback([o, &exit_code] { exit_code = run_explore(*o); });
}

}  // namespace amp::cli
