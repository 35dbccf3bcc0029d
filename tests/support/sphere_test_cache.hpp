#pragma once
// The sphere cache that tests of the sphere model share when they are not testing generation or the
// cache itself: one folder in the build tree, so that the Panda's cover is generated once per build
// instead of once per test process (each regenerated it in 12-55 s under the sanitizers). Entries are
// keyed by the generator's version and the meshes (src/world/arm/sphere_cache.cpp), and
// PandaSpheres.SameInputSameSpheres compares a fresh generation with what this folder holds, so an
// entry left by an older generator cannot pass unnoticed. Writes are a rename into place, so tests
// running in parallel may fill it at once.
#include <filesystem>
#include "support/source_tree.hpp"

namespace amp::test {

inline std::filesystem::path shared_sphere_cache() { return std::filesystem::path(AMP_BINARY_DIR) / "test-sphere-cache"; }

}  // namespace amp::test
