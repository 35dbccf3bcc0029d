#include "amp/nav/world_timeline.hpp"

#include <algorithm>
#include <numeric>
#include <string>

#include "amp/core/error.hpp"

namespace amp::nav {

WorldTimeline::WorldTimeline(std::shared_ptr<const NavWorld> base, std::vector<WorldEvent> events)
    : events_(std::move(events)) {
  if (!base) throw ParameterError("WorldTimeline: no world");
  worlds_.push_back(std::move(base));
  from_step_.push_back(0);
  std::vector<std::size_t> order(events_.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return events_[a].step < events_[b].step; });
  for (const std::size_t i : order) {
    const WorldEvent& e = events_[i];
    std::shared_ptr<const NavWorld> next;
    try {
      next = worlds_.back()->changed(e.change);
    } catch (const ParameterError& err) {
      throw ParameterError("events[" + std::to_string(i) + "] (step " + std::to_string(e.step) + "): " + err.what());
    }
    // Events of one step make one version (the base stays version 0, even under step-0 events).
    if (worlds_.size() > 1 && from_step_.back() == e.step) {
      worlds_.back() = std::move(next);
    } else {
      worlds_.push_back(std::move(next));
      from_step_.push_back(e.step);
    }
  }
}

std::size_t WorldTimeline::version_at(std::size_t step) const {
  // The last version whose first step is <= step.
  const auto it = std::upper_bound(from_step_.begin(), from_step_.end(), step);
  return static_cast<std::size_t>(it - from_step_.begin()) - 1;
}

const std::shared_ptr<const NavWorld>& WorldTimeline::at(std::size_t step) const { return worlds_[version_at(step)]; }

}  // namespace amp::nav
