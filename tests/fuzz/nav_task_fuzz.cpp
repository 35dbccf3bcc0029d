// What `amp explore` and `amp navigate` read: a problem file (or a map_server YAML) made into a
// navigation task, its `events:` list applied to the world.
#include "amp/nav/nav_task.hpp"
#include "amp/world/problem.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = amp::fuzz::write_input(data, size, "input.yaml");
  amp::fuzz::expect_amp_errors_only([&] {
    const amp::world::Problem problem = amp::world::is_map_server_yaml(file)
        ? amp::world::load_map_problem(file, Eigen::Vector2d(1.0, 1.0), Eigen::Vector2d(2.0, 2.0), 0.22)
        : amp::world::load_problem(file);
    amp::nav::make_nav_task(problem);
  });
  return 0;
}
