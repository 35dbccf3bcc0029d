// Generated sphere sets kept on disk, keyed by what they are computed from (the options and every
// link's solids, byte for byte), so that a robot is covered once per user rather than once per run.
// An entry is text:
//   amp-sphere-cover 1 <key: 16 hex> <piece_size> <max_per_link> <bulge>
//   sphere <link name> <x> <y> <z> <r>                                  (one per sphere)
//   link <link name> <spheres> <excess_bound> <sphere_volume> <box_volume> <inflation>  (one per link)
//   end
// A reader trusts nothing in it: any entry that is not exactly this is regenerated.
#include <unistd.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <string_view>
#include <system_error>
#include <thread>
#include <vector>

#include "amp/world/arm_spheres.hpp"

namespace amp::world {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kMagic = "amp-sphere-cover";
constexpr std::string_view kFormatVersion = "1";
// Part of the key: raise it when the generator changes, so that older entries are not read back.
constexpr std::uint32_t kGeneratorVersion = 6;  // 6: a piece budget per link (sphere_pieces.hpp)

// 64-bit FNV-1a (Fowler, Noll, Vo): fast, and ample for telling robots apart (not an adversary).
class Fnv1a {
 public:
  void bytes(const void* data, std::size_t n) {
    constexpr std::uint64_t kPrime = 1099511628211ull;
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) hash_ = (hash_ ^ p[i]) * kPrime;
  }
  template <class T>
  void value(const T& v) {
    bytes(&v, sizeof v);
  }
  void text(const std::string& s) {
    value(s.size());
    bytes(s.data(), s.size());
  }
  std::uint64_t digest() const { return hash_; }

 private:
  std::uint64_t hash_ = 14695981039346656037ull;
};

void hash_solid(const Solid& s, Fnv1a& h) {
  h.value(static_cast<int>(s.kind));
  h.bytes(s.pose.matrix().data(), 16 * sizeof(double));
  h.bytes(s.size.data(), 3 * sizeof(double));
  h.value(s.radius);
  h.value(s.length);
  if (s.kind != Solid::Kind::kMesh || !s.mesh) return;
  h.value(s.mesh->vertices.size());
  for (const Eigen::Vector3d& v : s.mesh->vertices) h.bytes(v.data(), 3 * sizeof(double));
  h.value(s.mesh->triangles.size());
  for (const Eigen::Vector3i& t : s.mesh->triangles) h.bytes(t.data(), 3 * sizeof(int));
}

std::uint64_t cache_key(const ArmModel& model, const SphereCoverOptions& o) {
  Fnv1a h;
  h.value(kGeneratorVersion);
  h.value(o.piece_size);
  h.value(o.max_per_link);
  h.value(o.bulge);
  h.value(model.links().size());
  for (const ArmLink& l : model.links()) {
    h.text(l.name);
    h.value(l.collision.size());
    for (const Solid& s : l.collision) hash_solid(s, h);
  }
  return h.digest();
}

std::string hex(std::uint64_t key) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(key));
  return buf;
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// ---- Reading: fields separated by single spaces, lines by '\n', nothing else tolerated. ----

std::vector<std::string_view> split(std::string_view s, char sep) {
  std::vector<std::string_view> out;
  for (std::size_t start = 0;;) {
    const std::size_t end = s.find(sep, start);
    out.push_back(s.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) return out;
    start = end + 1;
  }
}

bool finite_number(std::string_view t, double& out) {
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), out);
  return ec == std::errc() && end == t.data() + t.size() && std::isfinite(out);
}

bool nonnegative(std::string_view t, double& out) { return finite_number(t, out) && out >= 0.0; }

// Canonical decimal only ("7", not "+7" or "07").
bool canonical_int(std::string_view t, int& out) {
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), out);
  return ec == std::errc() && end == t.data() + t.size() && std::to_string(out) == t;
}

bool header(std::string_view line, std::uint64_t& key, SphereCoverOptions& o) {
  const auto f = split(line, ' ');
  if (f.size() != 6 || f[0] != kMagic || f[1] != kFormatVersion || f[2].size() != 16) return false;
  const auto [end, ec] = std::from_chars(f[2].data(), f[2].data() + f[2].size(), key, 16);
  if (ec != std::errc() || end != f[2].data() + f[2].size() || hex(key) != f[2]) return false;
  return finite_number(f[3], o.piece_size) && o.piece_size > 0.0 && canonical_int(f[4], o.max_per_link) && o.max_per_link >= 1 &&
         finite_number(f[5], o.bulge) && o.bulge >= 0.0;
}

// A link named in the entry: one of the model's, with collision geometry.
int solid_link(std::string_view name, const ArmModel& model) {
  const int l = model.link_index(std::string(name));
  return l >= 0 && !model.link(l).collision.empty() ? l : -1;
}

bool sphere_line(const std::vector<std::string_view>& f, const ArmModel& model, LinkSphere& s) {
  if (f.size() != 6 || f[0] != "sphere") return false;
  s.link = solid_link(f[1], model);
  return s.link >= 0 && finite_number(f[2], s.center.x()) && finite_number(f[3], s.center.y()) && finite_number(f[4], s.center.z()) &&
         finite_number(f[5], s.radius) && s.radius > 0.0;
}

bool link_line(const std::vector<std::string_view>& f, const ArmModel& model, LinkCoverReport& r) {
  if (f.size() != 7 || f[0] != "link") return false;
  r.link = solid_link(f[1], model);
  return r.link >= 0 && canonical_int(f[2], r.spheres) && r.spheres >= 1 && nonnegative(f[3], r.excess_bound) &&
         nonnegative(f[4], r.sphere_volume) && nonnegative(f[5], r.box_volume) && nonnegative(f[6], r.inflation);
}

