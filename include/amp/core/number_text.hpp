#pragma once
#include <string>

namespace amp::core {

// A number as messages write it: the shortest text that reads back to the same double ("0.1",
// "1e-07", "inf", "nan"), so that an error quotes exactly the value it refuses. The one number
// formatter of error messages; records and figures keep their own formats.
std::string number_text(double v);

}  // namespace amp::core
