// PNG map images through libpng, converted to grey values the way ROS map_server's image loader
// (SDL_image) sees them, so that a PNG map gives the grid map_server publishes.
#include <png.h>

#include <csetjmp>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include "amp/core/error.hpp"
#include "amp/world/map_server_loader.hpp"

namespace amp::world {

namespace {

// The same sanity limit as the PGM reader's: a corrupt header cannot request gigabytes.
constexpr png_uint_32 kMaxSide = 1u << 20;
constexpr unsigned long long kMaxPixels = 1ULL << 28;

struct Source {
  const unsigned char* data = nullptr;
  std::size_t size = 0, pos = 0;
  char error[200] = {};  // libpng's message, copied before it unwinds to setjmp
};

void on_error(png_structp png, png_const_charp message) {
  auto* src = static_cast<Source*>(png_get_error_ptr(png));
  std::strncpy(src->error, message, sizeof(src->error) - 1);
  png_longjmp(png, 1);
}
void on_warning(png_structp, png_const_charp) {}  // e.g. a bad CRC in an ancillary chunk: not fatal

void read_bytes(png_structp png, png_bytep out, png_size_t n) {
  auto* src = static_cast<Source*>(png_get_io_ptr(png));
  if (src->size - src->pos < n) png_error(png, "truncated PNG: the data ends early");
  std::memcpy(out, src->data + src->pos, n);
  src->pos += n;
}

// The decoded image, 8 bits per channel, rows top first. Plain memory (malloc) on purpose: libpng
// reports errors by longjmp, which must not skip a C++ destructor.
struct Decoded {
  png_uint_32 width = 0, height = 0;
  int channels = 0;  // 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA
  std::size_t rowbytes = 0;
  unsigned char* pixels = nullptr;
  png_bytep* rows = nullptr;
};

// Decodes with map_server's transforms: 16-bit samples keep their high byte (png_set_strip_16, as
// SDL_image does); palettes become RGB and grey below 8 bits is scaled to 0..255 (SDL would hand
// map_server palette indices and unscaled 1-, 2- and 4-bit values); a tRNS colour becomes alpha.
// Returns false with src.error set on any fault. No C++ object lives across the setjmp.
bool decode(Source& src, Decoded& out) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &src, on_error, on_warning);
  if (png == nullptr) {
    std::strcpy(src.error, "cannot start the PNG decoder");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, info != nullptr ? &info : nullptr, nullptr);
    return false;
  }
  png_set_read_fn(png, &src, read_bytes);
  png_set_user_limits(png, kMaxSide, kMaxSide);
  png_read_info(png, info);
  out.width = png_get_image_width(png, info);
  out.height = png_get_image_height(png, info);
  if (static_cast<unsigned long long>(out.width) * out.height > kMaxPixels) {
    png_error(png, "PNG size is empty or too large");
  }
  const int color = png_get_color_type(png, info);
  if (color == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (color == PNG_COLOR_TYPE_GRAY && png_get_bit_depth(png, info) < 8) png_set_expand_gray_1_2_4_to_8(png);
  if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
  png_set_strip_16(png);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  out.channels = png_get_channels(png, info);
  out.rowbytes = png_get_rowbytes(png, info);
  if (out.channels < 1 || out.channels > 4 || out.rowbytes != out.width * static_cast<std::size_t>(out.channels)) {
    png_error(png, "unsupported PNG layout");
  }
  out.pixels = static_cast<unsigned char*>(std::malloc(out.rowbytes * out.height));
  out.rows = static_cast<png_bytep*>(std::malloc(sizeof(png_bytep) * out.height));
  if (out.pixels == nullptr || out.rows == nullptr) png_error(png, "PNG too large for memory");
  for (png_uint_32 r = 0; r < out.height; ++r) out.rows[r] = out.pixels + r * out.rowbytes;
  png_read_image(png, out.rows);
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

}  // namespace

bool is_png(const std::string& head) {
  return head.size() >= 8 && png_sig_cmp(reinterpret_cast<png_const_bytep>(head.data()), 0, 8) == 0;
}

PgmImage read_png(const std::filesystem::path& file, MapMode mode) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw FileError(file.string() + ": cannot open image file");
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw FileError(file.string() + ": cannot read image file");
  if (!is_png(data)) throw FileError(file.string() + ": not a PNG image (no PNG signature)");
  Source src;
  src.data = reinterpret_cast<const unsigned char*>(data.data());
  src.size = data.size();
  Decoded d;
  const bool ok = decode(src, d);
  const auto release = [&d] {
    std::free(d.rows);
    std::free(d.pixels);
  };
  if (!ok) {
    release();
    std::string what = src.error;
    if (what.empty()) what = "unreadable PNG";
    if (what.find("PNG") == std::string::npos) what = "PNG: " + what;
    throw FileError(file.string() + ": " + what);
  }
  // map_server averages the colour channels into one grey value. SDL_image hands it grey + alpha as
  // RGBA; in trinary mode the alpha is averaged in with the colours ("to preserve existing
  // behavior"), in the other modes it is left out and a fully transparent pixel is unknown. The sum
  // is kept whole over a maxval of 255 x the channels averaged, so the average stays exact.
  const bool alpha = d.channels == 2 || d.channels == 4;
  constexpr int colours = 3;  // grey counts as R = G = B
  const int averaged = alpha && mode == MapMode::kTrinary ? colours + 1 : colours;
  PgmImage img;
  img.width = static_cast<int>(d.width);
  img.height = static_cast<int>(d.height);
  img.maxval = 255 * averaged;
  img.pixels.resize(static_cast<std::size_t>(img.width) * img.height);
  if (alpha && mode != MapMode::kTrinary) img.transparent.assign(img.pixels.size(), 0);
  for (png_uint_32 r = 0; r < d.height; ++r) {
    const unsigned char* p = d.rows[r];
    for (png_uint_32 c = 0; c < d.width; ++c, p += d.channels) {
      const int sum = d.channels <= 2 ? 3 * p[0] : p[0] + p[1] + p[2];
      const int a = alpha ? p[d.channels - 1] : 255;
      const std::size_t i = static_cast<std::size_t>(r) * d.width + c;
      img.pixels[i] = static_cast<std::uint16_t>(averaged > colours ? sum + a : sum);
      if (!img.transparent.empty()) img.transparent[i] = a == 0 ? 1 : 0;
    }
  }
  release();
  return img;
}

PgmImage read_map_image(const std::filesystem::path& file, MapMode mode) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw FileError(file.string() + ": cannot open image file");
  std::string head(8, '\0');
  in.read(head.data(), 8);
  head.resize(static_cast<std::size_t>(in.gcount()));
  return is_png(head) ? read_png(file, mode) : read_pgm(file);
}

}  // namespace amp::world
