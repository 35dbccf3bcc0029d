// YAML problem files (docs/problem-format.md): planar, 3-D and map worlds, robots, seeds, defaults
// and events, as `amp plan` loads them.
#include "amp/world/problem.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = amp::fuzz::write_input(data, size, "input.yaml");
  amp::fuzz::expect_amp_errors_only([&] { amp::world::load_problem(file); });
  return 0;
}
