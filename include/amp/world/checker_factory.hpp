#pragma once
#include <memory>

#include "amp/core/counters.hpp"
#include "amp/world/validity_checker.hpp"

namespace amp::world {

// The role of a world that runs use: a validity checker per thread. Implementations are immutable,
// so one factory serves every thread of a benchmark.
class CheckerFactory {
 public:
  virtual ~CheckerFactory() = default;
  // A new checker that counts into `counters`; one per thread.
  virtual std::unique_ptr<ValidityChecker> make_checker(core::Counters& counters) const = 0;
};

}  // namespace amp::world
