// What `amp sins` and the bench methods static, random and sins take: `--param name=value` items
// (one per line here; the first byte picks the system, and whether an accepted set also runs, for at
// most 0.05 s in a 10 m arena, so that accepted extremes are driven too, not only checked), read by
// the study's settings reader (study::read_sins_params, as `amp sins` and Python read them) and by
// the navigation method.
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "amp/nav/navigator_catalog.hpp"
#include "amp/study/sins_study.hpp"
#include "amp/world/problem.hpp"
#include "cli_util.hpp"
#include "fuzz_input.hpp"
#include "support/source_tree.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const amp::world::Problem arena =
      amp::world::load_problem(std::filesystem::path(AMP_SOURCE_DIR) / "tests/fuzz/fixtures/sins-small-arena.yaml");
  if (size == 0) return 0;
  const char* systems[] = {"static", "random", "sins", "sins-plus"};
  std::vector<std::string> items;
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data) + 1, size - 1));
  for (std::string line; std::getline(lines, line);) items.push_back(line);
  amp::fuzz::expect_amp_errors_only([&] {
    amp::study::SinsSetup setup;
    amp::study::read_sins_params(amp::cli::parse_params(items), amp::nav::kClassicScale, setup);
  });
  amp::fuzz::expect_amp_errors_only([&] {
    const amp::core::ParamMap params = amp::cli::parse_params(items);
    amp::nav::execute_navigation(arena, systems[data[0] % 4], params, 1, (data[0] & 4) != 0 ? 0.05 : 0.0);
  });
  return 0;
}
