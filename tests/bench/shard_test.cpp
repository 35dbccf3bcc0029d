// shard.cpp: `--shard i/N`, a deterministic 1/N of an experiment's trials.
#include "amp/bench/shard.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"

namespace amp::bench {
namespace {

TEST(Shard, ParsesIOverNAndPrintsItBack) {
  EXPECT_EQ(parse_shard("0/1"), (Shard{0, 1}));
  EXPECT_EQ(parse_shard("3/4"), (Shard{3, 4}));
  EXPECT_EQ(parse_shard("12/100").to_string(), "12/100");
  for (const std::string text : {"0/4", "1/4", "2/4", "3/4"}) EXPECT_EQ(parse_shard(text).to_string(), text);
}

TEST(Shard, RefusesAnythingButZeroToNMinusOneOverN) {
  const auto message = [](const std::string& text) {
    try {
      parse_shard(text);
    } catch (const ParameterError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  for (const std::string bad : {"x", "", "/", "1", "1/", "/4", "-1/4", "1/4/2", " 1/4", "1/4 ", "1.0/4", "a/4"}) {
    EXPECT_EQ(message(bad), "--shard: expected i/N with integers, e.g. 0/4, got '" + bad + "'") << bad;
  }
  for (const std::string bad : {"3/2", "1/0", "0/0", "4/4"}) {
    EXPECT_EQ(message(bad), "--shard: need 0 <= i < N, got '" + bad + "'") << bad;
  }
}

// Trial i belongs to shard i mod N: the shards of one N partition the trials, and each holds a
// share of every run of N consecutive trials.
TEST(Shard, ShardsOfOneCountPartitionTheTrials) {
  constexpr std::size_t kCount = 3, kTrials = 20;
  std::vector<int> owners(kTrials, 0);
  for (std::size_t s = 0; s < kCount; ++s) {
    const Shard shard{s, kCount};
    std::vector<std::size_t> mine;
    for (std::size_t t = 0; t < kTrials; ++t) {
      if (shard.owns(t)) {
        ++owners[t];
        mine.push_back(t);
      }
    }
    EXPECT_EQ(mine.front(), s);
    for (std::size_t i = 1; i < mine.size(); ++i) EXPECT_EQ(mine[i] - mine[i - 1], kCount);
  }
  for (std::size_t t = 0; t < kTrials; ++t) EXPECT_EQ(owners[t], 1) << "trial " << t;
  const Shard whole;  // 0/1: every trial
  for (std::size_t t = 0; t < kTrials; ++t) EXPECT_TRUE(whole.owns(t));
}

}  // namespace
}  // namespace amp::bench
