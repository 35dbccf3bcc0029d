// ArmKinematics (AMP's forward kinematics of a URDF arm) against Orocos KDL on the same URDF read by
// urdfdom directly, and against poses computed by hand from the Panda's URDF.
#include "amp/world/arm_kinematics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "amp/core/rng.hpp"
#include "world/arm/kdl_chain.hpp"
#include "support/source_tree.hpp"

namespace amp::world {
namespace {

namespace fs = std::filesystem;

constexpr double kTolerance = 1e-9;
constexpr int kConfigurations = 1000;
constexpr std::uint64_t kSeed = 20250035;

fs::path panda_urdf() { return fs::path(AMP_SOURCE_DIR) / ".." / "shared" / "mbm" / "panda" / "panda.urdf"; }

// Every movable joint of the model, in model order: the whole arm is the group, `tip` its tip.
PlanningGroup all_joints(const ArmModel& m, const std::string& tip) {
  PlanningGroup g;
  g.name = "all";
  for (std::size_t j = 0; j < m.joints().size(); ++j) {
    if (m.joints()[j].movable() && m.joints()[j].mimic_joint < 0) g.joints.push_back(static_cast<int>(j));
  }
  g.tip_link = m.link_index(tip);
  return g;
}

class PandaKinematics : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::is_regular_file(panda_urdf())) {
      GTEST_SKIP() << panda_urdf() << " is absent (the shared test data, ../shared/mbm beside the source tree)";
    }
    model_ = std::make_shared<const ArmModel>(load_urdf(panda_urdf()));
    kinematics_ = std::make_unique<ArmKinematics>(model_, all_joints(*model_, "panda_grasptarget"), std::vector<double>(model_->joints().size(), 0.0));
    urdf_ = test::read_urdf(panda_urdf());
  }

  // The state of the group from named joint values (unnamed joints 0).
  State state(const std::vector<std::pair<std::string, double>>& values) const {
    State q = State::Zero(kinematics_->dof());
    for (const auto& [name, v] : values) q[state_index(name)] = v;
    return q;
  }

  // The state coordinate of a joint named in the URDF.
  int state_index(const std::string& joint) const {
    const int j = model_->joint_index(joint);
    for (int k = 0; k < kinematics_->dof(); ++k) {
      if (kinematics_->group().joints[static_cast<std::size_t>(k)] == j) return k;
    }
    ADD_FAILURE() << joint << " is not a joint of the group";
    return 0;
  }

  Eigen::Isometry3d pose(const State& q, const std::string& link) const {
    std::vector<Eigen::Isometry3d> poses(kinematics_->link_count());
    kinematics_->link_poses(q, poses.data());
    const int i = model_->link_index(link);
    EXPECT_GE(i, 0) << link;
    return poses[static_cast<std::size_t>(i)];
  }

  std::shared_ptr<const ArmModel> model_;
  std::unique_ptr<ArmKinematics> kinematics_;
  urdf::ModelInterfaceSharedPtr urdf_;
};

// The URDF writes pi/2 as 1.57079632679 (4.9e-12 short) and pi/4 as 0.785398163397: poses worked
// out with exact angles agree to about 1e-11 after seven joints.
constexpr double kByHand = 1e-10;

void expect_pose(const Eigen::Isometry3d& got, const Eigen::Vector3d& p, const Eigen::Matrix3d& r, const std::string& what,
                 double tolerance = kByHand) {
  EXPECT_LT((got.translation() - p).cwiseAbs().maxCoeff(), tolerance) << what << ": position " << got.translation().transpose()
                                                                      << ", expected " << p.transpose();
  EXPECT_LT((got.linear() - r).cwiseAbs().maxCoeff(), tolerance) << what << ": rotation\n" << got.linear() << "\nexpected\n" << r;
}

Eigen::Matrix3d rows(std::initializer_list<double> v) {
  Eigen::Matrix3d m;
  auto it = v.begin();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) m(r, c) = *it++;
  }
  return m;
}

