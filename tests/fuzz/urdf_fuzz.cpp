// URDF robots through urdfdom (world::parse_urdf): links, joints, limits, mimic and every
// `<collision>` geometry. Meshes resolve against a folder of this process holding only two tiny
// bundled meshes (box.obj, tetra.stl), so that a mesh found, scaled and shared is read too while no
// other file is: any other mesh is missing, which must be a FileError.
#include <filesystem>
#include <string>

#include "amp/world/arm_model.hpp"
#include "fuzz_input.hpp"
#include "support/source_tree.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path& mesh_dir() {
  static const fs::path dir = [] {
    const fs::path d = amp::fuzz::workdir() / "urdf-meshes";
    fs::create_directory(d);
    const fs::path meshes = fs::path(AMP_SOURCE_DIR) / "tests" / "data" / "meshes";
    for (const char* name : {"box.obj", "tetra.stl"}) fs::create_symlink(meshes / name, d / name);
    return d;
  }();
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string xml(reinterpret_cast<const char*>(data), size);
  amp::fuzz::expect_amp_errors_only([&] { amp::world::parse_urdf(xml, "input.urdf", mesh_dir()); });
  return 0;
}
