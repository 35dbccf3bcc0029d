// SINS's cycle runs every control interval inside the navigation loop: retrieve, adapt and learn
// must not touch the heap, except for the two vectors of a created case. Global operator new is
// replaced by a counting one for this executable.
#include <gtest/gtest.h>

#include "support/counting_allocator.hpp"


#include "amp/core/rng.hpp"
#include "amp/learn/case_library.hpp"

using amp::test::g_allocations;

namespace amp::learn {
namespace {

TEST(CaseLibraryAllocation, TheCycleAllocatesOnlyForACreatedCase) {
  CaseSettings s;
  s.case_length = 20;
  s.max_cases = 10;
  CaseLibrary lib(s);
  CaseHistory h(s.case_length);
  core::Rng rng(9);
  CaseOutputs outputs{0.5, 0.5, 0.5, 0.5};
  long created = 0, cycle_allocations = 0, learn_allocations = 0;
  for (int t = 0; t < 2000; ++t) {
    const double regime = 0.1 + 0.2 * ((t / 100) % 5);  // five regimes in turn
    const CaseInputs in{regime, regime, rng.uniform(0, 0.05), rng.uniform(0, 0.05)};
    long before = g_allocations.load();
    h.push(in, outputs);
    const CaseMatch m = lib.retrieve(h);
    outputs = lib.adapt(m, rng);
    cycle_allocations += g_allocations.load() - before;
    before = g_allocations.load();
    created += lib.learn(m, h) == Learned::kCreated;
    learn_allocations += g_allocations.load() - before;
  }
  EXPECT_EQ(cycle_allocations, 0);
  EXPECT_GE(created, 1);
  EXPECT_EQ(learn_allocations, 2 * created);  // a new case's inputs and outputs
}

}  // namespace
}  // namespace amp::learn