TEST_F(PandaKinematics, LinksAndJointsAreNumberedDepthFirst) {
  ASSERT_EQ(model_->links().size(), 13u);  // link0..8, hand, two fingers, grasp target
  ASSERT_EQ(model_->joints().size(), 12u);
  EXPECT_EQ(model_->link(0).name, "panda_link0");
  for (std::size_t j = 0; j < model_->joints().size(); ++j) {
    const ArmJoint& joint = model_->joints()[j];
    EXPECT_LT(joint.parent_link, joint.child_link) << joint.name;
    EXPECT_EQ(model_->link(joint.child_link).parent_joint, static_cast<int>(j)) << joint.name;
    if (j > 0) {
      EXPECT_LT(model_->joints()[j - 1].child_link, joint.child_link) << joint.name;
    }
  }
  EXPECT_EQ(kinematics_->dof(), 7);  // the finger joints are fixed in this URDF
  for (int k = 0; k < 7; ++k) {
    EXPECT_EQ(model_->joint(kinematics_->group().joints[static_cast<std::size_t>(k)]).name, "panda_joint" + std::to_string(k + 1));
  }
}

// All zeros. Worked from the URDF's <origin> elements (Rx(a) is a rotation by a about x):
//   link0: identity.
//   link1: (0, 0, 0.333), R = I.
//   link2: joint2 rpy (-pi/2, 0, 0): (0, 0, 0.333), R2 = Rx(-pi/2) = [1 0 0; 0 0 1; 0 -1 0].
//   link3: joint3 xyz (0, -0.316, 0): R2 * (0, -0.316, 0) = (0, 0, 0.316) -> (0, 0, 0.649);
//          R3 = R2 * Rx(pi/2) = I.
//   link4: joint4 xyz (0.0825, 0, 0) -> (0.0825, 0, 0.649); R4 = Rx(pi/2) = [1 0 0; 0 0 -1; 0 1 0].
//   link5: joint5 xyz (-0.0825, 0.384, 0): R4 * (-0.0825, 0.384, 0) = (-0.0825, 0, 0.384)
//          -> (0, 0, 1.033); R5 = R4 * Rx(-pi/2) = I.
//   link6: (0, 0, 1.033); R6 = Rx(pi/2).
//   link7: joint7 xyz (0.088, 0, 0) -> (0.088, 0, 1.033); R7 = R6 * Rx(pi/2) = Rx(pi) = diag(1, -1, -1).
//   link8: xyz (0, 0, 0.107): R7 * (0, 0, 0.107) = (0, 0, -0.107)
//          -> (0.088, 0, 1.033 - 0.107) = (0.088, 0, 0.926) (0.333 + 0.316 + 0.384 - 0.107); R8 = R7.
//   hand:  rpy (0, 0, -pi/4): R = diag(1, -1, -1) * Rz(-pi/4) = [c s 0; s -c 0; 0 0 -1], c = s = sqrt(1/2).
//   leftfinger: xyz (0, 0.065, 0.0584): R_hand * (0, 0.065, 0.0584) = (0.065 s, -0.065 c, -0.0584)
//          -> (0.088 + 0.065 s, -0.065 c, 0.8676).
//   rightfinger: xyz (0, -0.065, 0.0584) -> (0.088 - 0.065 s, 0.065 c, 0.8676).
//   grasptarget: xyz (0, 0, 0.105) -> (0.088, 0, 0.821).
TEST_F(PandaKinematics, AllZerosByHand) {
  const State q = state({});
  const double c = std::sqrt(0.5), s = std::sqrt(0.5);
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d rx_m90 = rows({1, 0, 0, 0, 0, 1, 0, -1, 0});
  const Eigen::Matrix3d rx_p90 = rows({1, 0, 0, 0, 0, -1, 0, 1, 0});
  const Eigen::Matrix3d rx_180 = rows({1, 0, 0, 0, -1, 0, 0, 0, -1});
  const Eigen::Matrix3d hand = rows({c, s, 0, s, -c, 0, 0, 0, -1});
  expect_pose(pose(q, "panda_link0"), {0, 0, 0}, I, "link0");
  expect_pose(pose(q, "panda_link1"), {0, 0, 0.333}, I, "link1");
  expect_pose(pose(q, "panda_link2"), {0, 0, 0.333}, rx_m90, "link2");
  expect_pose(pose(q, "panda_link3"), {0, 0, 0.649}, I, "link3");
  expect_pose(pose(q, "panda_link4"), {0.0825, 0, 0.649}, rx_p90, "link4");
  expect_pose(pose(q, "panda_link5"), {0, 0, 1.033}, I, "link5");
  expect_pose(pose(q, "panda_link6"), {0, 0, 1.033}, rx_p90, "link6");
  expect_pose(pose(q, "panda_link7"), {0.088, 0, 1.033}, rx_180, "link7");
  expect_pose(pose(q, "panda_link8"), {0.088, 0, 0.926}, rx_180, "link8");
  expect_pose(pose(q, "panda_hand"), {0.088, 0, 0.926}, hand, "hand");
  expect_pose(pose(q, "panda_leftfinger"), {0.088 + 0.065 * s, -0.065 * c, 0.8676}, hand, "leftfinger");
  expect_pose(pose(q, "panda_rightfinger"), {0.088 - 0.065 * s, 0.065 * c, 0.8676}, hand, "rightfinger");
  expect_pose(pose(q, "panda_grasptarget"), {0.088, 0, 0.821}, hand, "grasptarget");
  EXPECT_LT((kinematics_->tip_position(q) - Eigen::Vector3d(0.088, 0, 0.821)).norm(), kByHand);  // the tip: panda_grasptarget
}

