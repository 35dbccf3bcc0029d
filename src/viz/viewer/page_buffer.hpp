#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace amp::viz::detail {

// The viewer page's one binary buffer: float32 and uint32 arrays appended one after another, each
// at a byte offset the page's JSON names. Every element is 4 bytes, so each array starts aligned
// for the browser's typed-array views. Little-endian, as every WebGL platform is.
class PageBuffer {
 public:
  // The byte offset the array starts at.
  std::size_t append(std::span<const float> values);
  std::size_t append(std::span<const std::uint32_t> values);
  std::size_t size() const { return bytes_.size(); }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

// RFC 4648 base64 with padding: how the buffer travels inside the HTML text.
std::string base64(std::string_view bytes);

}  // namespace amp::viz::detail
