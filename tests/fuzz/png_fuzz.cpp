// PNG images through libpng, in the three map_server modes (the last byte picks one, so that every
// mode meets every image).
#include "amp/world/map_server_loader.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = amp::fuzz::write_input(data, size, "input.png");
  using amp::world::MapMode;
  const MapMode modes[] = {MapMode::kTrinary, MapMode::kScale, MapMode::kRaw};
  const MapMode mode = size == 0 ? MapMode::kTrinary : modes[data[size - 1] % 3];
  amp::fuzz::expect_amp_errors_only([&] { amp::world::read_png(file, mode); });
  return 0;
}
