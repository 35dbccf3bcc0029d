#pragma once
// The parts of a MoveIt SRDF that planning needs: the planning groups and the link pairs whose
// collisions are disabled (adjacent links among them: the SRDF says which, AMP never guesses).
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "amp/world/arm_model.hpp"

namespace amp::world {

struct SrdfGroup {
  std::string name;
  std::vector<std::string> joints;
  std::vector<std::string> links;
  std::vector<std::pair<std::string, std::string>> chains;  // (base_link, tip_link)
  std::vector<std::string> subgroups;
};

struct Srdf {
  std::string robot;
  std::vector<SrdfGroup> groups;
  std::vector<std::pair<std::string, std::string>> disabled_collisions;  // link pairs
};

// Reads an SRDF with tinyxml2. Throws FileError naming the file (and the element) when it is not
// XML or an element lacks a required attribute.
Srdf load_srdf(const std::filesystem::path& file);
Srdf parse_srdf(const std::string& xml, const std::string& label);

// A planning group resolved against the model, as MoveIt resolves it: a chain gives the joints
// from base to tip, a link its parent joint, a subgroup its own joints. Only movable joints stay,
// numbered as the model numbers them (MoveIt's order, the order of a path file's columns).
struct PlanningGroup {
  std::string name;
  std::vector<int> joints;  // model joint indices, movable only, not mimic followers
  // The link whose position is the group's reference point: a chain's tip, else the deepest link
  // of the last joint.
  int tip_link = -1;
};

// Throws FileError "<srdf>: group '<name>': ..." for a missing group, or a joint, link or chain the
// model lacks; also when the group has no movable joint.
PlanningGroup resolve_group(const ArmModel& model, const Srdf& srdf, const std::string& group, const std::string& label);

}  // namespace amp::world
