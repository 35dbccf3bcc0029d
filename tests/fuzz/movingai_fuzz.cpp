// MovingAI `.map` benchmark maps.
#include "amp/world/movingai_loader.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = amp::fuzz::write_input(data, size, "input.map");
  amp::fuzz::expect_amp_errors_only([&] { amp::world::load_movingai(file); });
  return 0;
}
