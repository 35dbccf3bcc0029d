#include "amp/core/number_text.hpp"

#include <charconv>
#include <system_error>

namespace amp::core {

std::string number_text(double v) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : std::to_string(v);
}

}  // namespace amp::core
