#include "amp/bench/shard.hpp"

#include <charconv>

#include "amp/core/error.hpp"

namespace amp::bench {

Shard parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  Shard s;
  auto parse = [&](std::string_view part, std::size_t& out) {
    const auto r = std::from_chars(part.data(), part.data() + part.size(), out);
    return r.ec == std::errc() && r.ptr == part.data() + part.size() && !part.empty();
  };
  const std::string_view t(text);
  if (slash == std::string::npos || !parse(t.substr(0, slash), s.index) || !parse(t.substr(slash + 1), s.count)) {
    throw ParameterError("--shard: expected i/N with integers, e.g. 0/4, got '" + text + "'");
  }
  if (s.count == 0 || s.index >= s.count) {
    throw ParameterError("--shard: need 0 <= i < N, got '" + text + "'");
  }
  return s;
}

}  // namespace amp::bench
