#include "amp/nav/pgcs/route_planner.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/learn/pgcs.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;
constexpr double kPi = std::numbers::pi;

// A(0,0) B(1,0) C(2,0) on a line and D(1,1) above: Delaunay edges AB, BC, AD, BD, CD. The start
// (-0.5, 0) is nearest A, the target (2.5, 0) nearest C.
struct Diamond {
  learn::Pgcs g;
  int a, b, c, d;
  explicit Diamond(double pa = 0.25, double pb = 0.25, double pc = 0.25, double pd = 0.25) {
    a = g.add_cluster({0, 0}, 0.1, pa);
    b = g.add_cluster({1, 0}, 0.1, pb);
    c = g.add_cluster({2, 0}, 0.1, pc);
    d = g.add_cluster({1, 1}, 0.1, pd);
  }
};
const V kStart(-0.5, 0), kTarget(2.5, 0);

std::vector<int> clusters_of(const Route& r) { return {r.nodes.begin() + 1, r.nodes.end() - 1}; }

TEST(RoutePlanner, StraightRouteWinsOnceTurnsCost) {
  Diamond w;
  EdgeMemory memory(0.01);
  CentreGraph graph(w.g, memory);
  RoutePlanner p({1.0, 0.0, 1});
  const Route r = p.plan(graph, kStart, kTarget);
  ASSERT_FALSE(r.empty());
  EXPECT_EQ(r.nodes.front(), Route::kStart);
  EXPECT_EQ(r.nodes.back(), Route::kTarget);
  EXPECT_EQ(clusters_of(r), (std::vector<int>{w.a, w.b, w.c}));
  EXPECT_NEAR(r.cost, 3.0, 1e-12);  // 0.5 + 1 + 1 + 0.5, no turn
  EXPECT_EQ(r.points.front(), kStart);
  EXPECT_EQ(r.points.back(), kTarget);
}

TEST(RoutePlanner, WithoutTurnCostOnlyLengthCounts) {
  Diamond w;
  EdgeMemory memory(0.01);
  memory.mark(w.a, w.b, w.g.mean(w.a), w.g.mean(w.b));
  CentreGraph graph(w.g, memory);
  RoutePlanner p({0.0, 0.0, 1});
  const Route r = p.plan(graph, kStart, kTarget);
  EXPECT_EQ(clusters_of(r), (std::vector<int>{w.a, w.d, w.c}));
  EXPECT_NEAR(r.cost, 1.0 + 2 * std::sqrt(2.0), 1e-12);
}

TEST(RoutePlanner, IllegalEdgeIsAvoidedAndTurnsAreCharged) {
  Diamond w;
  EdgeMemory memory(0.01);
  memory.mark(w.b, w.a, w.g.mean(w.b), w.g.mean(w.a));  // either order
  CentreGraph graph(w.g, memory);
  RoutePlanner p({1.0, 0.0, 1});
  const Route r = p.plan(graph, kStart, kTarget);
  // A-D-C turns pi/4 at A, pi/2 at D and pi/4 at C; A-D-B-C would turn 3 pi/2 for a shorter gain.
  EXPECT_EQ(clusters_of(r), (std::vector<int>{w.a, w.d, w.c}));
  EXPECT_NEAR(r.cost, 1.0 + 2 * std::sqrt(2.0) + kPi, 1e-12);
}

TEST(RoutePlanner, EdgeBlockedForThisPlanIsLeftOutLikeAnIllegalOne) {
  Diamond w;
  const EdgeMemory remembered(0.01);
  EdgeMemory now(0.0);
  now.mark(w.a, w.b, w.g.mean(w.a), w.g.mean(w.b));
  CentreGraph graph(w.g, remembered, &now);
  RoutePlanner p({1.0, 0.0, 1});
  const Route r = p.plan(graph, kStart, kTarget);
  EXPECT_EQ(clusters_of(r), (std::vector<int>{w.a, w.d, w.c}));
  now.clear();  // read afresh by the next plan, on the same graph
  EXPECT_EQ(clusters_of(p.plan(graph, kStart, kTarget)), (std::vector<int>{w.a, w.b, w.c}));
}

