#include "amp/learn/pgcs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"

namespace amp::learn {
namespace {

constexpr double kTol = 1e-12;

// No insertion or deletion unless a test asks for one.
PgcsSettings still(int window) {
  PgcsSettings s;
  s.window = window;
  s.warm_up = false;  // the hand computations below use l from the first step
  s.insert_every = 1000000000;
  s.delete_every = 1000000000;
  return s;
}

TEST(Pgcs, WarmUpMakesTheCentreTheRunningMeanUntilTheWindowFills) {
  PgcsSettings s = still(4);
  s.warm_up = true;
  Pgcs p(s);
  // One cluster: p(k|xi) = pi = 1, so eta = 1/min(n, l): 1/2, 1/3, 1/4, then 1/4 (l = 4).
  const Eigen::Vector2d xs[] = {{0, 0}, {2, 0}, {4, 3}, {6, 1}, {10, 4}};
  p.step(xs[0]);
  p.step(xs[1]);
  EXPECT_NEAR(p.mean(p.ids()[0]).x(), 1.0, kTol);  // (0 + 2) / 2
  p.step(xs[2]);
  EXPECT_NEAR(p.mean(p.ids()[0]).x(), 2.0, kTol);  // (0 + 2 + 4) / 3
  EXPECT_NEAR(p.mean(p.ids()[0]).y(), 1.0, kTol);
  p.step(xs[3]);
  EXPECT_NEAR(p.mean(p.ids()[0]).x(), 3.0, kTol);  // (0 + 2 + 4 + 6) / 4
  EXPECT_NEAR(p.mean(p.ids()[0]).y(), 1.0, kTol);
  p.step(xs[4]);
  EXPECT_NEAR(p.mean(p.ids()[0]).x(), 3.0 + (10.0 - 3.0) / 4, kTol);  // the window is full: eta = 1/4
  EXPECT_NEAR(p.mean(p.ids()[0]).y(), 1.0 + (4.0 - 1.0) / 4, kTol);
}

TEST(Pgcs, FirstSampleInitialises) {
  Pgcs p(still(10));
  p.step({1, 2});
  ASSERT_EQ(p.size(), 1);
  EXPECT_EQ(p.mean(0), Eigen::Vector2d(1, 2));
  EXPECT_EQ(p.variance(0), p.settings().sigma2_min);  // 0, floored
  EXPECT_EQ(p.prior(0), 1.0);
}

TEST(Pgcs, OneAdaptationStepByHand) {
  // A = (0,0), s2 1, pi .5; B = (3,0), s2 4, pi .5; xi = (1,1), l = 10. By hand (double precision):
  //  c_A = 2/1 + 2 log(2 pi) - 2 log .5 = 7.0620484939385815
  //  c_B = 5/4 + 2 log(8 pi) - 2 log .5 = 9.084637216178363            -> winner A
  //  p(A|xi) = e^{-c_A/2} / (e^{-c_A/2} + e^{-c_B/2}) = 0.7332733813807409, p(B|xi) = 0.266726618619259
  //  eta = 0.73327338 / (10 * .5) = 0.1466546762761482
  //  mu_A = 0 + eta (1,1) = (0.14665467627614820, same); s2_A = 1 + eta (|(1,1) - 0|^2 - 1) = 1.1466546762761483
  //  pi_A = .5 + (0.73327338 - .5) / 10 = 0.5233273381380741; pi_B = 0.4766726618619259
  Pgcs p(still(10));
  const int a = p.add_cluster({0, 0}, 1, 0.5), b = p.add_cluster({3, 0}, 4, 0.5);
  const Eigen::Vector2d xi(1, 1);
  EXPECT_NEAR(p.criterion(a, xi), 7.0620484939385815, kTol);
  EXPECT_NEAR(p.criterion(b, xi), 9.084637216178363, kTol);
  EXPECT_EQ(p.winner(xi), a);
  EXPECT_NEAR(p.posterior(a, xi), 0.7332733813807409, kTol);
  EXPECT_NEAR(p.posterior(b, xi), 0.266726618619259, kTol);
  p.step(xi);
  EXPECT_EQ(p.last_step().winner, a);
  EXPECT_NEAR(p.last_step().posterior, 0.7332733813807409, kTol);
  EXPECT_NEAR(p.last_step().eta, 0.1466546762761482, kTol);
  EXPECT_NEAR(p.mean(a).x(), 0.1466546762761482, kTol);
  EXPECT_NEAR(p.mean(a).y(), 0.1466546762761482, kTol);
  EXPECT_NEAR(p.variance(a), 1.1466546762761483, kTol);
  EXPECT_EQ(p.mean(b), Eigen::Vector2d(3, 0));  // only the winner moves
  EXPECT_EQ(p.variance(b), 4.0);
  EXPECT_NEAR(p.prior(a), 0.5233273381380741, kTol);
  EXPECT_NEAR(p.prior(b), 0.4766726618619259, kTol);
}

TEST(Pgcs, LearningRateIsClampedToOne) {
  // A has pi .02 and takes p(A|xi) ~ 1 (B is far): eta = 1 / (10 * .02) = 5 -> 1, so mu_A = xi and
  // s2_A = |xi - mu_old|^2 = 0.25 exactly.
  Pgcs p(still(10));
  const int a = p.add_cluster({0, 0}, 1, 0.02);
  p.add_cluster({100, 100}, 1, 0.98);
  p.step({0.3, 0.4});
  EXPECT_EQ(p.last_step().winner, a);
  EXPECT_EQ(p.last_step().eta, 1.0);
  EXPECT_NEAR(p.mean(a).x(), 0.3, kTol);
  EXPECT_NEAR(p.mean(a).y(), 0.4, kTol);
  EXPECT_NEAR(p.variance(a), 0.25, kTol);
}

// A, B, C with a_pi = a_sigma = 1 and sum s2 = 4:
//  A (0,0) s2 1 pi .5: phi .75;  B (2,0) s2 2 pi .3: phi .8;  C (0,2) s2 1 pi .2: phi .45.
Pgcs three_clusters() {
  PgcsSettings s = still(10);
  s.delete_min_clusters = 3;
  Pgcs p(s);
  p.add_cluster({0, 0}, 1, 0.5);
  p.add_cluster({2, 0}, 2, 0.3);
  p.add_cluster({0, 2}, 1, 0.2);
  return p;
}

TEST(Pgcs, InsertionByHand) {
  // q = B (phi .8); its Delaunay neighbours A (.75) and C (.45): f = A. w_q = .8/1.55, w_f = .75/1.55.
  //  mu_r = w_q (2,0) + w_f (0,0) = (1.6/1.55, 0) = (1.032258064516129, 0)
  //  s2_r = (.8*2 + .75*1)/1.55 = 1.5161290322580645; pi_r = (.8*.3 + .75*.5)/1.55 = 0.3967741935483871
  //  s2_B = (1 - .8/1.55) 2 = 0.967741935483871; pi_B = (.75/1.55) .3 = 0.14516129032258066
  //  s2_A = (1 - .75/1.55) 1 = 0.5161290322580645; pi_A = (.8/1.55) .5 = 0.25806451612903225
  Pgcs p = three_clusters();
  EXPECT_NEAR(p.phi(0), 0.75, kTol);
  EXPECT_NEAR(p.phi(1), 0.8, kTol);
  EXPECT_NEAR(p.phi(2), 0.45, kTol);
  const int r = p.insert_cluster();
  ASSERT_EQ(r, 3);
  EXPECT_NEAR(p.mean(r).x(), 1.032258064516129, kTol);
  EXPECT_NEAR(p.mean(r).y(), 0.0, kTol);
  EXPECT_NEAR(p.variance(r), 1.5161290322580645, kTol);
  EXPECT_NEAR(p.prior(r), 0.3967741935483871, kTol);
  EXPECT_NEAR(p.variance(1), 0.967741935483871, kTol);
  EXPECT_NEAR(p.prior(1), 0.14516129032258066, kTol);
  EXPECT_NEAR(p.variance(0), 0.5161290322580645, kTol);
  EXPECT_NEAR(p.prior(0), 0.25806451612903225, kTol);
  EXPECT_EQ(p.variance(2), 1.0);  // C untouched
  EXPECT_EQ(p.prior(2), 0.2);
  EXPECT_NEAR(p.prior(0) + p.prior(1) + p.prior(2) + p.prior(r), 1.0, kTol);
  EXPECT_EQ(p.triangulation().size(), 4);
  EXPECT_EQ(p.triangulation().nearest({1.0, 0.1}), r);
}

TEST(Pgcs, InsertionWithoutNeighbourSplitsTheCluster) {
  // One cluster: f = q, so r = (mu_q, s2_q, pi_q) and q halves its variance and prior.
  Pgcs p(still(10));
  p.add_cluster({1, 1}, 2, 1);
  const int r = p.insert_cluster();
  ASSERT_EQ(r, 1);
  EXPECT_EQ(p.mean(r), Eigen::Vector2d(1, 1));
  EXPECT_EQ(p.variance(r), 2.0);
  EXPECT_EQ(p.prior(r), 1.0);
  EXPECT_EQ(p.variance(0), 1.0);
  EXPECT_EQ(p.prior(0), 0.5);
  EXPECT_TRUE(p.triangulation().hidden(r));  // a duplicate centre, out of the triangulation
}

TEST(Pgcs, DeletionByHand) {
  // The lowest phi is C (.45); A and B are renormalised by 1 / (1 - .2): .625 and .375.
  Pgcs p = three_clusters();
  EXPECT_EQ(p.delete_cluster(), 2);
  EXPECT_EQ(p.ids(), (std::vector<int>{0, 1}));
  EXPECT_NEAR(p.prior(0), 0.625, kTol);
  EXPECT_NEAR(p.prior(1), 0.375, kTol);
  EXPECT_EQ(p.triangulation().edges(), (std::vector<std::pair<int, int>>{{0, 1}}));
  EXPECT_EQ(p.delete_cluster(), -1);  // fewer than delete_min_clusters
  EXPECT_EQ(p.add_cluster({5, 5}, 1, 0.1), 2);  // the freed id is reused
}

// The paper's updates written out naively (every cluster, no index, no lazy scale).
struct NaiveModel {
  std::vector<Eigen::Vector2d> mu;
  std::vector<double> s2, pi;
  void step(const Eigen::Vector2d& xi, double l) {
    std::vector<double> t(mu.size());
    double sum = 0.0;
    for (std::size_t k = 0; k < mu.size(); ++k) {  // eq. (1) times the prior
      t[k] = pi[k] / (2 * std::numbers::pi * s2[k]) * std::exp(-(xi - mu[k]).squaredNorm() / (2 * s2[k]));
      sum += t[k];
    }
    const std::size_t w = static_cast<std::size_t>(std::max_element(t.begin(), t.end()) - t.begin());
    const double eta = std::min(1.0, t[w] / sum / (l * pi[w]));
    const Eigen::Vector2d d = xi - mu[w];
    mu[w] += eta * d;
    s2[w] += eta * (d.squaredNorm() - s2[w]);
    for (std::size_t k = 0; k < mu.size(); ++k) pi[k] += (t[k] / sum - pi[k]) / l;
  }
};

TEST(Pgcs, ManyStepsMatchANaiveComputation) {
  // window 3: the lazy prior scale (2/3)^t is folded back several times in 2,000 steps.
  Pgcs p(still(3));
  NaiveModel naive{{{0, 0}, {2, 0}, {1, 2}}, {1, 1, 1}, {0.3, 0.3, 0.4}};
  for (std::size_t k = 0; k < 3; ++k) p.add_cluster(naive.mu[k], naive.s2[k], naive.pi[k]);
  core::Rng rng(3);
  for (int t = 0; t < 2000; ++t) {
    const Eigen::Vector2d xi(rng.uniform(-1, 3), rng.uniform(-1, 3));
    naive.step(xi, 3);
    p.step(xi);
  }
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(p.mean(k).x(), naive.mu[k].x(), 1e-9);
    EXPECT_NEAR(p.mean(k).y(), naive.mu[k].y(), 1e-9);
    EXPECT_NEAR(p.variance(k), naive.s2[k], 1e-9);
    EXPECT_NEAR(p.prior(k), naive.pi[k], 1e-9);
  }
}

TEST(Pgcs, WindowOneSetsThePriorsToThePosteriors) {
  // l = 1: pi_k = p(k|xi) after the step (the same numbers as OneAdaptationStepByHand), and
  // eta = 0.73327338 / (1 * .5) > 1 is clamped to 1, so mu_A = xi.
  Pgcs p(still(1));
  const int a = p.add_cluster({0, 0}, 1, 0.5), b = p.add_cluster({3, 0}, 4, 0.5);
  p.step({1, 1});
  EXPECT_NEAR(p.prior(a), 0.7332733813807409, kTol);
  EXPECT_NEAR(p.prior(b), 0.266726618619259, kTol);
  EXPECT_EQ(p.last_step().eta, 1.0);
  EXPECT_EQ(p.mean(a), Eigen::Vector2d(1, 1));
}

TEST(Pgcs, IndexedWinnerEqualsLinearScan) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    PgcsSettings s;
    s.window = 200;
    s.max_clusters = 120;
    s.insert_every = 15;
    s.delete_every = 100;
    s.index_min_clusters = 4;
    s.index_leaf_size = 3;
    Pgcs p(s);
    core::Rng rng(seed);
    int compared = 0;
    for (int t = 0; t < 3000; ++t) {
      // A random walk with jumps, over a 10 x 10 square.
      const Eigen::Vector2d xi(rng.uniform(0, 10), rng.uniform(0, 10) * (t % 3 == 0 ? 1.0 : 0.3));
      if (p.size() > 0) {
        ASSERT_EQ(p.winner(xi), p.winner_linear(xi)) << "seed " << seed << " step " << t;
        ++compared;
      }
      p.step(xi);
    }
    EXPECT_GT(p.size(), 40);
    EXPECT_GT(compared, 2900);
  }
}

