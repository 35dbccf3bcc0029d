// PGM images (P2 and P5), as map_server YAML files and problem files refer to them.
#include "amp/world/map_server_loader.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = amp::fuzz::write_input(data, size, "input.pgm");
  amp::fuzz::expect_amp_errors_only([&] { amp::world::read_pgm(file); });
  return 0;
}
