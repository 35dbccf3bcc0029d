#include "amp/roadmap/prm/node_classifier.hpp"

namespace amp::roadmap {

NodeClass classify(const Insertion& insertion) {
  if (insertion.components_joined == 0) return NodeClass::kCreate;
  if (insertion.components_joined >= 2) return NodeClass::kMerge;
  return insertion.visibility() < kExpandVisibility ? NodeClass::kExpand : NodeClass::kOversample;
}

std::string_view to_string(NodeClass c) {
  switch (c) {
    case NodeClass::kCreate: return "cc_create";
    case NodeClass::kMerge: return "cc_merge";
    case NodeClass::kExpand: return "cc_expand";
    case NodeClass::kOversample: return "cc_oversample";
  }
  return "cc_create";
}

void NodeClassCounter::inserted(const Roadmap& /*roadmap*/, const Insertion& insertion) {
  if (!insertion.seed) ++counts_[static_cast<int>(classify(insertion))];
}

void NodeClassCounter::report(std::map<std::string, double>& extra) const {
  for (const auto& [name, value] : constants_) extra[name] = value;
  for (int i = 0; i < kNodeClassCount; ++i) {
    extra[std::string(to_string(static_cast<NodeClass>(i)))] = static_cast<double>(counts_[i]);
  }
}

}  // namespace amp::roadmap
