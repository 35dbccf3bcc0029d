// STL meshes through assimp (world::load_mesh), as problem files and OMPL.app .cfg files load them.
#include "amp/world/mesh_loader.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = amp::fuzz::write_input(data, size, "input.stl");
  amp::fuzz::expect_amp_errors_only([&] { amp::world::load_mesh(file); });
  return 0;
}
