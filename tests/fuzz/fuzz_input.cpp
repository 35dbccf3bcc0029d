#include "fuzz_input.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <system_error>
#include <unistd.h>
#include "support/source_tree.hpp"

namespace amp::fuzz {
namespace {

namespace fs = std::filesystem;

// Links every bundled file the fuzzed formats refer to by a relative path.
void link_fixtures(const fs::path& dir) {
  const fs::path src = AMP_SOURCE_DIR;
  for (const char* sub : {"maps", "ompl", "puzzle"}) fs::create_directory_symlink(src / "problems" / sub, dir / sub);
  fs::create_directory_symlink(src / "tests" / "data" / "meshes", dir / "meshes");
  // Problem files at the top (for experiment files) and the .cfg meshes beside the input.
  for (const fs::directory_entry& e : fs::directory_iterator(src / "problems")) {
    if (e.path().extension() == ".yaml") fs::create_symlink(e.path(), dir / e.path().filename());
  }
  for (const fs::directory_entry& e : fs::directory_iterator(src / "problems" / "ompl")) {
    const fs::path ext = e.path().extension();
    if (ext == ".obj" || ext == ".dae" || ext == ".stl") fs::create_symlink(e.path(), dir / e.path().filename());
  }
}

class Workdir {
 public:
  Workdir() {
    std::string pattern = (fs::temp_directory_path() / "amp-fuzz-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) {
      std::perror("amp fuzz: mkdtemp");
      std::abort();
    }
    path_ = pattern;
    link_fixtures(path_);
  }
  ~Workdir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

}  // namespace

const fs::path& workdir() {
  static const Workdir dir;  // libFuzzer's entry point has no context to keep it in
  return dir.path();
}

fs::path write_input(const std::uint8_t* data, std::size_t size, const std::string& name) {
  const fs::path file = workdir() / name;
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out) std::abort();
  return file;
}

void check_one_line(const char* message) {
  const auto fail = [message](const char* what) {
    std::fprintf(stderr, "amp fuzz: error message %s: %s\n", what, message);
    std::abort();
  };
  for (const auto* c = reinterpret_cast<const unsigned char*>(message); *c != 0; ++c) {
    if (*c < 0x20 || *c == 0x7f) fail("holds a control byte");
    if (*c < 0x80) continue;
    // A multi-byte UTF-8 sequence: a lead byte and its continuation bytes, else raw input bytes.
    const int extra = (*c & 0xe0) == 0xc0 ? 1 : (*c & 0xf0) == 0xe0 ? 2 : (*c & 0xf8) == 0xf0 ? 3 : -1;
    if (extra < 0) fail("holds a byte that is not UTF-8");
    for (int k = 0; k < extra; ++k) {
      if ((*++c & 0xc0) != 0x80) fail("holds a byte that is not UTF-8");
    }
  }
}

}  // namespace amp::fuzz
