#pragma once
#include <cstddef>
#include <memory>
#include <vector>

#include "amp/nav/nav_world.hpp"
#include "amp/nav/world_event.hpp"

namespace amp::nav {

// A world and the events that change it, applied once up front: one immutable world per distinct
// event step, so a simulator looks its world up by step and threads share every version.
class WorldTimeline {
 public:
  // Applies the events in step order (file order among equal steps). Throws ParameterError naming
  // the event ("events[2]: ...") when one cannot apply.
  WorldTimeline(std::shared_ptr<const NavWorld> base, std::vector<WorldEvent> events);

  const std::vector<WorldEvent>& events() const { return events_; }
  const std::shared_ptr<const NavWorld>& base() const { return worlds_.front(); }
  // The world during step `step`: every event with event.step <= step applied.
  const std::shared_ptr<const NavWorld>& at(std::size_t step) const;
  // The index of that world among all versions (0 = base), for noticing a change cheaply.
  std::size_t version_at(std::size_t step) const;
  std::size_t version_count() const { return worlds_.size(); }

 private:
  std::vector<WorldEvent> events_;
  std::vector<std::size_t> from_step_;  // worlds_[i] holds from step from_step_[i] on
  std::vector<std::shared_ptr<const NavWorld>> worlds_;
};

}  // namespace amp::nav
