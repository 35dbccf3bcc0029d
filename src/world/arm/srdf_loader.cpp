#include <tinyxml2.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

#include "amp/core/error.hpp"
#include "amp/world/arm_srdf.hpp"

namespace amp::world {

namespace {

namespace fs = std::filesystem;

std::string attribute(const tinyxml2::XMLElement& e, const char* name, const std::string& label) {
  const char* v = e.Attribute(name);
  if (v == nullptr) {
    throw FileError(label + ": line " + std::to_string(e.GetLineNum()) + ": <" + e.Name() + "> lacks the '" + name +
                    "' attribute");
  }
  return v;
}

SrdfGroup read_group(const tinyxml2::XMLElement& g, const std::string& label) {
  SrdfGroup out;
  out.name = attribute(g, "name", label);
  for (const tinyxml2::XMLElement* e = g.FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
    const std::string tag = e->Name();
    if (tag == "joint") out.joints.push_back(attribute(*e, "name", label));
    if (tag == "link") out.links.push_back(attribute(*e, "name", label));
    if (tag == "chain") out.chains.emplace_back(attribute(*e, "base_link", label), attribute(*e, "tip_link", label));
    if (tag == "group") out.subgroups.push_back(attribute(*e, "name", label));
  }
  return out;
}

[[noreturn]] void group_fail(const std::string& label, const std::string& group, const std::string& what) {
  throw FileError(label + ": group '" + group + "': " + what);
}

// The joints from `base` down to `tip` (tip's parent joint first, then upwards), in model order.
void add_chain(const ArmModel& m, const std::string& base, const std::string& tip, const std::string& label,
               const std::string& group, std::set<int>& joints) {
  const int b = m.link_index(base), t = m.link_index(tip);
  if (b < 0) group_fail(label, group, "chain base_link '" + base + "' is not a link of the URDF");
  if (t < 0) group_fail(label, group, "chain tip_link '" + tip + "' is not a link of the URDF");
  if (!m.in_subtree(b, t)) group_fail(label, group, "chain: '" + tip + "' does not descend from '" + base + "'");
  for (int l = t; l != b;) {
    const int j = m.link(l).parent_joint;
    joints.insert(j);
    l = m.joint(j).parent_link;
  }
}

void collect(const ArmModel& m, const Srdf& srdf, const std::string& name, const std::string& label,
             std::set<int>& joints, std::set<std::string>& seen, int& tip) {
  const auto g = std::find_if(srdf.groups.begin(), srdf.groups.end(), [&](const SrdfGroup& x) { return x.name == name; });
  if (g == srdf.groups.end()) {
    std::string names;
    for (const SrdfGroup& x : srdf.groups) names += (names.empty() ? "" : ", ") + x.name;
    throw FileError(label + ": no group '" + name + "' (groups: " + (names.empty() ? "none" : names) + ")");
  }
  if (!seen.insert(name).second) group_fail(label, name, "contains itself through its subgroups");
  for (const std::string& j : g->joints) {
    const int i = m.joint_index(j);
    if (i < 0) group_fail(label, name, "joint '" + j + "' is not a joint of the URDF");
    joints.insert(i);
  }
  for (const std::string& l : g->links) {
    const int i = m.link_index(l);
    if (i < 0) group_fail(label, name, "link '" + l + "' is not a link of the URDF");
    if (m.link(i).parent_joint >= 0) joints.insert(m.link(i).parent_joint);
  }
  for (const auto& [base, t] : g->chains) {
    add_chain(m, base, t, label, name, joints);
    tip = m.link_index(t);
  }
  for (const std::string& s : g->subgroups) collect(m, srdf, s, label, joints, seen, tip);
}

}  // namespace

Srdf parse_srdf(const std::string& xml, const std::string& label) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS) {
    throw FileError(label + ": not valid XML: line " + std::to_string(doc.ErrorLineNum()) + ": " + doc.ErrorName());
  }
  const tinyxml2::XMLElement* robot = doc.FirstChildElement("robot");
  if (robot == nullptr) throw FileError(label + ": not an SRDF: no <robot> element");
  Srdf out;
  if (const char* n = robot->Attribute("name")) out.robot = n;
  for (const tinyxml2::XMLElement* e = robot->FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
    const std::string tag = e->Name();
    if (tag == "group") out.groups.push_back(read_group(*e, label));
    if (tag == "disable_collisions") {
      out.disabled_collisions.emplace_back(attribute(*e, "link1", label), attribute(*e, "link2", label));
    }
  }
  return out;
}

Srdf load_srdf(const fs::path& file) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) throw FileError(file.string() + ": no such file");
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return parse_srdf(text.str(), file.string());
}

PlanningGroup resolve_group(const ArmModel& model, const Srdf& srdf, const std::string& group, const std::string& label) {
  std::set<int> all;
  std::set<std::string> seen;
  int tip = -1;
  collect(model, srdf, group, label, all, seen, tip);
  PlanningGroup out;
  out.name = group;
  for (const int j : all) {  // std::set: ascending model order
    if (model.joint(j).movable() && model.joint(j).mimic_joint < 0) out.joints.push_back(j);
  }
  if (out.joints.empty()) group_fail(label, group, "has no movable joint");
  if (tip < 0) {
    // The deepest link of the last joint: follow fixed joints down while there is one child.
    tip = model.joint(out.joints.back()).child_link;
    while (model.link(tip).child_joints.size() == 1 && !model.joint(model.link(tip).child_joints[0]).movable()) {
      tip = model.joint(model.link(tip).child_joints[0]).child_link;
    }
  }
  out.tip_link = tip;
  return out;
}

}  // namespace amp::world
