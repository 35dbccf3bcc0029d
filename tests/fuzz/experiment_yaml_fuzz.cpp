// Experiment files (docs/experiment-format.md): the bundled problems are linked beside the input.
#include "amp/bench/experiment.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = amp::fuzz::write_input(data, size, "input.yaml");
  amp::fuzz::expect_amp_errors_only([&] { amp::bench::load_experiment(file); });
  return 0;
}
