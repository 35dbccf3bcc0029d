#pragma once
#include <optional>
#include <string_view>

#include "amp/core/coordinate_layout.hpp"
#include "amp/core/rng.hpp"
#include "amp/core/state.hpp"

namespace amp::core {

// A configuration space: sampling within bounds, a metric, interpolation along geodesics and the
// resolution at which edges are checked. Implementations: JointSpace (Rn, SE2, linkages), Se3Space.
class Space {
 public:
  virtual ~Space() = default;

  // "rn", "se2", "se3" or "linkage".
  virtual std::string_view kind() const = 0;
  // Number of coordinates of a State of this space (SE3: 7, x y z qx qy qz qw).
  virtual int dimension() const = 0;
  // Degrees of freedom (SE3: 6).
  virtual int dof() const { return dimension(); }

  // A state uniform in the bounds: unit_dimension() uniforms in [0, 1) mapped by from_unit.
  void sample_uniform(Rng& rng, State& out) const;
  // How many numbers in [0, 1) make one state (SE3: 6, three for the position and three for
  // Shoemake's rotation), and the map from them onto the space that is uniform when they are. A
  // low-discrepancy sequence fed through it covers the space evenly (HaltonSequence).
  virtual int unit_dimension() const { return dimension(); }
  virtual void from_unit(const double* u, State& out) const = 0;
  virtual double distance(const State& a, const State& b) const = 0;
  // The state a fraction t in [0, 1] of the way from a to b along the shortest path.
  virtual void interpolate(const State& a, const State& b, double t, State& out) const = 0;
  virtual bool in_bounds(const State& s) const = 0;
  // Clamps linear coordinates, wraps angles, renormalises quaternions.
  virtual void enforce_bounds(State& s) const = 0;
  // The largest distance() between two states of the space.
  virtual double maximum_extent() const = 0;

  // Embedding into R^m for KD-tree search: its Euclidean distance is a lower bound of distance(),
  // so a KD-tree's candidates re-ranked by distance() give exactly the k nearest.
  virtual int embedding_dimension() const = 0;
  virtual void embed(const State& s, double* out) const = 0;
  // Further embeddings of the same state (SE3 embeds q and -q, the same rotation).
  virtual int embedding_variants() const { return 1; }
  virtual void embed_variant(const State& s, int /*variant*/, double* out) const { embed(s, out); }

  // The state's coordinates by kind, for code that works on them one at a time (KD-tree bounds,
  // grid charts): it asks for the layout it needs instead of the space's type. None for a space
  // that offers no such code its coordinates (UnicycleSpace: velocities beside the pose).
  virtual std::optional<CoordinateLayout> coordinate_layout() const { return std::nullopt; }

  // Longest distance between two consecutive states checked along an edge.
  double resolution() const { return resolution_; }
  // Throws ParameterError unless 0 < r.
  void set_resolution(double r);

 protected:
  double resolution_ = 0.0;
};

}  // namespace amp::core
