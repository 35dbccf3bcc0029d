#include "amp/roadmap/uas/hybrid_observer.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/roadmap/samplers/sampler.hpp"

namespace amp::roadmap {
namespace {

// A learning sampler that records what its observer tells it, in order.
class Recorder final : public Sampler, public SampleLearner {
 public:
  bool sample(core::Rng&, State&) override { return false; }
  void observe(const Roadmap&, const Insertion& i) override { log.push_back("observe " + std::to_string(i.vertex)); }
  void reward_last(const Insertion& i) override { log.push_back("reward " + std::to_string(i.vertex)); }
  void report(std::map<std::string, double>& extra) const override { extra["recorder_calls"] = log.size(); }
  std::vector<std::string> log;
};

// Every insertion is observed first; only samples, never seeds, are rewarded.
TEST(HybridObserver, ObservesEveryInsertionAndRewardsSamplesOnly) {
  auto owned = std::make_unique<Recorder>();
  const Recorder& recorder = *owned;
  const ObservedSampler made = with_hybrid_observer(std::move(owned), {{"constant", 7.0}});
  Roadmap roadmap;
  State q(2);
  q << 0.0, 0.0;
  const VertexId seed = roadmap.add_vertex(q);
  made.observer->inserted(roadmap, Insertion{seed, true, 0, 0, 0});
  q << 1.0, 0.0;
  const VertexId sample = roadmap.add_vertex(q);
  roadmap.add_edge(seed, sample, 1.0, EdgeCheck::kValid);
  made.observer->inserted(roadmap, Insertion{sample, false, 1, 1, 1});
  EXPECT_EQ(recorder.log, (std::vector<std::string>{"observe 0", "observe 1", "reward 1"}));

  std::map<std::string, double> extra;
  made.observer->report(extra);
  EXPECT_EQ(extra.at("constant"), 7.0);        // the constants, as given
  EXPECT_EQ(extra.at("recorder_calls"), 3.0);  // the learner's own figures
  // and the node classes, of samples only: the one sample joined the seed's component
  // with visibility 1/1: an oversample node
  EXPECT_EQ(extra.at("cc_oversample"), 1.0);
  EXPECT_EQ(extra.at("cc_create") + extra.at("cc_merge") + extra.at("cc_expand"), 0.0);
}

}  // namespace
}  // namespace amp::roadmap