TEST(RoutePlanner, SuspectEdgeIsALastResort) {
  Diamond w;
  EdgeMemory memory(0.01, 2);
  memory.mark(w.a, w.b, w.g.mean(w.a), w.g.mean(w.b));  // blocked once: a suspect
  RouteSettings settings{0.0, 0.0, 1};
  settings.suspect_weight = 100.0;
  CentreGraph graph(w.g, memory);
  RoutePlanner p(settings);
  // A-B costs 101 now: round it through D (2 sqrt 2) rather than A-B-C (102).
  Route r = p.plan(graph, kStart, kTarget);
  EXPECT_EQ(clusters_of(r), (std::vector<int>{w.a, w.d, w.c}));
  EXPECT_NEAR(r.cost, 1.0 + 2 * std::sqrt(2.0), 1e-12);
  // With the ways round D suspect too, A-B (101 + 1) is the cheapest last resort: still a route.
  memory.mark(w.a, w.d, w.g.mean(w.a), w.g.mean(w.d));
  memory.mark(w.c, w.d, w.g.mean(w.c), w.g.mean(w.d));
  r = p.plan(graph, kStart, kTarget);
  EXPECT_EQ(clusters_of(r), (std::vector<int>{w.a, w.b, w.c}));
  EXPECT_NEAR(r.cost, 1.0 + 101.0 + 1.0, 1e-12);
  // A second block makes it illegal: then only the suspects round D remain.
  memory.mark(w.a, w.b, w.g.mean(w.a), w.g.mean(w.b));
  r = p.plan(graph, kStart, kTarget);
  EXPECT_EQ(clusters_of(r), (std::vector<int>{w.a, w.d, w.b, w.c}));
}

TEST(RoutePlanner, LowPriorClusterIsPenalised) {
  Diamond w(0.3, 0.05, 0.3, 0.35);  // mean prior 0.25: only B is below it, penalty log 5
  EdgeMemory memory(0.01);
  CentreGraph graph(w.g, memory);
  const Route light = RoutePlanner({1.0, 1.0, 1}).plan(graph, kStart, kTarget);
  EXPECT_EQ(clusters_of(light), (std::vector<int>{w.a, w.b, w.c}));
  EXPECT_NEAR(light.cost, 3.0 + std::log(5.0), 1e-12);
  const Route heavy = RoutePlanner({1.0, 3.0, 1}).plan(graph, kStart, kTarget);
  EXPECT_EQ(clusters_of(heavy), (std::vector<int>{w.a, w.d, w.c}));  // 6.97 < 3 + 3 log 5
  EXPECT_NEAR(heavy.cost, 1.0 + 2 * std::sqrt(2.0) + kPi, 1e-12);
}

TEST(RoutePlanner, FailedAttachmentMovesTheStartToItsNextCentre) {
  Diamond w;
  EdgeMemory memory(0.01);
  CentreGraph graph(w.g, memory);
  RoutePlanner p({1.0, 0.0, 1});
  const FailedAttachment failed[] = {{kStart + V(0.005, 0), w.a}};  // within the tolerance
  const Route r = p.plan(graph, kStart, kTarget, {failed, 0.01});
  EXPECT_EQ(clusters_of(r), (std::vector<int>{w.b, w.c}));
  EXPECT_NEAR(r.cost, 3.0, 1e-12);
  const FailedAttachment elsewhere[] = {{V(5, 5), w.a}};
  EXPECT_EQ(clusters_of(p.plan(graph, kStart, kTarget, {elsewhere, 0.01})), (std::vector<int>{w.a, w.b, w.c}));
}