// q1 = pi/2, q4 = -pi/2, q6 = pi/2, the rest 0. By hand (Rz(a): rotation by a about z):
//   link1: (0, 0, 0.333), R1 = Rz(pi/2) = [0 -1 0; 1 0 0; 0 0 1].
//   link3: R2 * (0, -0.316, 0) = R1 * Rx(-pi/2) * (0, -0.316, 0) = R1 * (0, 0, 0.316) -> (0, 0, 0.649); R3 = R1.
//   link4: R1 * (0.0825, 0, 0) = (0, 0.0825, 0) -> (0, 0.0825, 0.649); R4 = R1 * Rx(pi/2) * Rz(-pi/2).
//   link5: Rz(-pi/2) * (-0.0825, 0.384, 0) = (0.384, 0.0825, 0); Rx(pi/2) * that = (0.384, 0, 0.0825);
//          R1 * that = (0, 0.384, 0.0825) -> (0, 0.4665, 0.7315);
//          R5 = R4 * Rx(-pi/2) = R1 * [Rx(pi/2) Rz(-pi/2) Rx(-pi/2) = Ry(pi/2)] = [0 -1 0; 0 0 1; -1 0 0].
//   link6: (0, 0.4665, 0.7315); R6 = R5 * Rx(pi/2) * Rz(pi/2).
//   link7: R6 * (0.088, 0, 0) = R5 * Rx(pi/2) * (0, 0.088, 0) = R5 * (0, 0, 0.088) = (0, 0.088, 0)
//          -> (0, 0.5545, 0.7315); R7 = R6 * Rx(pi/2): columns R5 e_z, -R5 e_y, R5 e_x
//          = (0, 1, 0), (1, 0, 0), (0, 0, -1), i.e. [0 1 0; 1 0 0; 0 0 -1] (the hand points down).
//   link8: R7 * (0, 0, 0.107) = (0, 0, -0.107) -> (0, 0.5545, 0.6245); R8 = R7.
//   grasptarget: hand z = link8 z = (0, 0, -1): (0, 0.5545, 0.6245 - 0.105) = (0, 0.5545, 0.5195).
TEST_F(PandaKinematics, ArmStretchedSidewaysHandDownByHand) {
  const double pi = std::numbers::pi;
  const State q = state({{"panda_joint1", pi / 2}, {"panda_joint4", -pi / 2}, {"panda_joint6", pi / 2}});
  const double t = kByHand;
  expect_pose(pose(q, "panda_link1"), {0, 0, 0.333}, rows({0, -1, 0, 1, 0, 0, 0, 0, 1}), "link1", t);
  expect_pose(pose(q, "panda_link3"), {0, 0, 0.649}, rows({0, -1, 0, 1, 0, 0, 0, 0, 1}), "link3", t);
  EXPECT_LT((pose(q, "panda_link4").translation() - Eigen::Vector3d(0, 0.0825, 0.649)).norm(), t);
  expect_pose(pose(q, "panda_link5"), {0, 0.4665, 0.7315}, rows({0, -1, 0, 0, 0, 1, -1, 0, 0}), "link5", t);
  EXPECT_LT((pose(q, "panda_link6").translation() - Eigen::Vector3d(0, 0.4665, 0.7315)).norm(), t);
  expect_pose(pose(q, "panda_link7"), {0, 0.5545, 0.7315}, rows({0, 1, 0, 1, 0, 0, 0, 0, -1}), "link7", t);
  expect_pose(pose(q, "panda_link8"), {0, 0.5545, 0.6245}, rows({0, 1, 0, 1, 0, 0, 0, 0, -1}), "link8", t);
  EXPECT_LT((pose(q, "panda_grasptarget").translation() - Eigen::Vector3d(0, 0.5545, 0.5195)).norm(), t);
  EXPECT_LT((kinematics_->tip_position(q) - Eigen::Vector3d(0, 0.5545, 0.5195)).norm(), t);
}

