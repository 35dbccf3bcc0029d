// Loads a problem, runs PRM with seed 1 for at most 10 s, and prints the run record.
#include <exception>
#include <iostream>

#include "amp/bench/record_format.hpp"
#include "amp/roadmap/run.hpp"
#include "amp/world/problem.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: plan_a_problem PROBLEM.yaml\n";
    return 2;
  }
  try {
    const amp::world::Problem problem = amp::world::load_problem(argv[1]);
    const amp::roadmap::RunOutcome run = amp::roadmap::execute_run(problem, "prm", {}, 1, 10.0, 20000);
    std::cout << amp::bench::format_table(run.record);
    return run.record.status == amp::core::PlanStatus::kSolved ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "plan_a_problem: " << e.what() << "\n";
    return 1;
  }
}
