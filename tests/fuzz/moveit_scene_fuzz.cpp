// MoveIt PlanningScene YAML (world::parse_moveit_scene), in robowflex's form and the plain
// ROS-message form: collision objects (primitives, meshes), the allowed collision matrix, the
// robot state.
#include <string>

#include "amp/world/moveit_files.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string yaml(reinterpret_cast<const char*>(data), size);
  amp::fuzz::expect_amp_errors_only([&] { amp::world::parse_moveit_scene(yaml, "input.yaml"); });
  return 0;
}
