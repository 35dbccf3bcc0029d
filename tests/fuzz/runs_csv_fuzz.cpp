// runs.csv as `amp bench --resume` and `amp merge` read it back (bench::for_each_trial), for the
// experiment of fixtures/runs-experiment.yaml.
#include "amp/bench/experiment.hpp"
#include "amp/bench/runs_csv.hpp"
#include "fuzz_input.hpp"
#include "support/source_tree.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const amp::bench::Experiment experiment =
      amp::bench::load_experiment(std::filesystem::path(AMP_SOURCE_DIR) / "tests/fuzz/fixtures/runs-experiment.yaml");
  const auto file = amp::fuzz::write_input(data, size, "runs.csv");
  amp::fuzz::expect_amp_errors_only([&] {
    std::uintmax_t complete = 0;
    std::size_t trials = 0;
    amp::bench::for_each_trial(file, experiment, [&](const amp::bench::Trial&) { ++trials; }, &complete);
    if (complete > size) std::abort();  // the resumed run would cut the file past its end
  });
  return 0;
}