// 1,000 seeded configurations within the joint limits: every link's pose equals KDL's, on the
// chains panda_link0 -> panda_hand and -> each of the other leaf links (the fingers, the grasp
// target), so that every link is compared.
TEST_F(PandaKinematics, EveryLinkPoseEqualsKdlOnRandomConfigurations) {
  std::vector<test::KdlChain> chains;
  for (const char* tip : {"panda_hand", "panda_leftfinger", "panda_rightfinger", "panda_grasptarget"}) {
    chains.push_back(test::kdl_chain(*urdf_, "panda_link0", tip));
  }
  ASSERT_EQ(chains[0].chain.getNrOfSegments(), 9u);  // link1..7, link8 (fixed), hand (fixed)
  ASSERT_EQ(chains[0].chain.getNrOfJoints(), 7u);
  ASSERT_EQ(chains[1].chain.getNrOfSegments(), 10u);
  core::Rng rng(kSeed);
  std::vector<Eigen::Isometry3d> amp_poses(kinematics_->link_count());
  double worst = 0.0;
  int compared = 0;
  for (int n = 0; n < kConfigurations; ++n) {
    State q(kinematics_->dof());
    for (int k = 0; k < kinematics_->dof(); ++k) {
      const ArmJoint& j = model_->joint(kinematics_->group().joints[static_cast<std::size_t>(k)]);
      const urdf::JointConstSharedPtr u = urdf_->getJoint(j.name);  // the limits as urdfdom reads them
      q[k] = rng.uniform(u->limits->lower, u->limits->upper);
    }
    kinematics_->link_poses(q, amp_poses.data());
    for (const test::KdlChain& c : chains) {
      KDL::JntArray kq(c.chain.getNrOfJoints());
      for (std::size_t i = 0; i < c.joints.size(); ++i) kq(static_cast<unsigned>(i)) = q[state_index(c.joints[i])];
      KDL::ChainFkSolverPos_recursive fk(c.chain);
      for (std::size_t s = 0; s < c.links.size(); ++s) {
        KDL::Frame f;
        ASSERT_GE(fk.JntToCart(kq, f, static_cast<int>(s + 1)), 0);
        const Eigen::Isometry3d kdl = test::to_eigen(f);
        const Eigen::Isometry3d& amp = amp_poses[static_cast<std::size_t>(model_->link_index(c.links[s]))];
        const double err = std::max((kdl.translation() - amp.translation()).cwiseAbs().maxCoeff(),
                                    (kdl.linear() - amp.linear()).cwiseAbs().maxCoeff());
        worst = std::max(worst, err);
        ++compared;
        ASSERT_LT(err, kTolerance) << "configuration " << n << ", link " << c.links[s] << "\nAMP:\n"
                                   << amp.matrix() << "\nKDL:\n" << kdl.matrix();
      }
    }
    // The group's reference point is the tip link's origin.
    const auto tip = static_cast<std::size_t>(kinematics_->group().tip_link);
    EXPECT_LT((kinematics_->tip_position(q) - amp_poses[tip].translation()).norm(), kTolerance);
  }
  std::cout << "[ figures  ] " << compared << " link poses compared with KDL, largest difference " << worst << "\n";
}

}  // namespace
}  // namespace amp::world
