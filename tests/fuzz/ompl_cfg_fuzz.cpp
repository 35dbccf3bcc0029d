// OMPL.app `.cfg` problems; the meshes of problems/ompl sit beside the input.
#include "amp/world/problem.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = amp::fuzz::write_input(data, size, "input.cfg");
  amp::fuzz::expect_amp_errors_only([&] { amp::world::load_problem(file); });
  return 0;
}
