// `.path` files (text and YAML) as `amp render` and the oracle read them, in the spaces the bundled
// problems use: the first byte picks one.
#include "amp/core/joint_space.hpp"
#include "amp/core/path_file.hpp"
#include "amp/core/se3_space.hpp"
#include "fuzz_input.hpp"

namespace {

const amp::core::Space& space(std::uint8_t pick) {
  using namespace amp::core;
  static const JointSpace se2 = make_se2_space(-10, -10, 10, 10, 1.0);
  static const JointSpace rn = make_rn_space({0, 0, 0}, {1, 2, 3});
  static const Se3Space se3(Eigen::Vector3d(-5, -5, -5), Eigen::Vector3d(5, 5, 5), 1.0);
  switch (pick % 3) {
    case 0: return se2;
    case 1: return rn;
    default: return se3;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const auto file = amp::fuzz::write_input(data + 1, size - 1, "input.path");
  amp::fuzz::expect_amp_errors_only([&] { amp::core::read_path_file(file, space(data[0])); });
  return 0;
}
