// Our own PGM reader (Netpbm P2 / P5), so map loading needs no image library.
#include <cctype>
#include <fstream>
#include <iterator>
#include <string>

#include "amp/core/error.hpp"
#include "amp/world/map_server_loader.hpp"

namespace amp::world {

namespace {

constexpr int kMaxMaxval = 65535;
// A sanity limit on the image size so that a corrupt header cannot request gigabytes.
constexpr long long kMaxPixels = 1LL << 28;

class PgmParser {
 public:
  PgmParser(std::string data, std::filesystem::path file) : data_(std::move(data)), file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& what) const { throw FileError(file_.string() + ": " + what); }

  // Skips whitespace and '#' comments (allowed anywhere in the header).
  void skip_space() {
    while (pos_ < data_.size()) {
      const char c = data_[pos_];
      if (c == '#') {
        while (pos_ < data_.size() && data_[pos_] != '\n' && data_[pos_] != '\r') ++pos_;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        ++pos_;
      } else {
        break;
      }
    }
  }

  // A decimal integer token; `what` names the field for the error.
  long long integer(const char* what) {
    skip_space();
    if (pos_ >= data_.size()) fail(std::string("truncated PGM: missing ") + what);
    if (!std::isdigit(static_cast<unsigned char>(data_[pos_]))) {
      fail(std::string("PGM ") + what + ": expected a non-negative integer, got '" + token_at(pos_) + "'");
    }
    long long v = 0;
    while (pos_ < data_.size() && std::isdigit(static_cast<unsigned char>(data_[pos_]))) {
      v = v * 10 + (data_[pos_] - '0');
      if (v > (1LL << 40)) fail(std::string("PGM ") + what + ": number too large");
      ++pos_;
    }
    return v;
  }

  // Raw: amp::Error escapes what is not printable UTF-8 (a PNG's signature shows as \x89PNG).
  std::string token_at(std::size_t p) const {
    std::size_t e = p;
    while (e < data_.size() && e - p < 16 && !std::isspace(static_cast<unsigned char>(data_[e]))) ++e;
    return data_.substr(p, e - p);
  }

  PgmImage parse() {
    if (data_.size() < 2 || data_[0] != 'P' || (data_[1] != '2' && data_[1] != '5')) {
      fail("unsupported image format '" + token_at(0) + "' (expected PGM, magic P2 or P5)");
    }
    const bool binary = data_[1] == '5';
    pos_ = 2;
    PgmImage img;
    const long long w = integer("width");
    const long long h = integer("height");
    const long long maxval = integer("maxval");
    if (w < 1 || h < 1 || w > kMaxPixels || h > kMaxPixels || w * h > kMaxPixels) {  // each first: no overflow
      fail("PGM size " + std::to_string(w) + "x" + std::to_string(h) + " is empty or too large");
    }
    if (maxval < 1 || maxval > kMaxMaxval) fail("PGM maxval must be in 1..65535, got " + std::to_string(maxval));
    img.width = static_cast<int>(w);
    img.height = static_cast<int>(h);
    img.maxval = static_cast<int>(maxval);
    const std::size_t n = static_cast<std::size_t>(w * h);
    if (binary) {
      read_binary(img, n);
    } else {
      read_ascii(img, n);
    }
    return img;
  }

 private:
  void read_binary(PgmImage& img, std::size_t n) {
    // Exactly one whitespace character separates maxval from the raster.
    if (pos_ >= data_.size() || !std::isspace(static_cast<unsigned char>(data_[pos_]))) {
      fail("truncated PGM: no raster after the header");
    }
    ++pos_;
    const std::size_t bytes_per_sample = img.maxval > 255 ? 2 : 1;
    const std::size_t expected = n * bytes_per_sample;
    const std::size_t have = data_.size() - pos_;
    if (have != expected) {
      fail("PGM raster has " + std::to_string(have) + " bytes but the header's " + std::to_string(img.width) + "x" +
           std::to_string(img.height) + " needs " + std::to_string(expected) + (have < expected ? " (truncated)" : ""));
    }
    img.pixels.resize(n);  // only now: a short file claiming a huge size must not allocate it
    const auto* p = reinterpret_cast<const unsigned char*>(data_.data() + pos_);
    for (std::size_t i = 0; i < n; ++i) {
      // 16-bit samples are big-endian (Netpbm).
      const unsigned v = bytes_per_sample == 2 ? (unsigned{p[2 * i]} << 8) | p[2 * i + 1] : unsigned{p[i]};
      check_sample(v, img.maxval, i, img.width);
      img.pixels[i] = static_cast<std::uint16_t>(v);
    }
  }

  void read_ascii(PgmImage& img, std::size_t n) {
    // Each sample takes a digit and a separator: a file too short for the header's size fails
    // before the raster is allocated (a 1-kB file claiming 10^8 pixels would otherwise take seconds).
    const std::size_t room = (data_.size() - pos_ + 1) / 2;
    if (room < n) {
      fail("truncated PGM: the header's " + std::to_string(img.width) + "x" + std::to_string(img.height) + " needs " +
           std::to_string(n) + " samples, the file has room for at most " + std::to_string(room));
    }
    img.pixels.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      skip_space();
      if (pos_ >= data_.size()) {
        fail("truncated PGM: " + std::to_string(i) + " samples but the header's " + std::to_string(img.width) + "x" +
             std::to_string(img.height) + " needs " + std::to_string(n));
      }
      const long long v = integer("sample");
      check_sample(v, img.maxval, i, img.width);
      img.pixels[i] = static_cast<std::uint16_t>(v);
    }
    skip_space();
    if (pos_ < data_.size()) {
      fail("PGM has more samples than the header's " + std::to_string(img.width) + "x" + std::to_string(img.height) +
           " (extra '" + token_at(pos_) + "')");
    }
  }

  void check_sample(long long v, int maxval, std::size_t i, int width) const {
    if (v > maxval) {
      fail("PGM sample " + std::to_string(v) + " at column " + std::to_string(i % width) + ", row " +
           std::to_string(i / width) + " exceeds maxval " + std::to_string(maxval));
    }
  }

  std::string data_;
  std::filesystem::path file_;
  std::size_t pos_ = 0;
};

}  // namespace

PgmImage read_pgm(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw FileError(file.string() + ": cannot open image file");
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw FileError(file.string() + ": cannot read image file");
  return PgmParser(std::move(data), file).parse();
}

}  // namespace amp::world
