#include "collada_screen.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <vector>

namespace amp::world {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// One start tag as written: its name, the text of its attributes, and where its content begins.
struct StartTag {
  std::string_view name;
  std::string_view attributes;
  std::size_t content = 0;  // just past the '>'
  bool empty = false;       // <tag ... />
};

// The start tag at doc[pos] == '<', or nothing for an end tag, a comment, a declaration or a tag
// that never closes. A name ends at '<' too, so that a run of '<' costs linear time, not quadratic.
std::optional<StartTag> start_tag_at(std::string_view doc, std::size_t pos) {
  std::size_t i = pos + 1;
  if (i >= doc.size() || doc[i] == '/' || doc[i] == '!' || doc[i] == '?') return std::nullopt;
  while (i < doc.size() && !is_space(doc[i]) && doc[i] != '>' && doc[i] != '/' && doc[i] != '<') ++i;
  const std::size_t close = doc.find_first_of("<>", i);
  if (close == std::string_view::npos || doc[close] != '>') return std::nullopt;
  StartTag tag;
  tag.name = doc.substr(pos + 1, i - pos - 1);
  tag.empty = doc[close - 1] == '/';
  tag.attributes = doc.substr(i, close - i - (tag.empty ? 1 : 0));
  tag.content = close + 1;
  return tag;
}

// The value of attribute `key` as written (entities not decoded), or nothing.
std::optional<std::string_view> attribute(std::string_view attributes, std::string_view key) {
  std::size_t i = 0;
  while (true) {
    while (i < attributes.size() && is_space(attributes[i])) ++i;
    const std::size_t name_begin = i;
    while (i < attributes.size() && !is_space(attributes[i]) && attributes[i] != '=') ++i;
    const std::string_view name = attributes.substr(name_begin, i - name_begin);
    while (i < attributes.size() && is_space(attributes[i])) ++i;
    if (name.empty() || i >= attributes.size() || attributes[i] != '=') return std::nullopt;
    ++i;
    while (i < attributes.size() && is_space(attributes[i])) ++i;
    if (i >= attributes.size() || (attributes[i] != '"' && attributes[i] != '\'')) return std::nullopt;
    const std::size_t end = attributes.find(attributes[i], i + 1);
    if (end == std::string_view::npos) return std::nullopt;
    if (name == key) return attributes.substr(i + 1, end - i - 1);
    i = end + 1;
  }
}

// A plain decimal count of at most 12 digits (so that sums and products below cannot overflow),
// or nothing.
std::optional<unsigned long long> plain_count(std::string_view text) {
  if (text.empty() || text.size() > 12) return std::nullopt;
  unsigned long long v = 0;
  for (char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
    v = v * 10 + static_cast<unsigned long long>(c - '0');
  }
  return v;
}

// An optional count attribute: `fallback` when absent, nothing when written but not plain.
std::optional<unsigned long long> count_attribute(const StartTag& tag, std::string_view key,
                                                  unsigned long long fallback) {
  const std::optional<std::string_view> text = attribute(tag.attributes, key);
  return text ? plain_count(*text) : std::optional<unsigned long long>(fallback);
}

std::string quote(std::string_view text) {
  std::string q(1, '\'');
  q.append(text.substr(0, 32));
  q.push_back('\'');
  return q;
}

bool is_index_list(std::string_view name) { return name == "p" || name == "v" || name == "vcount" || name == "h"; }

bool is_data_array(std::string_view name) {
  constexpr std::array<std::string_view, 7> kArrays = {"float_array", "int_array",    "bool_array",  "Name_array",
                                                        "IDREF_array", "SIDREF_array", "token_array"};
  return std::find(kArrays.begin(), kArrays.end(), name) != kArrays.end();
}

// The <param> children of an accessor whose content starts at `from`: counted up to the first tag
// that is neither a param nor a comment, so that each '<' of the document is looked at once.
unsigned long long params_from(std::string_view doc, std::size_t from) {
  unsigned long long params = 0;
  for (std::size_t p = doc.find('<', from); p != std::string_view::npos; p = doc.find('<', p + 1)) {
    const std::string_view rest = doc.substr(p);
    if (rest.starts_with("<param") && rest.size() > 6 && (is_space(rest[6]) || rest[6] == '/' || rest[6] == '>')) {
      ++params;
    } else if (!rest.starts_with("</param") && !rest.starts_with("<!")) {
      break;
    }
  }
  return params;
}

struct Accessor {
  std::string_view source;
  unsigned long long count = 0, stride = 1, offset = 0, params = 0;
};

}  // namespace

std::string collada_refusal(std::string_view doc) {
  std::map<std::string_view, unsigned long long> array_size;  // id -> stored values (least, if repeated)
  std::vector<Accessor> accessors;
  for (std::size_t pos = doc.find('<'); pos != std::string_view::npos; pos = doc.find('<', pos + 1)) {
    const std::optional<StartTag> tag = start_tag_at(doc, pos);
    if (!tag) continue;
    if (is_index_list(tag->name) && !tag->empty) {
      const std::string_view body = doc.substr(tag->content, doc.find('<', tag->content) - tag->content);
      const auto bad = std::find_if(body.begin(), body.end(), [](char c) { return !is_space(c) && (c < '0' || c > '9'); });
      if (bad != body.end()) {
        return "a COLLADA index list holds " + quote(body.substr(static_cast<std::size_t>(bad - body.begin()), 16)) +
               ", not only indices";
      }
    } else if (is_data_array(tag->name)) {
      const std::optional<std::string_view> id = attribute(tag->attributes, "id");
      const std::optional<unsigned long long> count = count_attribute(*tag, "count", 0);
      if (!count) return "the count of COLLADA <" + std::string(tag->name) + "> is not a plain number";
      if (id) {
        const auto [it, inserted] = array_size.emplace(*id, *count);
        if (!inserted) it->second = std::min(it->second, *count);
      }
    } else if (tag->name == "accessor") {
      Accessor a;
      const std::optional<std::string_view> source = attribute(tag->attributes, "source");
      const auto count = count_attribute(*tag, "count", 0), stride = count_attribute(*tag, "stride", 1),
                 offset = count_attribute(*tag, "offset", 0);
      if (!source || !count || !stride || !offset) {
        return "a COLLADA <accessor> lacks a plain source, count, stride or offset";
      }
      a.source = *source, a.count = *count, a.stride = *stride, a.offset = *offset;
      if (!tag->empty) a.params = params_from(doc, tag->content);
      accessors.push_back(a);
    }
  }
  for (const Accessor& a : accessors) {
    if (a.count == 0) continue;  // reads nothing
    if (a.source.empty() || a.source.front() != '#' || !array_size.contains(a.source.substr(1))) {
      return "a COLLADA <accessor> source " + quote(a.source) + " names no data array in the file";
    }
    const unsigned long long stored = array_size.at(a.source.substr(1));
    if (a.params > a.stride) {
      return "a COLLADA <accessor> has " + std::to_string(a.params) + " params in a stride of " + std::to_string(a.stride);
    }
    if (a.offset + a.count * a.stride > stored) {
      return "a COLLADA <accessor> of " + std::to_string(a.count) + " x " + std::to_string(a.stride) + " from offset " +
             std::to_string(a.offset) + " reads past " + quote(a.source) + " of " + std::to_string(stored) + " values";
    }
  }
  return {};
}

}  // namespace amp::world
