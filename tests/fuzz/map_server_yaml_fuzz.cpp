// ROS map_server YAML files, with the image they name (problems/maps is linked as maps/).
#include "amp/world/map_server_loader.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = amp::fuzz::write_input(data, size, "input.yaml");
  amp::fuzz::expect_amp_errors_only([&] { amp::world::load_map_server(file); });
  return 0;
}