TEST(RoutePlanner, TheClusterDrivenFromJoinsTheStartAsVerified) {
  Diamond w;
  EdgeMemory memory(0.01);
  CentreGraph graph(w.g, memory);
  RouteSettings s{0.0, 0.0, 1};
  s.unverified_weight = 10.0;
  RoutePlanner p(s);
  // The start's own link to A is unverified (0.5 * 11), so A-B-C costs 5.5 + 1 + 1 + 0.5.
  const Route r = p.plan(graph, kStart, kTarget);
  EXPECT_EQ(clusters_of(r), (std::vector<int>{w.a, w.b, w.c}));
  EXPECT_NEAR(r.cost, 8.0, 1e-12);
  // Just back from D, the start joins D too, at its plain length: D-C is cheaper.
  const Route back = p.plan(graph, kStart, kTarget, {{}, 0.0, w.d});
  EXPECT_EQ(clusters_of(back), (std::vector<int>{w.d, w.c}));
  EXPECT_NEAR(back.cost, std::sqrt(1.5 * 1.5 + 1.0) + std::sqrt(2.0) + 0.5, 1e-12);
}

TEST(RoutePlanner, CutOffStartGivesNoRoute) {
  Diamond w;
  EdgeMemory memory(0.01);
  memory.mark(w.a, w.b, w.g.mean(w.a), w.g.mean(w.b));
  memory.mark(w.a, w.d, w.g.mean(w.a), w.g.mean(w.d));
  CentreGraph graph(w.g, memory);
  RoutePlanner one({1.0, 0.0, 1});
  EXPECT_TRUE(one.plan(graph, kStart, kTarget).empty());
  RoutePlanner three({1.0, 0.0, 3});  // the start also joins B and D
  EXPECT_FALSE(three.plan(graph, kStart, kTarget).empty());
}

TEST(RoutePlanner, MovedClusterForgetsItsIllegalEdge) {
  EdgeMemory memory(0.1);
  memory.mark(3, 1, V(1, 0), V(0, 0));
  EXPECT_TRUE(memory.illegal(1, 3, V(0, 0), V(1, 0)));
  EXPECT_TRUE(memory.illegal(3, 1, V(1.05, 0), V(0, 0)));
  EXPECT_FALSE(memory.illegal(1, 3, V(0, 0), V(1.2, 0)));  // an end moved on: a new edge
  EXPECT_FALSE(memory.illegal(1, 2, V(0, 0), V(1, 0)));
  ASSERT_EQ(memory.entries().size(), 1u);
  EXPECT_EQ(memory.entries()[0].a, 1);
}

TEST(RoutePlanner, TargetNearerThanAnyCentreIsJoinedDirectly) {
  Diamond w;
  EdgeMemory memory(0.01);
  CentreGraph graph(w.g, memory);
  RoutePlanner p({1.0, 0.0, 1});
  const Route r = p.plan(graph, V(0.5, 2.0), V(0.6, 2.0));
  ASSERT_EQ(r.nodes.size(), 2u);
  EXPECT_NEAR(r.cost, 0.1, 1e-12);
  const FailedAttachment failed[] = {{V(0.5, 2.0), Route::kTarget}};
  EXPECT_GT(p.plan(graph, V(0.5, 2.0), V(0.6, 2.0), {failed, 0.01}).nodes.size(), 2u);
}

TEST(RoutePlanner, RejectsBadSettings) {
  EXPECT_THROW(RoutePlanner({-1.0, 0.0, 1}), ParameterError);
  EXPECT_THROW(RoutePlanner({1.0, -1.0, 1}), ParameterError);
  EXPECT_THROW(RoutePlanner({1.0, 1.0, 0}), ParameterError);
  EXPECT_THROW(RoutePlanner({1.0, 1.0, 1, -1.0}), ParameterError);
  EXPECT_THROW(RoutePlanner({1.0, 1.0, 1, 0.0, -1.0}), ParameterError);
}

}  // namespace
}  // namespace amp::nav
