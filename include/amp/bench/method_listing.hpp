#pragma once
#include <ostream>

namespace amp::bench {

// What `amp bench --list` prints: every registered planner, then every navigation method, each
// with its help and its parameters (type, default, range or choices), in two sections.
void list_methods(std::ostream& out);

}  // namespace amp::bench
