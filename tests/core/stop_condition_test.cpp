// StopCondition and StopPoll: a deadline is seen on the first check after it (no stride over calls),
// stays seen, and long loops that poll every kStride steps stop within one stride.
#include "amp/core/stop_condition.hpp"

#include <atomic>
#include <chrono>
#include <limits>
#include <thread>

#include <gtest/gtest.h>

namespace amp::core {
namespace {

constexpr auto kPastTheLimit = std::chrono::milliseconds(30);  // sleep after a 10 ms limit

TEST(StopCondition, EveryCheckAfterTheDeadlineSeesIt) {
  const StopCondition stop(0.01, 1000);
  EXPECT_FALSE(stop.fired());
  std::this_thread::sleep_for(kPastTheLimit);
  EXPECT_FALSE(stop.fired());  // fired() does not read the clock
  // The first check after the deadline, however many calls came before (the clock was once read
  // only every 8th call, so up to 7 long planner iterations ran past the limit).
  EXPECT_EQ(stop.check(0), StopReason::kTimeLimit);
  EXPECT_TRUE(stop.fired());
  EXPECT_TRUE(stop.time_up());
}

TEST(StopCondition, TimeUpIsLatchedAndReportedByCheck) {
  const StopCondition stop(0.01, 1000);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(stop.check(5), StopReason::kNone);
  std::this_thread::sleep_for(kPastTheLimit);
  EXPECT_TRUE(stop.time_up());
  EXPECT_TRUE(stop.fired());
  EXPECT_EQ(stop.check(5), StopReason::kTimeLimit);
  EXPECT_EQ(stop.check(1000), StopReason::kNodeLimit);  // the node limit is still reported as such
}

TEST(StopCondition, CancelIsTimeUpWithoutAClock) {
  std::atomic<bool> cancel{false};
  const StopCondition stop(1e6, 1000, &cancel);
  EXPECT_FALSE(stop.time_up());
  cancel = true;
  EXPECT_TRUE(stop.fired());
  EXPECT_TRUE(stop.time_up());
  EXPECT_EQ(stop.check(0), StopReason::kCancelled);
}

TEST(StopCondition, UnboundedLimitsNeverFireAndNegativeOnesAtOnce) {
  for (const double limit : {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN(), 1e300}) {
    const StopCondition stop(limit, std::numeric_limits<std::size_t>::max());
    EXPECT_FALSE(stop.time_up()) << limit;
    EXPECT_EQ(stop.check(123456789), StopReason::kNone) << limit;
  }
  const StopCondition negative(-1.0, 10);
  EXPECT_TRUE(negative.time_up());
}

TEST(StopPoll, NullNeverFires) {
  StopPoll poll(nullptr);
  for (std::uint32_t i = 0; i < 3 * StopPoll::kStride; ++i) ASSERT_FALSE(poll.step());
  EXPECT_FALSE(poll.fired());
}

TEST(StopPoll, FiresWithinOneStrideOfTheDeadlineAndStaysFired) {
  const StopCondition stop(0.01, 1000);
  StopPoll poll(&stop);
  for (std::uint32_t i = 0; i < 2 * StopPoll::kStride; ++i) ASSERT_FALSE(poll.step());  // well before 10 ms
  std::this_thread::sleep_for(kPastTheLimit);
  std::uint32_t steps = 0;
  while (!poll.step()) ASSERT_LE(++steps, StopPoll::kStride);
  EXPECT_TRUE(poll.step());  // latched: no stride to wait for again
  EXPECT_TRUE(poll.fired());
  // A new poll on a fired condition refuses its work before the first step.
  StopPoll next(&stop);
  EXPECT_TRUE(next.fired());
}

}  // namespace
}  // namespace amp::core
