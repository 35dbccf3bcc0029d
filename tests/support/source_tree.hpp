#pragma once
// Where the source and build trees are, for tests, benchmarks and fuzz targets. The paths live in one
// generated source (CMakeLists.txt, amp_source_tree), not in a definition on every compile line, so
// that every other object file is the same in every clone and the compiler cache that clones share
// hits (docs/build.md). Both macros are C strings: `fs::path(AMP_SOURCE_DIR) / "problems"`.
namespace amp::test_paths {
const char* source_dir();
const char* binary_dir();
}  // namespace amp::test_paths

#define AMP_SOURCE_DIR (::amp::test_paths::source_dir())
#define AMP_BINARY_DIR (::amp::test_paths::binary_dir())