TEST(Pgcs, IndexedRunEqualsLinearRun) {
  // The skipped posteriors (each < 1e-18 of the sum) do not change the learning.
  PgcsSettings s;
  s.window = 300;
  s.max_clusters = 60;
  s.insert_every = 30;
  s.delete_every = 400;
  s.index_min_clusters = 8;
  PgcsSettings linear = s;
  linear.index_min_clusters = 1000000;
  Pgcs a(s), b(linear);
  core::Rng rng(11);
  for (int t = 0; t < 4000; ++t) {
    const Eigen::Vector2d xi(rng.uniform(0, 10), rng.uniform(0, 10));
    a.step(xi);
    b.step(xi);
  }
  ASSERT_EQ(a.ids(), b.ids());
  for (int k : a.ids()) {
    EXPECT_NEAR((a.mean(k) - b.mean(k)).norm(), 0.0, 1e-9);
    EXPECT_NEAR(a.variance(k), b.variance(k), 1e-9);
    EXPECT_NEAR(a.prior(k), b.prior(k), 1e-12);
  }
}

TEST(Pgcs, CentresConvergeToTheMeansOfAMixture) {
  const std::vector<Eigen::Vector2d> means{{0, 0}, {10, 0}, {0, 10}, {10, 10}, {5, 5}};
  PgcsSettings s;
  s.window = 500;
  s.max_clusters = 10;
  s.insert_every = 500;
  s.delete_every = 1000000000;
  Pgcs p(s);
  core::Rng rng(5);
  // The stream dwells 300 samples on one component at a time, as the paper's exploring robot's
  // positions do. (On an i.i.d. stream, insertion between q and its neighbour can leave one broad
  // cluster spanning several components with starved clusters between them: seen with this seed.)
  std::size_t component = 0;
  for (int t = 0; t < 30000; ++t) {
    if (t % 300 == 0) component = rng.uniform_index(means.size());
    const Eigen::Vector2d& m = means[component];
    p.step({rng.normal(m.x(), 0.5), rng.normal(m.y(), 0.5)});
  }
  for (const Eigen::Vector2d& m : means) {
    double best = 1e300;
    for (int k : p.ids()) best = std::min(best, (p.mean(k) - m).norm());
    EXPECT_LT(best, 0.3) << "mean (" << m.transpose() << ")";
  }
}

TEST(Pgcs, BadSettingsThrow) {
  auto bad = [](auto edit) {
    PgcsSettings s;
    edit(s);
    EXPECT_THROW(Pgcs{s}, ParameterError);
  };
  bad([](PgcsSettings& s) { s.window = 0; });
  bad([](PgcsSettings& s) { s.max_clusters = 2; });
  bad([](PgcsSettings& s) { s.insert_every = 0; });
  bad([](PgcsSettings& s) { s.delete_every = 0; });
  bad([](PgcsSettings& s) { s.sigma2_min = 0; });
  bad([](PgcsSettings& s) { s.eta_max = 1.5; });
  bad([](PgcsSettings& s) { s.a_pi = s.a_sigma = 0; });
  EXPECT_NO_THROW(PgcsSettings{}.validate());
}

}  // namespace
}  // namespace amp::learn
