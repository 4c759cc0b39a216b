#pragma once
// Text for messages that name simplices: "(3, 7, 9)". One place, so every error reads the same.
#include <cstddef>
#include <string>

namespace cmx::algorithm {

template <class Ids>
std::string ids_text(const Ids& ids) {
  std::string s(1, '(');
  bool first = true;
  for (auto v : ids) {
    if (!first) s.append(", ");
    s.append(std::to_string(v));
    first = false;
  }
  s.push_back(')');
  return s;
}

}  // namespace cmx::algorithm
