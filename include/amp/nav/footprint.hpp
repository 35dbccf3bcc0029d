#pragma once
#include <cmath>
#include <vector>

#include <Eigen/Core>

namespace amp::nav {

class NavWorld;

// A robot's footprint as equal discs in its body frame (x forward): one disc at the origin for a
// round robot, or a certified cover of a rectangle, so that every check stays a disc check the
// navigation worlds answer exactly. A rectangle `length` x `width` is cut into n equal slices
// along its length, each inside the disc through its corners (radius sqrt((w/2)^2 + (l/2n)^2));
// n is the least that keeps that radius within `cover_tolerance` of w/2, so the cover is at most
// 2 cover_tolerance wider than the rectangle and never misses any of it.
class Footprint {
 public:
  static constexpr double kCoverTolerance = 0.005;  // m

  static Footprint disc(double radius);
  // Throws ParameterError unless length >= width > 0 (a robot is driven lengthwise) and both finite.
  static Footprint rectangle(double length, double width, double cover_tolerance = kCoverTolerance);

  const std::vector<Eigen::Vector2d>& centres() const { return centres_; }  // body frame
  double disc_radius() const { return radius_; }
  double length() const { return length_; }  // along the heading (2 r for a disc)
  double width() const { return width_; }
  // How far a disc centre is from the origin at most: a turn by dtheta moves it by this x dtheta.
  double centre_reach() const { return reach_; }
  bool is_disc() const { return centres_.size() == 1 && reach_ == 0.0; }

  // The discs' centres in the world at pose (p, heading).
  std::vector<Eigen::Vector2d> placed(const Eigen::Vector2d& p, double heading) const;
  // Calls visit(centre) with each disc's centre in the world at pose (p, heading) until one call
  // returns false, without allocating (simulators and searches ask this millions of times).
  // Returns whether every call returned true.
  template <class Visit>
  bool all_placed(const Eigen::Vector2d& p, double heading, Visit&& visit) const {
    const double c = std::cos(heading), s = std::sin(heading);
    for (const Eigen::Vector2d& b : centres_) {
      if (!visit(Eigen::Vector2d(p.x() + c * b.x() - s * b.y(), p.y() + s * b.x() + c * b.y()))) return false;
    }
    return true;
  }
  // Every disc free (touching is free, as NavWorld::disc_free).
  bool free(const NavWorld& world, const Eigen::Vector2d& p, double heading) const;
  // The least clearance of the discs: < 0 when one overlaps an obstacle.
  double clearance(const NavWorld& world, const Eigen::Vector2d& p, double heading) const;
  // min(clearance(world, p, heading), cap), exact, and cheaper far from obstacles on a map.
  double clearance_up_to(const NavWorld& world, const Eigen::Vector2d& p, double heading, double cap) const;
  // Whether the footprint is free all along the turn in place at p from heading `from` by `turn`
  // radians (either sign), by conservative advancement on the clearance: a turn by c / reach
  // moves no disc by more than c. A disc footprint turns freely wherever it is free.
  bool turn_free(const NavWorld& world, const Eigen::Vector2d& p, double from, double turn) const;

 private:
  Footprint(std::vector<Eigen::Vector2d> centres, double radius, double length, double width);
  std::vector<Eigen::Vector2d> centres_;
  double radius_ = 0.0, length_ = 0.0, width_ = 0.0, reach_ = 0.0;
};

}  // namespace amp::nav
