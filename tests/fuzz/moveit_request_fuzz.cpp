// MoveIt MotionPlanRequest YAML (world::parse_moveit_request): the group, the start state, one
// goal of joint constraints, the planning time.
#include <string>

#include "amp/world/moveit_files.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string yaml(reinterpret_cast<const char*>(data), size);
  amp::fuzz::expect_amp_errors_only([&] { amp::world::parse_moveit_request(yaml, "input.yaml"); });
  return 0;
}