// The reports must be exactly one per link with solids, in model order, each counting its spheres;
// the spheres grouped by link in model order.
bool consistent(const SphereCover& c, const ArmModel& model) {
  std::vector<int> count(model.links().size(), 0);
  for (std::size_t i = 0; i < c.spheres.size(); ++i) {
    if (i > 0 && c.spheres[i].link < c.spheres[i - 1].link) return false;
    ++count[static_cast<std::size_t>(c.spheres[i].link)];
  }
  std::size_t next = 0;
  for (int l = 0; l < static_cast<int>(model.links().size()); ++l) {
    if (model.link(l).collision.empty()) continue;
    if (next == c.links.size() || c.links[next].link != l || c.links[next].spheres != count[static_cast<std::size_t>(l)]) return false;
    ++next;
  }
  return next == c.links.size();
}

// The entry's cover and options, or false; the key is checked against the model and those options.
bool parse_entry(std::string_view text, const ArmModel& model, SphereCover& cover) {
  std::vector<std::string_view> lines = split(text, '\n');
  if (lines.size() < 3 || !lines.back().empty()) return false;  // the last line ends with '\n' too
  lines.pop_back();
  std::uint64_t key = 0;
  SphereCover c;
  if (!header(lines.front(), key, c.options) || lines.back() != "end") return false;
  std::size_t i = 1;
  for (; i + 1 < lines.size() && lines[i].starts_with("sphere "); ++i) {
    if (!sphere_line(split(lines[i], ' '), model, c.spheres.emplace_back())) return false;
  }
  for (; i + 1 < lines.size(); ++i) {
    if (!link_line(split(lines[i], ' '), model, c.links.emplace_back())) return false;
  }
  if (!consistent(c, model) || key != cache_key(model, c.options)) return false;
  cover = std::move(c);
  return true;
}

// Link names are fields: a name with a space or a line break cannot be written.
bool writable(const ArmModel& model) {
  for (const ArmLink& l : model.links()) {
    if (l.name.empty() || l.name.find_first_of(" \n") != std::string::npos) return false;
  }
  return true;
}

bool read_entry(const fs::path& file, const ArmModel& model, const SphereCoverOptions& options, SphereCover& out) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return false;
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  SphereCover cover;
  if (!parse_entry(text, model, cover)) return false;
  const SphereCoverOptions& stored = cover.options;
  if (stored.piece_size != options.piece_size || stored.max_per_link != options.max_per_link ||
      stored.bulge != options.bulge) {
    return false;
  }
  out = std::move(cover);
  return true;
}

// Through a temporary file renamed into place, so that a reader never sees half an entry; failures
// are ignored (the cover was computed, only not kept).
void write_entry(const fs::path& dir, const fs::path& file, const std::string& text) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  const fs::path tmp = file.string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                       std::to_string(std::hash<std::thread::id>{}(std::this_thread::get_id()));
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out || !(out << text) || !out.flush()) {
      out.close();
      fs::remove(tmp, ec);
      return;
    }
  }
  fs::rename(tmp, file, ec);
  if (ec) fs::remove(tmp, ec);
}

}  // namespace

std::filesystem::path default_sphere_cache_dir() {
  const auto set = [](const char* name) -> const char* {
    const char* v = std::getenv(name);
    return v != nullptr && *v != '\0' ? v : nullptr;
  };
  if (const char* d = set("AMP_CACHE_DIR")) return fs::path(d);
  if (const char* d = set("XDG_CACHE_HOME")) return fs::path(d) / "amp";
  if (const char* d = set("HOME")) return fs::path(d) / ".cache" / "amp";
  return {};
}

std::string format_sphere_cache(const SphereCover& cover, const ArmModel& model) {
  const SphereCoverOptions& o = cover.options;
  std::string out = std::string(kMagic) + " " + std::string(kFormatVersion) + " " + hex(cache_key(model, o)) + " " + num(o.piece_size) +
                    " " + std::to_string(o.max_per_link) + " " + num(o.bulge) + "\n";
  for (const LinkSphere& s : cover.spheres) {
    out += "sphere " + model.link(s.link).name + " " + num(s.center.x()) + " " + num(s.center.y()) + " " + num(s.center.z()) + " " +
           num(s.radius) + "\n";
  }
  for (const LinkCoverReport& r : cover.links) {
    out += "link " + model.link(r.link).name + " " + std::to_string(r.spheres) + " " + num(r.excess_bound) + " " + num(r.sphere_volume) +
           " " + num(r.box_volume) + " " + num(r.inflation) + "\n";
  }
  return out + "end\n";
}

bool parse_sphere_cache(const std::string& text, const ArmModel& model, SphereCover& out) { return parse_entry(text, model, out); }

SphereCover cached_cover_with_spheres(const ArmModel& model, const std::filesystem::path& cache_dir, const SphereCoverOptions& options) {
  if (cache_dir.empty() || !writable(model)) return cover_with_spheres(model, options);
  const fs::path file = cache_dir / ("spheres-" + hex(cache_key(model, options)) + ".txt");
  SphereCover cover;
  if (read_entry(file, model, options, cover)) return cover;
  cover = cover_with_spheres(model, options);
  write_entry(cache_dir, file, format_sphere_cache(cover, model));
  return cover;
}

}  // namespace amp::world
