#pragma once
// Shared by tests: a state written as a list, st({x, y, theta}).
#include <initializer_list>

#include "amp/core/state.hpp"

namespace amp::test {

inline State st(std::initializer_list<double> v) {
  State s(static_cast<int>(v.size()));
  int i = 0;
  for (double x : v) s[i++] = x;
  return s;
}

}  // namespace amp::test
