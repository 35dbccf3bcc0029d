// Sphere cache entries (world::parse_sphere_cache) for the two-link test arm (tests/data/arm/two_link:
// box, cylinder and sphere links, no meshes). The parser must refuse, not throw or crash, on any
// text; an entry it accepts must be a cover of the arm's links with solids, and must come back
// unchanged through format_sphere_cache (%.17g round-trips every double).
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "amp/world/arm_model.hpp"
#include "amp/world/arm_spheres.hpp"
#include "fuzz_input.hpp"
#include "support/source_tree.hpp"

namespace {

const amp::world::ArmModel& model() {
  static const amp::world::ArmModel m =
      amp::world::load_urdf(std::filesystem::path(AMP_SOURCE_DIR) / "tests" / "data" / "arm" / "two_link" / "two_link.urdf");
  return m;
}

bool same(const amp::world::SphereCover& a, const amp::world::SphereCover& b) {
  if (a.spheres.size() != b.spheres.size() || a.links.size() != b.links.size()) return false;
  for (std::size_t i = 0; i < a.spheres.size(); ++i) {
    const auto& x = a.spheres[i];
    const auto& y = b.spheres[i];
    if (x.link != y.link || x.center != y.center || x.radius != y.radius) return false;
  }
  for (std::size_t i = 0; i < a.links.size(); ++i) {
    const auto& x = a.links[i];
    const auto& y = b.links[i];
    if (x.link != y.link || x.spheres != y.spheres || x.excess_bound != y.excess_bound || x.sphere_volume != y.sphere_volume ||
        x.box_volume != y.box_volume || x.inflation != y.inflation) {
      return false;
    }
  }
  return a.options.piece_size == b.options.piece_size && a.options.max_per_link == b.options.max_per_link &&
         a.options.bulge == b.options.bulge;
}

// What an accepted entry promises its users (the sphere checker indexes links with it).
bool well_formed(const amp::world::SphereCover& c) {
  const int links = static_cast<int>(model().links().size());
  for (const auto& s : c.spheres) {
    if (s.link < 0 || s.link >= links || model().link(s.link).collision.empty()) return false;
    if (!s.center.allFinite() || !std::isfinite(s.radius) || !(s.radius > 0.0)) return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  amp::world::SphereCover cover;
  cover.options.max_per_link = -7;  // a marker: a refused input must leave `cover` untouched
  if (!amp::world::parse_sphere_cache(text, model(), cover)) {
    if (cover.options.max_per_link != -7 || !cover.spheres.empty() || !cover.links.empty()) std::abort();
    return 0;
  }
  if (!well_formed(cover)) std::abort();
  amp::world::SphereCover again;
  if (!amp::world::parse_sphere_cache(amp::world::format_sphere_cache(cover, model()), model(), again) || !same(cover, again)) std::abort();
  return 0;
}
