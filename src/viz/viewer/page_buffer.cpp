#include "page_buffer.hpp"

#include <bit>
#include <cstring>

namespace amp::viz::detail {

namespace {
static_assert(std::endian::native == std::endian::little, "the viewer's buffer is little-endian");

template <typename T>
std::size_t append_raw(std::string& bytes, std::span<const T> values) {
  static_assert(sizeof(T) == 4);
  const std::size_t offset = bytes.size();
  bytes.resize(offset + values.size_bytes());
  if (!values.empty()) std::memcpy(bytes.data() + offset, values.data(), values.size_bytes());
  return offset;
}
}  // namespace

std::size_t PageBuffer::append(std::span<const float> values) { return append_raw(bytes_, values); }
std::size_t PageBuffer::append(std::span<const std::uint32_t> values) { return append_raw(bytes_, values); }

std::string base64(std::string_view bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 3 <= bytes.size(); i += 3) {
    const std::uint32_t v = (std::uint32_t{static_cast<unsigned char>(bytes[i])} << 16) |
                            (std::uint32_t{static_cast<unsigned char>(bytes[i + 1])} << 8) |
                            std::uint32_t{static_cast<unsigned char>(bytes[i + 2])};
    for (int k = 3; k >= 0; --k) out.push_back(kAlphabet[(v >> (6 * k)) & 63U]);
  }
  const std::size_t rest = bytes.size() - i;
  if (rest > 0) {
    std::uint32_t v = std::uint32_t{static_cast<unsigned char>(bytes[i])} << 16;
    if (rest == 2) v |= std::uint32_t{static_cast<unsigned char>(bytes[i + 1])} << 8;
    out.push_back(kAlphabet[(v >> 18) & 63U]);
    out.push_back(kAlphabet[(v >> 12) & 63U]);
    out.push_back(rest == 2 ? kAlphabet[(v >> 6) & 63U] : '=');
    out.push_back('=');
  }
  return out;
}

}  // namespace amp::viz::detail
