#include "collada_index_lists.hpp"

#include <array>

namespace amp::world {

std::string_view bad_collada_index_list(std::string_view doc) {
  constexpr std::array<std::string_view, 4> kTags = {"<p", "<v", "<vcount", "<h"};
  const auto index_char = [](char c) { return (c >= '0' && c <= '9') || c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  for (std::size_t pos = doc.find('<'); pos != std::string_view::npos; pos = doc.find('<', pos + 1)) {
    for (std::string_view tag : kTags) {
      if (doc.compare(pos, tag.size(), tag) != 0) continue;
      const std::size_t after = pos + tag.size();
      // The tag name must end there (<p> or <p attr=...>, not <param>); self-closing lists are empty.
      if (after >= doc.size() || (doc[after] != '>' && doc[after] != ' ')) continue;
      const std::size_t open_end = doc.find('>', after);
      if (open_end == std::string_view::npos || doc[open_end - 1] == '/') break;
      const std::size_t close = doc.find('<', open_end + 1);
      const std::string_view body = doc.substr(open_end + 1, close == std::string_view::npos ? close : close - open_end - 1);
      for (std::size_t i = 0; i < body.size(); ++i) {
        if (!index_char(body[i])) return body.substr(i, 16);
      }
      break;
    }
  }
  return {};
}

}  // namespace amp::world
