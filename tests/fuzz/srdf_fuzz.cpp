// MoveIt SRDF files (world::parse_srdf), then every group they define resolved (world::resolve_group)
// against one fixed arm: a URDF of primitives only, parsed once, holding the links and joints of
// both seed robots (tests/data/arm/two_link and MotionBenchMaker's Panda, with its mimic finger)
// under one root, so that the seeds' groups resolve and mutated ones fail on real names.
#include <string>

#include "amp/world/arm_srdf.hpp"
#include "fuzz_input.hpp"

namespace {

constexpr const char* kModel = R"(<robot name="fuzz_arms">
  <link name="world"/>
  <joint name="world_to_base" type="fixed"><parent link="world"/><child link="base"/></joint>
  <joint name="world_to_panda" type="fixed"><parent link="world"/><child link="panda_link0"/>
    <origin xyz="1 0 0"/></joint>
  <link name="base"><collision><geometry><box size="0.2 0.2 0.1"/></geometry></collision></link>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="link1"/>
    <axis xyz="0 0 1"/><limit lower="-2.5" upper="2.5" effort="10" velocity="1"/></joint>
  <link name="link1"><collision><geometry><box size="0.5 0.1 0.1"/></geometry></collision></link>
  <joint name="slide" type="prismatic"><parent link="link1"/><child link="link2"/>
    <axis xyz="1 0 0"/><limit lower="0" upper="0.3" effort="10" velocity="0.5"/></joint>
  <link name="link2"><collision><geometry><cylinder radius="0.03" length="0.2"/></geometry></collision></link>
  <joint name="wrist" type="continuous"><parent link="link2"/><child link="link3"/><axis xyz="0 0 1"/></joint>
  <link name="link3"/>
  <joint name="tool_joint" type="fixed"><parent link="link3"/><child link="tool"/></joint>
  <link name="tool"><collision><geometry><sphere radius="0.03"/></geometry></collision></link>
  <link name="panda_link0"/>
  <joint name="panda_joint1" type="revolute"><parent link="panda_link0"/><child link="panda_link1"/>
    <axis xyz="0 0 1"/><limit lower="-2.9" upper="2.9" effort="87" velocity="2.4"/></joint>
  <link name="panda_link1"/>
  <joint name="panda_joint2" type="revolute"><parent link="panda_link1"/><child link="panda_link2"/>
    <axis xyz="0 0 1"/><limit lower="-1.8" upper="1.8" effort="87" velocity="2.4"/></joint>
  <link name="panda_link2"/>
  <joint name="panda_joint3" type="revolute"><parent link="panda_link2"/><child link="panda_link3"/>
    <axis xyz="0 0 1"/><limit lower="-2.9" upper="2.9" effort="87" velocity="2.4"/></joint>
  <link name="panda_link3"/>
  <joint name="panda_joint4" type="revolute"><parent link="panda_link3"/><child link="panda_link4"/>
    <axis xyz="0 0 1"/><limit lower="-3.1" upper="0.08" effort="87" velocity="2.4"/></joint>
  <link name="panda_link4"/>
  <joint name="panda_joint5" type="revolute"><parent link="panda_link4"/><child link="panda_link5"/>
    <axis xyz="0 0 1"/><limit lower="-2.9" upper="2.9" effort="12" velocity="2.9"/></joint>
  <link name="panda_link5"/>
  <joint name="panda_joint6" type="revolute"><parent link="panda_link5"/><child link="panda_link6"/>
    <axis xyz="0 0 1"/><limit lower="-0.08" upper="3.8" effort="12" velocity="2.9"/></joint>
  <link name="panda_link6"/>
  <joint name="panda_joint7" type="revolute"><parent link="panda_link6"/><child link="panda_link7"/>
    <axis xyz="0 0 1"/><limit lower="-2.9" upper="2.9" effort="12" velocity="2.9"/></joint>
  <link name="panda_link7"/>
  <joint name="panda_joint8" type="fixed"><parent link="panda_link7"/><child link="panda_link8"/></joint>
  <link name="panda_link8"/>
  <joint name="panda_hand_joint" type="fixed"><parent link="panda_link8"/><child link="panda_hand"/></joint>
  <link name="panda_hand"><collision><geometry><box size="0.05 0.2 0.07"/></geometry></collision></link>
  <joint name="panda_finger_joint1" type="prismatic"><parent link="panda_hand"/><child link="panda_leftfinger"/>
    <axis xyz="0 1 0"/><limit lower="0" upper="0.04" effort="20" velocity="0.2"/></joint>
  <link name="panda_leftfinger"><collision><geometry><sphere radius="0.01"/></geometry></collision></link>
  <joint name="panda_finger_joint2" type="prismatic"><parent link="panda_hand"/><child link="panda_rightfinger"/>
    <axis xyz="0 -1 0"/><limit lower="0" upper="0.04" effort="20" velocity="0.2"/>
    <mimic joint="panda_finger_joint1"/></joint>
  <link name="panda_rightfinger"><collision><geometry><sphere radius="0.01"/></geometry></collision></link>
</robot>)";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const amp::world::ArmModel model = amp::world::parse_urdf(kModel, "fuzz_arms.urdf", {});
  const std::string xml(reinterpret_cast<const char*>(data), size);
  amp::fuzz::expect_amp_errors_only([&] {
    const amp::world::Srdf srdf = amp::world::parse_srdf(xml, "input.srdf");
    for (const amp::world::SrdfGroup& g : srdf.groups) {
      amp::fuzz::expect_amp_errors_only([&] { amp::world::resolve_group(model, srdf, g.name, "input.srdf"); });
    }
  });
  return 0;
}
