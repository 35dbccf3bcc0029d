#pragma once
// A robot's links as sets of spheres that provably cover their collision geometry
// (docs/arms.md, "Sphere model"): generated from the meshes, or a spherized URDF's spheres inflated
// until they cover. A path free in the sphere model is free for the meshes, because every point of
// every collision solid lies inside some sphere of its link.
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "amp/world/arm_model.hpp"

namespace amp::world {

// One sphere of link `link` (an index into ArmModel::links()), in the link's frame.
struct LinkSphere {
  int link = 0;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0.0;
};

struct SphereCoverOptions {
  // The solids are cut into convex pieces no longer than this (metres) before they are grouped;
  // a piece lies inside a sphere when all its corners do, which is what makes the set a cover.
  double piece_size = 0.01;
  // A link's pieces are grouped in slabs across its long axis, one sphere each; the generator adds
  // slabs until every sphere reaches at most (1 + bulge) times as far as its own slab does from the
  // axis line through its centre, or the link has max_per_link spheres.
  int max_per_link = 16;
  double bulge = 0.1;
};

// How a link's spheres relate to its solids.
struct LinkCoverReport {
  int link = 0;
  int spheres = 0;
  // Every point of the link's spheres lies within this distance of the link's solids: the excess of
  // the cover. Per sphere: its radius plus its centre's distance to the nearest solid point found (a
  // piece corner), at most 2 x its radius for a generated sphere, which holds a point of a solid;
  // 0 for a sphere solid kept as it is.
  double excess_bound = 0.0;
  // Sum of the spheres' volumes (m^3), beside the volume of the solids' bounding box.
  double sphere_volume = 0.0;
  double box_volume = 0.0;
  // For a given (spherized) set: how far its spheres had to grow to cover (the largest growth).
  double inflation = 0.0;
};

struct SphereCover {
  std::vector<LinkSphere> spheres;  // grouped by link, links in model order
  std::vector<LinkCoverReport> links;  // one per link with collision geometry
  SphereCoverOptions options;  // what it was computed with: part of the cache key
};

// Spheres covering every link's collision solids: mesh surfaces (FCL tests mesh triangles) and
// the whole volume of boxes and cylinders (FCL's primitives are solid); a sphere solid is kept as
// it is. Deterministic. Links without collision geometry get no spheres.
SphereCover cover_with_spheres(const ArmModel& model, const SphereCoverOptions& options = {});

// Grows the `given` spheres (a spherized URDF's, with link indices of `model`) until they cover
// every link's collision solids: each piece of a solid goes to the sphere that must grow least to
// hold it. Throws ParameterError ("link 'x' has collision geometry but no sphere in <label>") when a
// link with solids has no sphere to grow.
SphereCover inflate_to_cover(const ArmModel& model, std::vector<LinkSphere> given, const std::string& label,
                             const SphereCoverOptions& options = {});

// The spheres of a spherized URDF (its links' <collision> spheres), matched to `model` by link
// name. Throws FileError naming the file when a link of the file is not one of the model's, or a
// collision element of it is not a sphere.
std::vector<LinkSphere> load_sphere_urdf(const std::filesystem::path& file, const ArmModel& model);

// The model with each link's collision replaced by its spheres (Solid::sphere): what the sphere
// checker and the FCL oracle both see.
ArmModel with_sphere_collision(const ArmModel& model, const std::vector<LinkSphere>& spheres);

// A per-user folder for generated sphere sets: $AMP_CACHE_DIR, else $XDG_CACHE_HOME/amp, else
// $HOME/.cache/amp; empty when none is set (no caching).
std::filesystem::path default_sphere_cache_dir();

// cover_with_spheres through a cache in `cache_dir` keyed by the solids' content and the options:
// a hit is read back, a miss (or an unreadable entry) is generated and written. An empty
// `cache_dir` only generates. A cache that cannot be written is not an error.
SphereCover cached_cover_with_spheres(const ArmModel& model, const std::filesystem::path& cache_dir,
                                      const SphereCoverOptions& options = {});

// The cache file format, exposed for its fuzz target: parses `text` as a cache entry for `model`;
// false (and `out` untouched) when it is not a well-formed one.
bool parse_sphere_cache(const std::string& text, const ArmModel& model, SphereCover& out);
std::string format_sphere_cache(const SphereCover& cover, const ArmModel& model);

}  // namespace amp::world
